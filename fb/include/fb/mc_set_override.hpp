// MC_SetOverride: the velocity override of an axis as a factor (Tc2_MC2 MC_SetOverride; seed 000
// §2.2 "Override").
//
// Enable-type block: no command, it acts on every call. While Enable is TRUE it writes
// PlcToNc.Override = round(VelFactor · 1 000 000) (1.0 = 100 %), so the NC changes the velocity
// level at once, as fast as A+/A-/J allow (the NC's override types 1…4 decide what "100 %"
// refers to). A VelFactor outside 0 … 1 or NaN is not written (the last value stays) and the
// block shows Error 0x4238 until the input is valid again. When Enable falls the outputs reset
// and the override keeps the value written last (the block does not restore an older one).
//
// Against MC_Power.Override: MC_Power writes its Override only when that input changes (and on
// its first call), MC_SetOverride on every call while enabled — so while an MC_SetOverride is
// enabled it wins, whatever the order in which the program calls the two blocks.
#pragma once

#include <cstdint>

#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_SetOverride {
 public:
  // Inputs (read every call).
  bool Enable = false;
  double VelFactor = 1.0;  // 0 … 1; 1.0 = 100 %

  // Outputs.
  bool Enabled = false;  // the override of VelFactor is written
  bool Busy = false;     // Enable is TRUE
  bool Error = false;
  uint32_t ErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(plc::AXIS_REF& axis) noexcept;
};

}  // namespace fb
