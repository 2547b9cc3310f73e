#include "fb/mc_move_absolute.hpp"

#include "fb/detail/move_command.hpp"

namespace fb {

void MC_MoveAbsolute::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    return detail::motion_start(plc::CommandType::kMoveAbsolute,
                                detail::move_inputs(*this, Position));
  });
  Done = out.done;
  detail::show_outputs(*this, out);
}

}  // namespace fb
