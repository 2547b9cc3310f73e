// MC_Halt: stops the axis on a ramp as a normal, abortable motion command (seed 000 §2.3).
//
// Execute-type block (rules in fb/detail/execute_block.hpp). Done at standstill. Another motion
// command may take the axis during the halt (CommandAborted). Deceleration or Jerk of 0 mean
// those of the running motion (the NC substitutes them and validates the rest). BufferMode: see
// MC_MoveAbsolute (blending into a halt is MC_Buffered; outside MC_BufferMode: 0x4F03).
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "fb/types.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_Halt {
 public:
  // Inputs (latched on the rising edge of Execute).
  bool Execute = false;
  double Deceleration = 0.0;  // mm/s², 0 = default
  double Jerk = 0.0;          // mm/s³, 0 = default
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
