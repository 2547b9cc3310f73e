// MC_Power: the software enables of an axis and its velocity override (Tc2_MC2 MC_Power).
//
// Enable-type block: it acts on every call, there is no command. It writes
// PlcToNc.ControlDWord bit 0 (controller enable) = Enable, bit 1 (feed enable plus) =
// Enable AND Enable_Positive, bit 2 (feed enable minus) = Enable AND Enable_Negative — the feed
// enables take effect only with Enable, as in Tc2_MC2 — and leaves the other bits alone.
// Override (percent) is written as PlcToNc.Override = round(Override · 10 000) (1 000 000 =
// 100 %) on the block's first call and whenever the input differs from the value the block wrote
// last — not on every call, so that an enabled MC_SetOverride on the same axis wins whatever the
// call order (see mc_set_override.hpp). An Override outside 0 … 100 or NaN is not written (the
// last valid value stays) and the block shows Error with 0x4238 until the input is valid again,
// independently of Enable (the override is written whether the axis is enabled or not).
// Status = NcToPlc.StateDWord bit 0 (Operational). Busy while Enable is TRUE; Active while
// Enable is TRUE and the block's values are all applied (no Error).
#pragma once

#include <cstdint>

#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_Power {
 public:
  // Inputs (read every call).
  bool Enable = false;
  bool Enable_Positive = false;
  bool Enable_Negative = false;
  double Override = 100.0;  // %, 0 … 100

  // Outputs.
  bool Status = false;
  bool Busy = false;
  bool Active = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(plc::AXIS_REF& axis) noexcept;

 private:
  // Writes Override to PlcToNc.Override and remembers it (a valid value that differs).
  [[gnu::noinline]] void write_override(plc::AXIS_REF& axis) noexcept;

  bool override_written_ = false;  // the block has written an override
  double written_override_ = 0.0;  // %, the override it wrote last
};

}  // namespace fb
