// MC_MoveAbsolute: positions the axis to an absolute target (seed 000 §2.1, "absolute start").
//
// Execute-type block (rules in fb/detail/execute_block.hpp). Done when the NC reports the job
// ended (set-value generation finished and, with target-window monitoring, InTargetPosition).
// Acceleration, Deceleration or Jerk of 0 mean the axis default. Velocity, the dynamics and the
// target are checked by the NC (0x4221, 0x422E…0x4231, 0x4222, 0x4F01, 0x4F02): the block shows
// its code. BufferMode: see below (a value outside MC_BufferMode: 0x4F03, nothing posted).
// BufferMode (Tc2_MC2, one buffered command per axis): MC_Aborting takes the axis at once;
// MC_Buffered waits (Busy, not Active) until the running command is done and starts at its end
// of path; MC_BlendingLow / Previous / Next / High let the running positioning pass its target
// with the lower / first / second / higher velocity (what the path allows, 0 on a reversal) and
// start there. A second buffered command while one waits: Error 0x4F60, the waiting one stays.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "fb/types.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_MoveAbsolute {
 public:
  // Inputs (latched on the rising edge of Execute).
  bool Execute = false;
  double Position = 0.0;      // mm
  double Velocity = 0.0;      // mm/s, > 0
  double Acceleration = 0.0;  // mm/s², 0 = axis default
  double Deceleration = 0.0;  // mm/s², 0 = axis default
  double Jerk = 0.0;          // mm/s³, 0 = axis default
  MC_BufferMode BufferMode = MC_Aborting;

  // Outputs.
  bool Done = false;
  bool Busy = false;
  bool Active = false;
  bool CommandAborted = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(plc::AXIS_REF& axis) noexcept;

  // Number of the command posted last (0: none); for traces and tests.
  uint16_t command_number() const noexcept { return block_.command_number(); }

 private:
  detail::ExecuteBlock block_;
};

}  // namespace fb
