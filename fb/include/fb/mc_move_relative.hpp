// MC_MoveRelative: moves the axis by a distance from its present set position (seed 000 §2.1,
// "relative start").
//
// Execute-type block (rules in fb/detail/execute_block.hpp); outputs and errors as
// MC_MoveAbsolute. The sign of Distance gives the direction.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "fb/types.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_MoveRelative {
 public:
  // Inputs (latched on the rising edge of Execute).
  bool Execute = false;
  double Distance = 0.0;      // mm
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

  uint16_t command_number() const noexcept { return block_.command_number(); }

 private:
  detail::ExecuteBlock block_;
};

}  // namespace fb
