// MC_ExtSetPointGenEnable: switches an axis to external setpoint generation — from the next NC
// cycle on the axis takes its set values from PlcToNc.ExtSetPos/ExtSetVelo/ExtSetAcc, fed each PLC
// cycle with MC_ExtSetPointGenFeed (seed 000 §2.6, seed 001, SPEC B8).
//
// Execute-type block (rules in fb/detail/execute_block.hpp). Position is the target for the
// target-window monitoring (InTargetPosition), not a position the axis moves to; PositionType
// says how the set values are taken: POSITIONTYPE_ABSOLUTE (the fed values are the set values)
// or POSITIONTYPE_RELATIVE (added to the internal generator's set values). A PositionType outside
// E_PositionType is refused here (0x4239, nothing posted); the NC refuses the rest with its code
// (axis in error, no controller or feed enable, a coupled axis, a start type different from the
// one already active, absolute while an internal motion runs). Done when the NC has taken the
// command. Enabled = StateDWord bit 14 (ExtSetPointGenEnabled) at every call, whatever the block
// does — as Tc2_MC2 shows the generator's state independent of the command.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "fb/types.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_ExtSetPointGenEnable {
 public:
  // Inputs (latched on the rising edge of Execute).
  bool Execute = false;
  double Position = 0.0;  // mm, target for target-window monitoring
  E_PositionType PositionType = POSITIONTYPE_ABSOLUTE;

  // Outputs.
  bool Done = false;
  bool Busy = false;
  bool Error = false;
  uint32_t ErrorID = 0;
  bool Enabled = false;

  // Cycle function: runs the block once.
  void operator()(plc::AXIS_REF& axis) noexcept;

  uint16_t command_number() const noexcept { return block_.command_number(); }

 private:
  detail::ExecuteBlock block_;
};

}  // namespace fb
