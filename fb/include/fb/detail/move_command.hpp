// What the PLCopen move blocks (MC_MoveAbsolute, MC_MoveRelative, MC_MoveModulo,
// MC_MoveVelocity) have in common, written once: their dynamics inputs go into the command the
// same way, and they show the rules' outputs the same way. Each block keeps only what is its own
// (target, direction check, Done or InVelocity).
// Cycle functions only: no allocation, no exceptions, no I/O.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"

namespace fb::detail {

// The command inputs of a move block: its Velocity, Acceleration, Deceleration, Jerk and
// BufferMode, with the block's own target (`position`: Position or Distance) and direction.
template <class Block>
MotionInputs move_inputs(const Block& block, double position = 0.0,
                         int32_t direction = 0) noexcept {
  return {.position = position,
          .velocity = block.Velocity,
          .acceleration = block.Acceleration,
          .deceleration = block.Deceleration,
          .jerk = block.Jerk,
          .direction = direction,
          .buffer_mode = block.BufferMode};
}

// Busy, Active, CommandAborted, Error and ErrorID from the rules' outputs; the block shows its
// end (Done, or InVelocity for a velocity job) itself.
template <class Block>
void show_outputs(Block& block, const ExecuteOutputs& out) noexcept {
  block.Busy = out.busy;
  block.Active = out.active;
  block.CommandAborted = out.aborted;
  block.Error = out.error;
  block.ErrorID = out.error_id;
}

}  // namespace fb::detail
