#include "fb/mc_set_override.hpp"

#include <cmath>

#include "plc_interface/error_code.hpp"

namespace fb {

void MC_SetOverride::operator()(plc::AXIS_REF& axis) noexcept {
  if (!Enable) {
    Enabled = false;
    Busy = false;
    Error = false;
    ErrorID = 0;
    return;
  }
  // Written as a comparison that NaN fails.
  const bool valid = VelFactor >= 0.0 && VelFactor <= 1.0;
  if (valid) {
    axis.PlcToNc.Override =
        static_cast<uint32_t>(std::lround(VelFactor * static_cast<double>(plc::kOverrideFull)));
  }
  Enabled = valid;
  Busy = true;
  Error = !valid;
  ErrorID = valid ? 0 : plc::to_id(plc::ErrorCode::kOverrideNotAllowed);
}

}  // namespace fb
