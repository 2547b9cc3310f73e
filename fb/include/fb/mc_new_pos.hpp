// MC_NewPos: a new end position for the positioning that runs (seed 000 §2.3 "New end position").
//
// Execute-type block (rules in fb/detail/execute_block.hpp), posting kNewPos with NewPos as the
// command's position. The NC re-plans the running positioning to NewPos the quickest way; where
// the axis has passed NewPos or cannot stop before it, it stops and returns on its own. The
// block shows the NC's answer for its command: Done when the NC reports it done, CommandAborted
// when another command took over first, Error with the NC's code when refused — NaN/±inf
// (0x4F01), outside the software limits (0x4222), while a stop is active, during position
// compensation, on an axis in error (0x4F06). The block checks nothing itself.
// Like Tc2's MC_NewPos it has no Active output.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_NewPos {
 public:
  // Inputs (latched on the rising edge of Execute).
  bool Execute = false;
  double NewPos = 0.0;  // mm, the new end position

  // Outputs.
  bool Done = false;
  bool Busy = false;
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
