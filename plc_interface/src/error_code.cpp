#include "plc_interface/error_code.hpp"

namespace plc {

std::string_view error_text(ErrorCode code) noexcept {
  using E = ErrorCode;
  switch (code) {
    case E::kNone:
      return "no error";
    case E::kAxisKindNotAllowed:
      return "this axis kind cannot carry out the function";
    case E::kCouplingFactorZero:
      return "coupling factor 0 is not allowed";
    case E::kVelocityNotAllowed:
      return "velocity above the axis's maximum or reference velocity";
    case E::kTargetPositionNotAllowed:
      return "target position outside the software limits";
    case E::kNoControllerOrFeedEnable:
      return "controller or feed enable missing at the start";
    case E::kMovementSmallerThanIncrement:
      return "movement shorter than one encoder increment";
    case E::kDriveNotReady:
      return "drive not ready";
    case E::kEmergencyStopParametersInvalid:
      return "stop deceleration or jerk invalid";
    case E::kSlaveTargetPositionNotAllowed:
      return "slave target position not allowed";
    case E::kSlaveNoControllerOrFeedEnable:
      return "slave lacks controller or feed enable";
    case E::kActivationPositionOutOfRange:
      return "activation position out of range";
    case E::kExtSetPointGenStartInvalid:
      return "external setpoint generation: start data invalid";
    case E::kJerkNotAllowed:
      return "jerk must be greater than 0";
    case E::kAccelerationNotAllowed:
      return "acceleration must be greater than 0";
    case E::kDecelerationNotAllowed:
      return "deceleration must be greater than 0";
    case E::kVelocityNotPositive:
      return "velocity must be greater than 0";
    case E::kOverrideNotAllowed:
      return "override outside 0 … 100 %";
    case E::kStartTypeNotAllowed:
      return "start type not allowed in the axis's present mode";
    case E::kStopAlreadyActive:
      return "a stop is active: the function is not allowed";
    case E::kCompensationIncomplete:
      return "compensation not carried out in full";
    case E::kCompensationParametersInvalid:
      return "compensation parameters invalid";
    case E::kCompensationActive:
      return "not allowed while a compensation is active";
    case E::kCompensationNotActive:
      return "no compensation is active";
    case E::kDecouplingNotAllowed:
      return "decoupling not allowed";
    case E::kFunctionNotAllowed:
      return "function not allowed in the axis's present state";
    case E::kCompensationStopNotAllowed:
      return "compensation is braking: stop not allowed";
    case E::kBusyWhileCoupling:
      return "master or slave busy with a job while coupling";
    case E::kSlaveStartParameterWrong:
      return "slave start parameter wrong";
    case E::kControllerEnableLost:
      return "the axis or a coupled slave lost its controller enable while a command ran";
    case E::kOverrideTypeInvalid:
      return "override type must be 1 … 4";
    case E::kActivationPositionOverrun:
      return "activation position already passed";
    case E::kCompensationLengthInvalid:
      return "compensation length must be greater than 0";
    case E::kCompensationVelocityInvalid:
      return "compensation velocities must be greater than 0";
    case E::kCompensationAccelerationInvalid:
      return "compensation ramps must be greater than 0";
    case E::kNewTargetPositionOverrun:
      return "new target position overrun";
    case E::kModuloTargetInvalid:
      return "modulo target position invalid";
    case E::kIllegalMotionReversal:
      return "illegal motion reversal";
    case E::kDecouplingTypeInvalid:
      return "decoupling type invalid";
    case E::kDecouplingVelocityInvalid:
      return "decoupling target velocity invalid";
    case E::kMotionCommandsLocked:
      return "motion commands locked by MC_Stop";
    case E::kControllerEnableMissing:
      return "controller enable missing";
    case E::kFeedEnableMinusMissing:
      return "feed enable minus missing";
    case E::kFeedEnablePlusMissing:
      return "feed enable plus missing";
    case E::kSetVelocityNotAllowed:
      return "set velocity not allowed";
    case E::kSoftLimitMinAtStart:
      return "software limit min exceeded at the start";
    case E::kSoftLimitMaxAtStart:
      return "software limit max exceeded at the start";
    case E::kSoftLimitMinDuringMotion:
      return "software limit min reached during motion";
    case E::kSoftLimitMaxDuringMotion:
      return "software limit max reached during motion";
    case E::kFollowingErrorPosition:
      return "following error (position) above its limit";
    case E::kFollowingErrorVelocity:
      return "following error (velocity) above its limit";
    case E::kBlockInputOutOfRange:
      return "block input out of range";
    case E::kAxisNotReady:
      return "axis not ready";
    case E::kPositionNotFinite:
      return "position is not a finite number";
    case E::kParameterNotFinite:
      return "parameter is not a finite number";
    case E::kBufferModeNotSupported:
      return "buffer mode not supported";
    case E::kMailboxFull:
      return "command mailbox full";
    case E::kUnknownCommand:
      return "unknown command";
    case E::kAxisInErrorState:
      return "axis in error state: reset it first";
    case E::kDirectionInvalid:
      return "direction invalid";
    case E::kInvalidAxisReference:
      return "partner axis unknown";
    case E::kPlannerNoSolution:
      return "planner found no profile";
    case E::kActualValueNotFinite:
      return "actual value is not a finite number";
    case E::kStateNotFinite:
      return "start state is not finite";
    case E::kTwoSpeedDistanceTooShort:
      return "two-speed axis: distance to the target not larger than the braking distance";
    case E::kCouplingLoop:
      return "coupling would close a loop (or master = slave)";
    case E::kGearRatioOutOfRange:
      return "gear ratio above 1e6 in size";
    case E::kStartFarOutsideLimits:
      return "start state too far outside the limits of the move (2e6 times, or a stop longer than "
             "1e15)";
    case E::kHomingCamNotFound:
      return "homing: reference cam not found within the search distance";
    case E::kHomingModeNotSupported:
      return "homing mode not supported (MC_AbsSwitch, MC_LimitSwitch, MC_RefPulse)";
    case E::kHomingSyncPulseNotFound:
      return "homing: cam edge or sync pulse not found within the search distance";
    case E::kHomingAxisMoving:
      return "homing: setting the position needs the axis at rest without a job";
    case E::kBufferFull:
      return "a buffered command already waits on this axis";
    case E::kAccBoundBelowStability:
      return "cyclic slave: AccBound below the stability bound (warning)";
    case E::kGearRatio1NotTaken:
      return "cyclic slave: GearRatio1 0, NaN, infinite or too large, old factor kept (warning)";
    case E::kPushByHandControllerEnabled:
      return "push by hand: the axis has its controller enable (the drive holds it)";
    case E::kHliFractOnReferencedAxis:
      return "FRACT coupling: the axis cannot stop before a software limit";
    case E::kHliChangeWhileMoving:
      return "coupling change while an axis moves";
    case E::kHliDenominatorZero:
      return "coupling denominator 0";
    case E::kHliFactorTooLarge:
      return "coupling factor above HLI_AXIS_COUPLING_FACT_MAX";
    case E::kHliCouplingLoop:
      return "coupling loop";
  }
  return "unknown error code";
}

std::string_view error_text(uint32_t code) noexcept {
  return error_text(static_cast<ErrorCode>(code));
}

}  // namespace plc
