// The cyclic axis interface: what the PLC sees of an NC axis, and what it writes to it.
//
// Mirrors TwinCAT's NCTOPLC_AXIS_REF / PLCTONC_AXIS_REF. The NC publishes NcToPlc at the end of
// every NC cycle and reads PlcToNc at its start; commands travel through the mailbox. Nothing
// else crosses between the PLC side and the NC side. Plain data: no allocation, no locks.
#pragma once

#include <cstdint>

#include "plc_interface/command.hpp"

namespace plc {

// Bit numbers of NCTOPLC_AXIS_REF.StateDWord (TwinCAT's numbering).
enum StateBit : uint32_t {
  kStateOperational = 0,
  kStateHomed = 1,
  kStateNotMoving = 2,
  kStateInPositionArea = 3,
  kStateInTargetPosition = 4,
  kStateProtected = 5,
  kStateErrorPropagationDelayed = 6,
  kStateHasBeenStopped = 7,
  kStateHasJob = 8,
  kStatePositiveDirection = 9,
  kStateNegativeDirection = 10,
  kStateHomingBusy = 11,
  kStateConstantVelocity = 12,
  kStateCompensating = 13,
  kStateExtSetPointGenEnabled = 14,
  // The coupling flag (seed 000 §3.2.1): set while the axis is a coupled slave. TwinCAT shows
  // coupling in CoupleState and publishes no StateDWord bit for it, so ncsdk uses the free bit 15.
  kStateCoupled = 15,
  kStateNewTargetPos = 17,
  kStateContinuousMotion = 19,
  kStatePtpMode = 25,
  kStateSoftLimitMinExceeded = 26,
  kStateSoftLimitMaxExceeded = 27,
  kStateMotionCommandsLocked = 29,
  kStateError = 31,
};

// Bit numbers of PLCTONC_AXIS_REF.ControlDWord.
enum ControlBit : uint32_t {
  kControlEnable = 0,
  kControlFeedEnablePlus = 1,
  kControlFeedEnableMinus = 2,
  // The reference cam (MC_Home.bCalibrationCam, TwinCAT's "homing sensor" bit): the NC samples it
  // while a default homing runs.
  kControlHomingSensor = 5,
};

// PLCopen axis state (Tc2_MC2 MC_AxisStates values), published in NcToPlc.AxisState.
// A two-speed axis publishes its nAxisState (0, 20 … 24) there instead.
enum class AxisState : uint32_t {
  kUndefined = 0,
  kDisabled = 1,
  kStandstill = 2,
  kErrorStop = 3,
  kStopping = 4,
  kHoming = 5,
  kDiscreteMotion = 6,
  kContinuousMotion = 7,
  kSynchronizedMotion = 8,
};

// NcToPlc.CoupleState values.
enum class CoupleState : uint32_t { kSingle = 0, kMaster = 1, kMasterAndSlave = 2, kSlave = 3 };

// Override scale: 1'000'000 = 100 %.
inline constexpr uint32_t kOverrideFull = 1'000'000;

struct NCTOPLC_AXIS_REF {
  uint32_t StateDWord = 0;
  uint32_t ErrorCode = 0;
  uint32_t AxisState = static_cast<uint32_t>(AxisState::kDisabled);
  uint32_t CoupleState = 0;
  double ActPos = 0.0;
  double ModuloActPos = 0.0;
  double ActVelo = 0.0;
  double ActAcc = 0.0;
  double PosDiff = 0.0;  // following error: set position - actual position
  double SetPos = 0.0;
  double ModuloSetPos = 0.0;
  double SetVelo = 0.0;
  double SetAcc = 0.0;
  double SetJerk = 0.0;
  double TargetPos = 0.0;
  double TargetVelo = 0.0;            // the velocity level the running job aims at (after override)
  double CompensationDistance = 0.0;  // compensation travelled so far (B7)
  uint32_t Warning = 0;               // last warning code (e.g. compensation incomplete)
  uint16_t CmdNo = 0;                 // command the axis executes
  uint16_t CmdState = 0;              // its CommandState
  int32_t AxisIndex = -1;             // the kernel's index of this axis (for coupling commands)
  uint32_t CycleCounter = 0;          // NC cycles since start (wraps)
  // The running (or last) position compensation as the NC plans it (B7; MC_MoveSuperImposed's
  // ActualLength / ActualVelocityDiff): the compensation length in use (L, or the remaining
  // distance when shorter) and the signed peak extra velocity (at most VK).
  double CompensationLength = 0.0;
  double CompensationVelocityDiff = 0.0;
  // The coupling factor in force while the axis is a coupled slave (SPEC C1); 0 otherwise.
  double GearRatio = 0.0;
};

struct PLCTONC_AXIS_REF {
  uint32_t ControlDWord = 0;
  uint32_t Override = kOverrideFull;  // 0 … 1'000'000 = 0 … 100 %
  double ExtSetPos = 0.0;
  double ExtSetVelo = 0.0;
  double ExtSetAcc = 0.0;
  int32_t ExtSetDirection = 0;  // -1, 0, +1
  double GearRatio1 = 1.0;      // cyclic coupling factor (MC_GearInDyn)
};

struct AXIS_REF {
  PLCTONC_AXIS_REF PlcToNc;
  NCTOPLC_AXIS_REF NcToPlc;
  CommandMailbox Mailbox;
};

constexpr bool test_bit(uint32_t word, uint32_t bit) noexcept {
  return ((word >> bit) & 1U) != 0;
}
constexpr uint32_t with_bit(uint32_t word, uint32_t bit, bool value) noexcept {
  return value ? (word | (1U << bit)) : (word & ~(1U << bit));
}

}  // namespace plc
