#include "fb/mc_read_actual_position.hpp"

#include <cmath>

#include "plc_interface/error_code.hpp"

namespace fb {

void MC_ReadActualPosition::operator()(const plc::AXIS_REF& axis) noexcept {
  Busy = Enable;
  const double position = axis.NcToPlc.ActPos;
  const bool finite = std::isfinite(position);
  Valid = Enable && finite;
  Error = Enable && !finite;
  ErrorID = Error ? plc::to_id(plc::ErrorCode::kActualValueNotFinite) : 0;
  Position = Valid ? position : 0.0;
}

}  // namespace fb
