// MC_Home on a servo axis (SPEC F, issue 13; docs/behaviour.md "Homing"): the homing modes and
// their refusals, the position setting, phase b while the default homing runs (the sequence
// itself is HomingJob, homing_job.hpp), and the simulated reference cam.
//
// A view on one axis's AxisCore for one call (it owns nothing). Cycle functions: noexcept, no
// allocation; a refused MC_Home changes nothing.
#pragma once

#include "axis/axis_core.hpp"
#include "plc_interface/command.hpp"

namespace nc::detail {

class AxisHoming : public AxisPart {
 public:
  using AxisPart::AxisPart;

  ErrorCode start_home(const plc::Command& command) noexcept;
  // Phase b with the homing job as the source.
  void run_homing() noexcept;
  // The simulated reference cam's digital input (AxisConfig::homing_cam_*), on the raw encoder.
  bool reference_cam() const noexcept;

 private:
  // Position setting: every displayed position (set, actual, target) moves by `delta`; nothing
  // moves physically and the following error stays.
  void shift_position(double delta) noexcept;
};

}  // namespace nc::detail
