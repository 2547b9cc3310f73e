// MC_MoveModulo: positions the axis to a modulo position (seed 000 §2.1, modulo start).
//
// Execute-type block (rules in fb/detail/execute_block.hpp), posting kMoveModulo with Position
// and the Direction's MC_Direction value. Below the axis's modulo factor (360 by default) the
// NC reaches the modulo position in the given direction — MC_Positive_Direction,
// MC_Negative_Direction, MC_Shortest_Way (the shorter way round) or MC_Current_Direction (the
// direction of the motion that runs); at or above it, it first travels the extra whole turns
// (from 0, Position 540 with factor 360 travels 540 and ends at modulo 180). Done, Busy, Active,
// CommandAborted, Error, ErrorID as MC_MoveAbsolute; the NC checks Position (0x4F01, 0x4282),
// Velocity and the dynamics (0x4F02, 0x4231, 0x4221, 0x422E…0x4230) and the software limits.
// Checked here, because the NC cannot tell a bad enum value from a meant one: a Direction
// other than the four (0x4F07), a BufferMode outside MC_BufferMode (0x4F03); nothing posted.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "fb/types.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_MoveModulo {
 public:
  // Inputs (latched on the rising edge of Execute).
  bool Execute = false;
  double Position = 0.0;      // mm (or °), the modulo target; ≥ modulo factor adds whole turns
  double Velocity = 0.0;      // mm/s, > 0
  double Acceleration = 0.0;  // mm/s², 0 = axis default
  double Deceleration = 0.0;  // mm/s², 0 = axis default
  double Jerk = 0.0;          // mm/s³, 0 = axis default
  MC_Direction Direction = MC_Positive_Direction;
  MC_BufferMode BufferMode = MC_Aborting;

  // Outputs.
  bool Done = false;
  bool Busy = false;
  bool Active = false;
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
