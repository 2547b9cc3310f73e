#include "fb/mc_abort_superposition.hpp"

#include "fb/detail/plain_command.hpp"

namespace fb {

void MC_AbortSuperposition::operator()(plc::AXIS_REF& axis) noexcept {
  // A compensation stop is not a job of its own: nothing can abort it, so no CommandAborted.
  detail::run_plain_command(*this, block_, axis, plc::CommandType::kAbortSuperposition);
}

}  // namespace fb
