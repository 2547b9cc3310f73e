// The coupling command of MC_GearIn and MC_GearInDyn, written once: the master's kernel index,
// the factor and the block's dynamics inputs. Cycle function: no allocation, no exceptions.
#pragma once

#include "fb/detail/execute_block.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb::detail {

template <class Block>
Start gear_start(const Block& block, plc::CommandType type, double ratio,
                 const plc::AXIS_REF& master) noexcept {
  Start start;
  start.command.type = type;
  start.command.ratio = ratio;
  start.command.other_axis = master.NcToPlc.AxisIndex;
  start.command.acceleration = block.Acceleration;
  start.command.deceleration = block.Deceleration;
  start.command.jerk = block.Jerk;
  start.command.buffer_mode = block.BufferMode;
  return start;
}

}  // namespace fb::detail
