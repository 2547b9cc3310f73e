// The PLCopen output rules every Execute-type block must keep at every call (API.md, SPEC F),
// checked after each call by fuzz_blocks and the soak: Busy, Done, Error and CommandAborted
// mutually exclusive; Active only with Busy and never beside Done, Error or CommandAborted;
// ErrorID non-zero exactly with Error. Blocks without a Done (MC_MoveVelocity) or an Active
// (MC_Reset, MC_NewPos, …) are checked on the outputs they have.
#pragma once

#include <cstdint>

#include "fail.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fuzz {

template <class Block>
FUZZ_CHECKER const char* broken_output_rule(const Block& b) noexcept {
  bool done = false;
  bool active = false;
  bool aborted = false;
  if constexpr (requires { b.Done; }) done = b.Done;
  if constexpr (requires { b.Active; }) active = b.Active;
  if constexpr (requires { b.CommandAborted; }) aborted = b.CommandAborted;
  const int shown = int{b.Busy} + int{done} + int{b.Error} + int{aborted};
  if (shown > 1) return "Busy, Done, Error and CommandAborted not exclusive";
  if (active && !b.Busy) return "Active without Busy";
  if (b.Error != (b.ErrorID != 0)) return "ErrorID does not go with Error";
  return nullptr;
}

// Calls the block once and crashes when an output rule breaks.
template <class Block>
void call_checked(Block& block, plc::AXIS_REF& axis) noexcept {
  block(axis);
  if (const char* broken = broken_output_rule(block)) fail(broken);
}

}  // namespace fuzz
