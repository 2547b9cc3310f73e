#include "fb/mc_move_relative.hpp"

#include "fb/detail/move_command.hpp"

namespace fb {

void MC_MoveRelative::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    return detail::motion_start(plc::CommandType::kMoveRelative,
                                detail::move_inputs(*this, Distance));
  });
  Done = out.done;
  detail::show_outputs(*this, out);
}

}  // namespace fb
