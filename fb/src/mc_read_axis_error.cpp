#include "fb/mc_read_axis_error.hpp"

namespace fb {

void MC_ReadAxisError::operator()(const plc::AXIS_REF& axis) noexcept {
  Valid = Enable;
  Busy = Enable;
  Error = false;
  ErrorID = 0;
  AxisErrorID = Enable ? axis.NcToPlc.ErrorCode : 0;
}

}  // namespace fb
