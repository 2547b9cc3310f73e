#include "fb/hli_axis_coupling.hpp"

#include "plc_interface/error_code.hpp"

namespace fb {

bool HLI_AxisCoupling::begin_call() noexcept {
  const bool rising = Execute && !previous_execute_;
  previous_execute_ = Execute;
  // A result was shown in the call that reached it; it stays only while Execute stays high.
  if (phase_ == Phase::kResult && (rising || !Execute)) phase_ = Phase::kIdle;
  return rising && phase_ == Phase::kIdle;
}

void HLI_AxisCoupling::operator()(plc::hli::HLI_AX* unit) noexcept {
  if (unit != nullptr) {
    (*this)(*unit);
    return;
  }
  if (begin_call() || phase_ == Phase::kWaiting || phase_ == Phase::kWritten) {
    phase_ = Phase::kResult;
    result_id_ = plc::to_id(plc::ErrorCode::kInvalidAxisReference);
  }
  show();
}

void HLI_AxisCoupling::operator()(plc::hli::HLI_AX& unit) noexcept {
  plc::hli::HLI_AX_COUPLING_COMMAND& command = unit.lr_mc_control.axis_coupling.command_w;
  if (begin_call()) {
    latched_ = desc;
    phase_ = Phase::kWaiting;
  }
  if (phase_ == Phase::kWaiting && !command.semaphor_rw) {
    command.desc = latched_;
    command.semaphor_rw = true;
    phase_ = Phase::kWritten;
  } else if (phase_ == Phase::kWritten && !command.semaphor_rw) {
    // The NC has evaluated the list and reset the semaphore.
    phase_ = Phase::kResult;
    result_id_ = unit.lr_mc_control.axis_coupling.state_r.error_r;
  }
  show();
}

void HLI_AxisCoupling::show() noexcept {
  Busy = phase_ == Phase::kWaiting || phase_ == Phase::kWritten;
  Done = phase_ == Phase::kResult && result_id_ == 0;
  Error = phase_ == Phase::kResult && result_id_ != 0;
  ErrorID = Error ? result_id_ : 0;
}

}  // namespace fb
