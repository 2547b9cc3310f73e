// The one buffered command of an axis (Tc2_MC2 BufferMode, issue 14; docs/behaviour.md
// "BufferMode"): a MoveAbsolute / MoveRelative / MoveModulo / MoveVelocity / Halt posted with a
// BufferMode other than MC_Aborting waits here, answered kBuffered, until the running command is
// done (MC_Buffered) or has passed its target (the four blending modes); then it takes over and
// is answered kActive. A second one while one waits is refused (kBufferFull); an aborting
// command, a stop or an axis error drops the waiting one.
//
// The waiting command plus pure helpers; when it takes over is BufferedCommands'
// (buffered_commands.hpp). Whether one waits is AxisCore::buffer_waiting_, among the hot members
// (the steady cycle reads only that; docs/performance.md "Eighth pass"). Cycle functions only:
// noexcept, no allocation.
#pragma once

#include <cstdint>

#include "axis/axis_channel.hpp"
#include "plc_interface/command.hpp"

namespace nc::detail {

struct CommandBuffer {
  plc::Command command{};  // valid while the axis's flag `waiting` is set

  // The waiting command, if any (`waiting`), is answered `state` on `channel` (an aborting
  // command, a stop, an error) and leaves the buffer.
  void drop(bool& waiting, AxisChannel& channel, plc::CommandState state,
            uint32_t code = 0) const noexcept {
    if (!waiting) return;
    waiting = false;
    channel.answer(command.number, state, code);
  }
};

// A BufferMode value the NC knows (MC_Aborting … MC_BlendingHigh).
constexpr bool known_buffer_mode(int32_t mode) noexcept {
  return mode >= plc::MC_Aborting && mode <= plc::MC_BlendingHigh;
}

constexpr bool blending_mode(int32_t mode) noexcept {
  return mode >= plc::MC_BlendingLow && mode <= plc::MC_BlendingHigh;
}

// The commands that take a BufferMode (the others ignore it).
constexpr bool bufferable(plc::CommandType type) noexcept {
  return type == plc::CommandType::kMoveAbsolute || type == plc::CommandType::kMoveRelative ||
         type == plc::CommandType::kMoveModulo || type == plc::CommandType::kMoveVelocity ||
         type == plc::CommandType::kHalt;
}

// The velocity a blending mode asks for at the first command's target, from the two commands'
// velocities (Low: the lower, Previous: the first's, Next: the second's, High: the higher);
// 0 for MC_Aborting and MC_Buffered.
double blend_velocity(int32_t mode, double previous, double next) noexcept;

}  // namespace nc::detail
