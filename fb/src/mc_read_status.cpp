#include "fb/mc_read_status.hpp"

#include "plc_interface/error_code.hpp"
#include "plc_interface/two_speed.hpp"

namespace fb {

namespace {

// A two-speed axis publishes its nAxisState (SPEC E5: 0 inactive, 20 stopped, 21-24 travel and
// braking) in NcToPlc.AxisState; its PLCopen state follows from that and the StateDWord.
// kUndefined for any other value.
plc::AxisState plcopen_state(const plc::NCTOPLC_AXIS_REF& nc) noexcept {
  const auto two_speed = static_cast<plc::TwoSpeedAxisState>(nc.AxisState);
  switch (two_speed) {
    case plc::TwoSpeedAxisState::kInactive:
    case plc::TwoSpeedAxisState::kStopped:
    case plc::TwoSpeedAxisState::kMainTravel:
    case plc::TwoSpeedAxisState::kHighToLowDelay:
    case plc::TwoSpeedAxisState::kLowSpeedTravel:
    case plc::TwoSpeedAxisState::kBrakeIncidenceDelay:
      break;
    default:
      return static_cast<plc::AxisState>(nc.AxisState);
  }
  if (plc::test_bit(nc.StateDWord, plc::kStateError)) return plc::AxisState::kErrorStop;
  if (!plc::test_bit(nc.StateDWord, plc::kStateOperational)) return plc::AxisState::kDisabled;
  if (two_speed == plc::TwoSpeedAxisState::kInactive ||
      two_speed == plc::TwoSpeedAxisState::kStopped) {
    return plc::AxisState::kStandstill;
  }
  // Travel or braking: after MC_Stop / MC_Halt (HasBeenStopped) it is stopping.
  return plc::test_bit(nc.StateDWord, plc::kStateHasBeenStopped) ? plc::AxisState::kStopping
                                                                 : plc::AxisState::kDiscreteMotion;
}

}  // namespace

void MC_ReadStatus::operator()(const plc::AXIS_REF& axis) noexcept {
  *this = MC_ReadStatus{.Enable = Enable};
  if (!Enable) return;
  Busy = true;

  const plc::NCTOPLC_AXIS_REF& nc = axis.NcToPlc;
  Status.Homed = plc::test_bit(nc.StateDWord, plc::kStateHomed);
  Status.HomingBusy = plc::test_bit(nc.StateDWord, plc::kStateHomingBusy);
  switch (plcopen_state(nc)) {
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
