// The Execute-type blocks whose only input is Execute and whose outputs are Done, Busy, Error
// and ErrorID (MC_Reset, MC_GearOut, MC_AbortSuperposition): their one body, written once.
// Cycle functions only (no allocation, no exceptions, no I/O).
#pragma once

#include "fb/detail/execute_block.hpp"
#include "plc_interface/axis_ref.hpp"
#include "plc_interface/command.hpp"

namespace fb::detail {

// The Start of a command that carries nothing but its type.
inline Start plain_command(plc::CommandType type) noexcept {
  Start start;
  start.command.type = type;
  return start;
}

// One call of a block whose only input is Execute and whose outputs are Done, Busy, Error and
// ErrorID (MC_Reset, MC_GearOut, MC_AbortSuperposition): posts `type` on the rising edge and
// writes those outputs. `rules` is the block's own ExecuteBlock.
template <class Block>
void run_plain_command(Block& block, ExecuteBlock& rules, plc::AXIS_REF& axis,
                       plc::CommandType type) noexcept {
  const ExecuteOutputs out =
      rules(block.Execute, axis, [type]() noexcept { return plain_command(type); });
  block.Done = out.done;
  block.Busy = out.busy;
  block.Error = out.error;
  block.ErrorID = out.error_id;
}

}  // namespace fb::detail
