// MC_Home: references an axis (Tc2_MC2 MC_Home; SPEC F; docs/behaviour.md "Homing").
//
// Execute-type block (rules in fb/detail/execute_block.hpp). HomingMode:
//  - MC_DefaultHoming: the NC's sequence (towards the reference cam, off it, sync pulse or cam
//    edge); Busy and Active while it runs, Done once the axis is referenced and at rest;
//  - MC_Direct: the actual position becomes Position without motion (set position with it);
//  - MC_ForceCalibration / MC_ResetCalibration: the axis counts as homed / not homed;
//  - MC_AbsSwitch, MC_LimitSwitch, MC_RefPulse: refused by the NC (0x4F21).
// Position = DEFAULT_HOME_POSITION (the default) takes the axis's configured reference position.
// bCalibrationCam is the reference cam's signal: the block writes it into PlcToNc on every call
// (ControlDWord bit 5), so the block must be called every PLC cycle while homing runs. Only
// BufferMode MC_Aborting is supported (others: 0x4F03, nothing posted). MC_Stop aborts homing.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "fb/types.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_Home {
 public:
  // Inputs (latched on the rising edge of Execute, except bCalibrationCam: every call).
  bool Execute = false;
  double Position = DEFAULT_HOME_POSITION;  // mm
  MC_HomingMode HomingMode = MC_DefaultHoming;
  MC_BufferMode BufferMode = MC_Aborting;
  bool bCalibrationCam = false;

  // Outputs.
  bool Done = false;
  bool Busy = false;
  bool Active = false;
  bool CommandAborted = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(plc::AXIS_REF& axis) noexcept;

  uint16_t command_number() const noexcept { return block_.command_number(); }

 private:
  detail::ExecuteBlock block_;
};

}  // namespace fb
