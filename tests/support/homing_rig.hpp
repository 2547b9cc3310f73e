// Homing tests' shared pieces (issue 13): MC_Home's command as the block posts it, and a PLC
// cycle that passes the simulated reference cam (Kernel::reference_cam) to the NC the way
// MC_Home.bCalibrationCam does (PlcToNc.ControlDWord bit 5) before each NC cycle.
#pragma once

#include <string>

#include "kernel_harness.hpp"

namespace kt {

inline plc::Command home(int32_t mode, double position = plc::DEFAULT_HOME_POSITION) {
  plc::Command c;
  c.type = plc::CommandType::kHome;
  c.mode = mode;
  c.position = position;
  return c;
}

// The seed axis with the homing defaults (cam 100 … 110 mm, 100 mm/s towards it, 10 mm/s off
// it, a sync pulse every 5 mm), not homed at start.
inline nc::AxisConfig homing_axis(std::string name = "X") {
  nc::AxisConfig c = seed_axis(std::move(name));
  c.homed_at_start = false;
  return c;
}

// One PLC cycle reading the cam input, then one NC cycle.
inline void cam_cycle(Harness& h, const std::string& name = "X") {
  h.x->PlcToNc.ControlDWord = plc::with_bit(h.x->PlcToNc.ControlDWord, plc::kControlHomingSensor,
                                            h.kernel.reference_cam(name));
  h.kernel.cycle();
}

}  // namespace kt
