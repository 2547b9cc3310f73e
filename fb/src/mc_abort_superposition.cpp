#include "fb/mc_abort_superposition.hpp"

namespace fb {

void MC_AbortSuperposition::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, []() noexcept {
    detail::Start start;
    start.command.type = plc::CommandType::kAbortSuperposition;
    return start;
  });
  // A compensation stop is not a job of its own: nothing can abort it, so no CommandAborted.
  Done = out.done;
  Busy = out.busy;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
