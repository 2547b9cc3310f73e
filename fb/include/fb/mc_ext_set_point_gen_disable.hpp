// MC_ExtSetPointGenDisable: switches external setpoint generation off; the NC takes the external
// set position for exactly one more cycle and then holds it, or goes on with its internal
// generator (seed 000 §2.6 "Disabling", SPEC B8).
//
// Execute-type block (rules in fb/detail/execute_block.hpp). Done when the NC has taken the
// command, Error with its code otherwise. Enabled = StateDWord bit 14 (ExtSetPointGenEnabled)
// at every call, whatever the block does.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_ExtSetPointGenDisable {
 public:
  // Input.
  bool Execute = false;

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
