// What an axis did over some cycles in which it should brake without a step (K26 tests): the
// largest change of its set velocity from one cycle to the next, its lowest set and actual
// velocity, its last set velocity and the cycle in which the set velocity first was 0.
//
// Test code: no allocation.
#pragma once

#include <algorithm>
#include <cmath>

#include "plc_interface/axis_ref.hpp"

namespace kt {

struct BrakeWatch {
  double largest_step = 0.0;  // mm/s per cycle
  double lowest_set = 1e300;
  double lowest_actual = 1e300;
  double last_set = 0.0;
  int cycles_to_rest = -1;  // -1: never at rest
};

// Runs `step()` (one NC cycle, with or without the PLC's calls) `cycles` times and watches `axis`.
template <class Step>
BrakeWatch watch_brake(const plc::AXIS_REF& axis, int cycles, Step&& step) {
  BrakeWatch b;
  double previous = axis.NcToPlc.SetVelo;
  for (int k = 1; k <= cycles; ++k) {
    step();
    const double v = axis.NcToPlc.SetVelo;
    b.largest_step = std::max(b.largest_step, std::abs(v - previous));
    b.lowest_set = std::min(b.lowest_set, v);
    b.lowest_actual = std::min(b.lowest_actual, axis.NcToPlc.ActVelo);
    if (b.cycles_to_rest < 0 && v == 0.0) b.cycles_to_rest = k;
    previous = v;
  }
  b.last_set = previous;
  return b;
}

}  // namespace kt
