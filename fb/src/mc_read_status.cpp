#include "fb/mc_read_status.hpp"

#include "plc_interface/error_code.hpp"

namespace fb {

void MC_ReadStatus::operator()(const plc::AXIS_REF& axis) noexcept {
  *this = MC_ReadStatus{.Enable = Enable};
  if (!Enable) return;
  Busy = true;

  const plc::NCTOPLC_AXIS_REF& nc = axis.NcToPlc;
  Status.Homed = plc::test_bit(nc.StateDWord, plc::kStateHomed);
  Status.HomingBusy = plc::test_bit(nc.StateDWord, plc::kStateHomingBusy);
  switch (static_cast<plc::AxisState>(nc.AxisState)) {
    case plc::AxisState::kDisabled:
      Disabled = true;
      break;
    case plc::AxisState::kStandstill:
      StandStill = true;
      break;
    case plc::AxisState::kErrorStop:
      ErrorStop = true;
      break;
    case plc::AxisState::kStopping:
      Stopping = true;
      break;
    case plc::AxisState::kHoming:
      Homing = true;
      break;
    case plc::AxisState::kDiscreteMotion:
      DiscreteMotion = true;
      break;
    case plc::AxisState::kContinuousMotion:
      ContinuousMotion = true;
      break;
    case plc::AxisState::kSynchronizedMotion:
      SynchronizedMotion = true;
      break;
    case plc::AxisState::kUndefined:
    default:
      Error = true;
      ErrorID = plc::to_id(plc::ErrorCode::kAxisKindNotAllowed);
      return;
  }
  Valid = true;

  ConstantVelocity = plc::test_bit(nc.StateDWord, plc::kStateConstantVelocity);
  if (!ConstantVelocity && nc.SetAcc != 0.0) {
    // Same sign: |v| grows; opposite: |v| shrinks; from rest any acceleration starts a motion.
    const double product = nc.SetAcc * nc.SetVelo;
    Accelerating = product > 0.0 || nc.SetVelo == 0.0;
    Decelerating = product < 0.0;
  }
}

}  // namespace fb
