// MC_ReadStatus: the PLCopen state of an axis as booleans, plus how its set velocity changes
// (Tc2_MC2 MC_ReadStatus).
//
// Enable-type block: while Enable is TRUE it reads NcToPlc on every call and shows Valid and
// Busy; with Enable FALSE every output is FALSE. The state booleans come from NcToPlc.AxisState
// (plc::AxisState, the values of Tc2_MC2's MC_AxisStates); exactly one of them is TRUE. A
// two-speed axis publishes its nAxisState there (0, 20-24): ErrorStop with the error bit,
// Disabled without Operational, StandStill at 0 / 20, else Stopping after a stop (HasBeenStopped)
// or DiscreteMotion. Any other value has no PLCopen state: Error with 0x4040, Valid FALSE.
// ConstantVelocity = StateDWord bit 12. Accelerating / Decelerating: the set acceleration
// makes |SetVelo| grow / shrink (from rest, any set acceleration is accelerating); neither
// while ConstantVelocity is set. Status: the StateDWord bits Tc2_MC2's ST_AxisStatus carries
// that ncsdk publishes so far (Homed = bit 1, HomingBusy = bit 11), read whenever Enable is TRUE.
#pragma once

#include <cstdint>

#include "plc_interface/axis_ref.hpp"

namespace fb {

// The part of Tc2_MC2's ST_AxisStatus that ncsdk fills (grows as the NC publishes more).
struct ST_AxisStatus {
  bool Homed = false;       // the axis is referenced (StateDWord bit 1)
  bool HomingBusy = false;  // a homing sequence runs (StateDWord bit 11)
};

class MC_ReadStatus {
 public:
  // Input.
  bool Enable = false;

  // Outputs.
  bool Valid = false;
  bool Busy = false;
  bool Error = false;
  uint32_t ErrorID = 0;
  bool ErrorStop = false;
  bool Disabled = false;
  bool Stopping = false;
  bool StandStill = false;
  bool DiscreteMotion = false;
  bool ContinuousMotion = false;
  bool SynchronizedMotion = false;
  bool Homing = false;
  bool ConstantVelocity = false;
  bool Accelerating = false;
  bool Decelerating = false;
  ST_AxisStatus Status{};

  // Cycle function: runs the block once.
  void operator()(const plc::AXIS_REF& axis) noexcept;
};

}  // namespace fb
