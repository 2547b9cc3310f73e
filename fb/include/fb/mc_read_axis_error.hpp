// MC_ReadAxisError: the axis's error code (Tc2_MC2 MC_ReadAxisError).
//
// Enable-type block: while Enable is TRUE, AxisErrorID = NcToPlc.ErrorCode on every call (0 =
// no axis error), with Valid and Busy TRUE; with Enable FALSE every output is FALSE / 0. The
// block's own Error is for failures of the block itself; reading the image cannot fail, so an
// axis error is shown in AxisErrorID, not in Error.
#pragma once

#include <cstdint>

#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_ReadAxisError {
 public:
  // Input.
  bool Enable = false;

  // Outputs.
  bool Valid = false;
  bool Busy = false;
  bool Error = false;
  uint32_t ErrorID = 0;
  uint32_t AxisErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(const plc::AXIS_REF& axis) noexcept;
};

}  // namespace fb
