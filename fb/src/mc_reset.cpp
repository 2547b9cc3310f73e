#include "fb/mc_reset.hpp"

#include "fb/detail/plain_command.hpp"

namespace fb {

void MC_Reset::operator()(plc::AXIS_REF& axis) noexcept {
  // The NC never aborts a reset (it is answered in the cycle it is taken).
  detail::run_plain_command(*this, block_, axis, plc::CommandType::kReset);
}

}  // namespace fb
