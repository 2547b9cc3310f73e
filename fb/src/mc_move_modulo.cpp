#include "fb/mc_move_modulo.hpp"

#include "fb/detail/move_command.hpp"

namespace fb {

void MC_MoveModulo::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    if (Direction != MC_Positive_Direction && Direction != MC_Shortest_Way &&
        Direction != MC_Negative_Direction && Direction != MC_Current_Direction) {
      return detail::refuse(plc::ErrorCode::kDirectionInvalid);
    }
    return detail::motion_start(plc::CommandType::kMoveModulo,
                                detail::move_inputs(*this, Position, Direction));
  });
  Done = out.done;
  detail::show_outputs(*this, out);
}

}  // namespace fb
