// The commands of an axis's superpositions (SPEC B7 position compensation, B8 external
// setpoints; seed 000 §2.5, §2.6): MC_MoveSuperImposed, its abort, and switching the external
// setpoint generation on and off, with their refusals. What the superpositions do in a cycle is
// SuperpositionStack's (superposition_stack.hpp).
//
// A view on one axis's AxisCore for one call (it owns nothing). Cycle functions: noexcept, no
// allocation; a refused command changes nothing (a compensation is planned into a copy first).
#pragma once

#include "axis/axis_core.hpp"
#include "plc_interface/command.hpp"

namespace nc::detail {

class SuperpositionCommands : public AxisPart {
 public:
  using AxisPart::AxisPart;

  ErrorCode start_compensation(const plc::Command& command) noexcept;
  ErrorCode stop_compensation(const plc::Command& command) noexcept;
  ErrorCode enable_external(const plc::Command& command) noexcept;
  ErrorCode disable_external(const plc::Command& command) noexcept;
};

}  // namespace nc::detail
