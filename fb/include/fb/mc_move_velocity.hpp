// MC_MoveVelocity: endless motion at a velocity (seed 000 §2.1, continuous start).
//
// Execute-type block (rules in fb/detail/execute_block.hpp). The job never ends by itself:
// InVelocity (in place of Done) while the NC reports the constant velocity reached; the block
// stays Busy and Active until another command takes the axis (CommandAborted) or the job fails
// (Error). Direction must be MC_Positive_Direction, MC_Negative_Direction or
// MC_Current_Direction (keep the direction of the motion that runs; Tc2_MC2 allows these three;
// others: 0x4F07, checked here); it is passed to the NC as its MC_Direction value, and the NC
// refuses MC_Current_Direction where there is no direction to keep. Velocity must be > 0; the
// NC checks it and the dynamics. BufferMode: see MC_MoveAbsolute (a
// value outside MC_BufferMode: 0x4F03).
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "fb/types.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_MoveVelocity {
 public:
  // Inputs (latched on the rising edge of Execute).
  bool Execute = false;
  double Velocity = 0.0;      // mm/s, > 0
  double Acceleration = 0.0;  // mm/s², 0 = axis default
  double Deceleration = 0.0;  // mm/s², 0 = axis default
  double Jerk = 0.0;          // mm/s³, 0 = axis default
  MC_Direction Direction = MC_Positive_Direction;
  MC_BufferMode BufferMode = MC_Aborting;

  // Outputs.
  bool InVelocity = false;
  bool Busy = false;
  bool Active = false;
  bool CommandAborted = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(plc::AXIS_REF& axis) noexcept;

  uint16_t command_number() const noexcept { return block_.command_number(); }

 private:
  detail::ExecuteBlock block_;
};

}  // namespace fb
