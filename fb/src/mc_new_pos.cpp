#include "fb/mc_new_pos.hpp"

namespace fb {

void MC_NewPos::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    detail::Start start;
    start.command.type = plc::CommandType::kNewPos;
    start.command.position = NewPos;
    return start;
  });
  Done = out.done;
  Busy = out.busy;
  CommandAborted = out.aborted;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
