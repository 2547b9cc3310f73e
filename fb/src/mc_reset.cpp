#include "fb/mc_reset.hpp"

namespace fb {

void MC_Reset::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, []() noexcept {
    detail::Start start;
    start.command.type = plc::CommandType::kReset;
    return start;
  });
  // The NC never aborts a reset (it is answered in the cycle it is taken).
  Done = out.done;
  Busy = out.busy;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
