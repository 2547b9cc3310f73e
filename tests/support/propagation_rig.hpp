// Kernel tests of error propagation and actual-value coupling (SPEC C7, C8; seed 000 §3.1): the
// gear rig's kernel of seed axes "A0" … (all enabled, one cycle run), each tuned by the test,
// with the coupling commands posted straight into the mailboxes (no function blocks).
//
// Test code: it allocates (names, vectors) in set-up only; post(), cycles() and the checks do
// not, so a counted no-allocation region may use them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

#include "gear_rig.hpp"

namespace pr {

// A slave whose drive saturates at 900 mm/s: a master cruising at 1000 mm/s leaves it behind by
// 100 mm/s, and once 5 mm behind for the filter time (20 ms) it raises 0x4550 (following error).
inline void slow_drive(nc::AxisConfig& c) {
  c.drive_max_velocity = 900.0;
  c.following_error_limit = 5.0;
  c.following_error_filter_time = 0.02;
}

inline void delayed(nc::AxisConfig& c, double delay) {
  c.error_propagation_mode = nc::ErrorPropagation::kDelayed;
  c.error_propagation_delay = delay;
}

// gr::Rig with each axis tuned, and what these tests read of an axis.
struct Group : gr::Rig {
  Group(std::size_t n, const std::function<void(std::size_t, nc::AxisConfig&)>& tune)
      : gr::Rig(n, tune) {}

  // MC_GearIn of `slave` to `master`, one cycle; true when InGear.
  bool couple(std::size_t slave, std::size_t master, double ratio) {
    return gr::Rig::couple(slave, master, ratio).state == plc::CommandState::kReached;
  }
  uint32_t error(std::size_t i) { return at(i).NcToPlc.ErrorCode; }
  bool delayed_bit(std::size_t i) { return kt::bit(at(i), plc::kStateErrorPropagationDelayed); }
  bool error_bit(std::size_t i) { return kt::bit(at(i), plc::kStateError); }
  // Cycles until axis `i` shows an error (at most `limit`); the cycles run, or -1.
  int until_error(std::size_t i, int limit = 10000) {
    for (int k = 1; k <= limit; ++k) {
      kernel.cycle();
      if (error(i) != 0U) return k;
    }
    return -1;
  }
};

}  // namespace pr
