#include "fb/mc_power.hpp"

#include <cmath>

#include "plc_interface/error_code.hpp"

namespace fb {

void MC_Power::operator()(plc::AXIS_REF& axis) noexcept {
  uint32_t control = axis.PlcToNc.ControlDWord;
  control = plc::with_bit(control, plc::kControlEnable, Enable);
  control = plc::with_bit(control, plc::kControlFeedEnablePlus, Enable && Enable_Positive);
  control = plc::with_bit(control, plc::kControlFeedEnableMinus, Enable && Enable_Negative);
  axis.PlcToNc.ControlDWord = control;

  // Written as a comparison that NaN fails.
  const bool override_valid = Override >= 0.0 && Override <= 100.0;
  Status = plc::test_bit(axis.NcToPlc.StateDWord, plc::kStateOperational);
  Error = !override_valid;
  ErrorID = override_valid ? 0 : plc::to_id(plc::ErrorCode::kOverrideNotAllowed);
  Busy = Enable;
  Active = Enable && !Error;
  // Last, so that its call is the block's last step (a jump): no call of the block saves and
  // restores registers for it. The outputs above do not depend on it.
  if (override_valid && (!override_written_ || Override != written_override_)) {
    write_override(axis);
  }
}

// Out of line: the call of lround made every call of the block save and restore registers.
void MC_Power::write_override(plc::AXIS_REF& axis) noexcept {
  axis.PlcToNc.Override = static_cast<uint32_t>(std::lround(Override * 10'000.0));
  override_written_ = true;
  written_override_ = Override;
}

}  // namespace fb
