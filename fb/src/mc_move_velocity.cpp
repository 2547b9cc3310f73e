#include "fb/mc_move_velocity.hpp"

#include "fb/detail/move_command.hpp"

namespace fb {

void MC_MoveVelocity::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    // The NC cannot tell a bad enum value from a meant one: checked here.
    if (Direction != MC_Positive_Direction && Direction != MC_Negative_Direction &&
        Direction != MC_Current_Direction) {
      return detail::refuse(plc::ErrorCode::kDirectionInvalid);
    }
    return detail::motion_start(plc::CommandType::kMoveVelocity,
                                detail::move_inputs(*this, 0.0, Direction));
  });
  // A velocity job has no end of its own; a kDone answer (never sent for it)
  // shows nothing.
  InVelocity = out.reached;
  detail::show_outputs(*this, out);
}

}  // namespace fb
