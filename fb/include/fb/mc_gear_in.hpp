// MC_GearIn: couples the slave to the master as a linear slave with factor
// RatioNumerator / RatioDenominator (SPEC C1, seed 000 §3.2.2).
//
// Execute-type block (rules in fb/detail/execute_block.hpp); the command goes to the slave's
// mailbox with the master's NcToPlc.AxisIndex. InGear (and Busy, Active) from the cycle the NC
// coupled the axes on, for as long as they stay coupled and the slave has no error (an error:
// Error with its ErrorID; the coupling stays); MC_GearOut ends the coupling (the block is then
// no longer Busy, with no result shown). Another MC_GearIn for the same slave takes over
// (this one: CommandAborted); so does this one after its Execute fell and rose again while
// InGear (the documented exception to "a rising edge while Busy starts nothing"): a new command
// with the new ratio, InGear again once the NC has taken it (the next NC cycle). RatioDenominator 0
// is refused here (0x4B06), BufferMode other than MC_Aborting too (0x4F03); the NC refuses the rest
// (factor 0, NaN, axes not at rest, loops...: docs/behaviour.md "Slave axes"). Acceleration,
// Deceleration and Jerk are not used by a linear coupling (kept for the Tc2_MC2 interface).
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "fb/types.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_GearIn {
 public:
  // Inputs (latched on the rising edge of Execute).
  bool Execute = false;
  double RatioNumerator = 1.0;
  uint16_t RatioDenominator = 1;
  double Acceleration = 0.0;
  double Deceleration = 0.0;
  double Jerk = 0.0;
  MC_BufferMode BufferMode = MC_Aborting;

  // Outputs.
  bool InGear = false;
  bool Busy = false;
  bool Active = false;
  bool CommandAborted = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(const plc::AXIS_REF& master, plc::AXIS_REF& slave) noexcept;

  uint16_t command_number() const noexcept { return block_.command_number(); }

 private:
  detail::ExecuteBlock block_{detail::ExecuteBlock::Retrigger::kWhileReached};
};

}  // namespace fb
