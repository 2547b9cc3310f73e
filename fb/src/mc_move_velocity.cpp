#include "fb/mc_move_velocity.hpp"

namespace fb {

void MC_MoveVelocity::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    // The NC cannot tell a bad enum value from a meant one: checked here.
    if (Direction != MC_Positive_Direction && Direction != MC_Negative_Direction &&
        Direction != MC_Current_Direction) {
      return detail::refuse(plc::ErrorCode::kDirectionInvalid);
    }
    return detail::motion_start(plc::CommandType::kMoveVelocity, {.velocity = Velocity,
                                                                  .acceleration = Acceleration,
                                                                  .deceleration = Deceleration,
                                                                  .jerk = Jerk,
                                                                  .direction = Direction,
                                                                  .buffer_mode = BufferMode});
  });
  // A velocity job has no end of its own; a kDone answer (never sent for it) shows nothing.
  InVelocity = out.reached;
  Busy = out.busy;
  Active = out.active;
  CommandAborted = out.aborted;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
