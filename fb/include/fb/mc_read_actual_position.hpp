// MC_ReadActualPosition: the axis's actual position (Tc2_MC2 MC_ReadActualPosition).
//
// Enable-type block: while Enable is TRUE, Position = NcToPlc.ActPos on every call, with Valid
// and Busy TRUE; with Enable FALSE every output is FALSE / 0. An actual position that is not a
// finite number is not shown: Error with 0x4F0B (kActualValueNotFinite), Valid FALSE.
#pragma once

#include <cstdint>

#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_ReadActualPosition {
 public:
  // Input.
  bool Enable = false;

  // Outputs.
  bool Valid = false;
  bool Busy = false;
  bool Error = false;
  uint32_t ErrorID = 0;
  double Position = 0.0;  // mm

  // Cycle function: runs the block once.
  void operator()(const plc::AXIS_REF& axis) noexcept;
};

}  // namespace fb
