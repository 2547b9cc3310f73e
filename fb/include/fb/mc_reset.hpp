// MC_Reset: clears the axis error (and a MC_Stop lock) so that the axis takes motion again
// (SPEC A6; Tc2_MC2 MC_Reset).
//
// Execute-type block (rules in fb/detail/execute_block.hpp). The NC answers in the cycle it
// takes the command: Done, or Error with the code why the reset failed.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_Reset {
 public:
  // Input.
  bool Execute = false;

  // Outputs.
  bool Done = false;
  bool Busy = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(plc::AXIS_REF& axis) noexcept;

  uint16_t command_number() const noexcept { return block_.command_number(); }

 private:
  detail::ExecuteBlock block_;
};

}  // namespace fb
