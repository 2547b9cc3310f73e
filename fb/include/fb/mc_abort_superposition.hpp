// MC_AbortSuperposition: compensation stop — ends a running position compensation early, the
// distance D replaced by the distance compensated by then (seed 000 §2.5 "Compensation stop",
// SPEC B7).
//
// Execute-type block (rules in fb/detail/execute_block.hpp). The NC answers Done once the
// compensation stop is taken, or Error with its code (e.g. 0x4246 no compensation active,
// 0x4258 the compensation is already in its braking phase). The basic motion is not touched.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_AbortSuperposition {
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
