// The one error-code catalogue of ncsdk.
//
// Codes cross the PLC↔NC interface (NcToPlc.ErrorCode, command answers, blocks' ErrorID), so the
// catalogue belongs to the contract. Where the vendor (TwinCAT NC) has a public number for a
// situation we use it, so users find the same code in the vendor's manuals; our own codes live in
// the free range 0x4Fxx. CNC HLI coupling IDs are decimal (70xxx). Every code has a text.
#pragma once

#include <cstdint>
#include <string_view>

namespace plc {

enum class ErrorCode : uint32_t {
  kNone = 0,

  // --- TwinCAT NC numbers (group / axis level) ---
  kAxisKindNotAllowed = 0x4040,
  kCouplingFactorZero = 0x421B,
  kVelocityNotAllowed = 0x4221,  // above max or reference velocity
  kTargetPositionNotAllowed = 0x4222,
  kNoControllerOrFeedEnable = 0x4223,
  kMovementSmallerThanIncrement = 0x4224,  // warning at a start
  kDriveNotReady = 0x4225,
  kEmergencyStopParametersInvalid = 0x4226,
  kSlaveTargetPositionNotAllowed = 0x4229,
  kSlaveNoControllerOrFeedEnable = 0x422A,
  kActivationPositionOutOfRange = 0x422B,
  kExtSetPointGenStartInvalid = 0x422C,
  kJerkNotAllowed = 0x422E,
  kAccelerationNotAllowed = 0x422F,
  kDecelerationNotAllowed = 0x4230,
  kVelocityNotPositive = 0x4231,
  kOverrideNotAllowed = 0x4238,
  kStartTypeNotAllowed = 0x4239,
  kStopAlreadyActive = 0x4242,
  kCompensationIncomplete = 0x4243,  // warning
  kCompensationParametersInvalid = 0x4244,
  kCompensationActive = 0x4245,
  kCompensationNotActive = 0x4246,
  kDecouplingNotAllowed = 0x424D,
  kFunctionNotAllowed = 0x424E,
  kCompensationStopNotAllowed = 0x4258,
  kBusyWhileCoupling = 0x425A,
  kSlaveStartParameterWrong = 0x425B,
  // The axis or a coupled slave lost its controller enable while executing a command.
  kControllerEnableLost = 0x4260,
  kOverrideTypeInvalid = 0x426C,
  kActivationPositionOverrun = 0x426D,
  kCompensationLengthInvalid = 0x4270,
  kCompensationVelocityInvalid = 0x4271,
  kCompensationAccelerationInvalid = 0x4272,
  kNewTargetPositionOverrun = 0x427F,
  kModuloTargetInvalid = 0x4282,
  kIllegalMotionReversal = 0x4289,
  kDecouplingTypeInvalid = 0x428D,
  kDecouplingVelocityInvalid = 0x428E,
  kMotionCommandsLocked = 0x42EF,
  kControllerEnableMissing = 0x4356,  // HLI target's drive, two-speed axis (not a gear axis)
  kFeedEnableMinusMissing = 0x4357,
  kFeedEnablePlusMissing = 0x4358,
  kSetVelocityNotAllowed = 0x4359,
  kSoftLimitMinAtStart = 0x4460,
  kSoftLimitMaxAtStart = 0x4461,
  kSoftLimitMinDuringMotion = 0x4462,
  kSoftLimitMaxDuringMotion = 0x4463,
  kFollowingErrorPosition = 0x4550,
  kFollowingErrorVelocity = 0x4551,
  kBlockInputOutOfRange = 0x4B06,
  kAxisNotReady = 0x4B09,

  // --- ncsdk's own numbers ---
  kPositionNotFinite = 0x4F01,       // target, distance or start position NaN or infinite
  kParameterNotFinite = 0x4F02,      // another parameter NaN or infinite
  kBufferModeNotSupported = 0x4F03,  // BufferMode not one of MC_BufferMode's values
  kMailboxFull = 0x4F04,
  kUnknownCommand = 0x4F05,
  kAxisInErrorState = 0x4F06,  // motion refused until MC_Reset
  kDirectionInvalid = 0x4F07,
  kInvalidAxisReference = 0x4F08,      // partner axis index unknown
  kPlannerNoSolution = 0x4F09,         // the planner found no profile (internal; never expected)
  kStateNotFinite = 0x4F0A,            // start state (p, v, a) NaN or infinite
  kActualValueNotFinite = 0x4F0B,      // an actual value read by a block is NaN or infinite
  kTwoSpeedDistanceTooShort = 0x4F0C,  // two-speed start not farther than the braking distance
  kCouplingLoop = 0x4F0D,              // coupling would close a loop (also master = slave)
  kGearRatioOutOfRange = 0x4F71,       // MC_GearIn ratio above 1e6 in size
  kStartFarOutsideLimits = 0x4F70,  // planner start 2e6 times outside the limits or 1e15 from rest
  // Homing (MC_Home; ncsdk's range 0x4F20 … 0x4F2F).
  kHomingCamNotFound = 0x4F20,        // no reference cam within the search distance
  kHomingModeNotSupported = 0x4F21,   // MC_AbsSwitch, MC_LimitSwitch, MC_RefPulse
  kHomingSyncPulseNotFound = 0x4F22,  // cam edge or sync pulse not within the search distance
  kHomingAxisMoving = 0x4F23,         // MC_Direct while the axis has a job or moves
  kBufferFull = 0x4F60,               // a buffered command already waits on this axis
  // Cyclic slave (MC_GearInDyn; ncsdk's range 0x4F80 … 0x4F8F), both warnings.
  kAccBoundBelowStability = 0x4F80,  // AccBound < max|factor| × the master's max acceleration
  kGearRatio1NotTaken = 0x4F81,      // PlcToNc.GearRatio1 0, NaN, inf or above 1e6: old factor kept
  // Error propagation and actual-value coupling (SPEC C7, C8; ncsdk's range 0x4F90 … 0x4F9F).
  kPushByHandControllerEnabled = 0x4F90,  // Kernel::push_by_hand on an axis that is enabled

  // --- CNC HLI coupling IDs (decimal) ---
  kHliFractOnReferencedAxis = 70195,
  kHliChangeWhileMoving = 70200,
  kHliDenominatorZero = 70396,
  kHliFactorTooLarge = 70397,
  kHliCouplingLoop = 70410,
};

constexpr uint32_t to_id(ErrorCode code) noexcept {
  return static_cast<uint32_t>(code);
}

// A short text for every code; "unknown error code" for numbers outside the catalogue.
std::string_view error_text(ErrorCode code) noexcept;
std::string_view error_text(uint32_t code) noexcept;

// True for codes that are warnings (the command still runs).
constexpr bool is_warning(ErrorCode code) noexcept {
  return code == ErrorCode::kMovementSmallerThanIncrement ||
         code == ErrorCode::kCompensationIncomplete || code == ErrorCode::kAccBoundBelowStability ||
         code == ErrorCode::kGearRatio1NotTaken;
}

}  // namespace plc
