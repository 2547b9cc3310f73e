#include "fb/mc_move_modulo.hpp"

namespace fb {

void MC_MoveModulo::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    if (Direction != MC_Positive_Direction && Direction != MC_Shortest_Way &&
        Direction != MC_Negative_Direction && Direction != MC_Current_Direction) {
      return detail::refuse(plc::ErrorCode::kDirectionInvalid);
    }
    return detail::motion_start(plc::CommandType::kMoveModulo, {.position = Position,
                                                                .velocity = Velocity,
                                                                .acceleration = Acceleration,
                                                                .deceleration = Deceleration,
                                                                .jerk = Jerk,
                                                                .direction = Direction,
                                                                .buffer_mode = BufferMode});
  });
  Done = out.done;
  Busy = out.busy;
  Active = out.active;
  CommandAborted = out.aborted;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
