// The state behind SPEC C7 (error propagation, seed 000 §3.1 "Advanced NC error handling") and C8
// (coupling to actual values, §3.1 "Changeover to actual value coupling") for one axis; the rules
// are in docs/behaviour.md "Error propagation and actual-value coupling". Plain data; cycle
// functions only (noexcept, no allocation).
#pragma once

#include <cmath>
#include <cstdint>

#include "nc_core/profile.hpp"

namespace nc::detail {

// The countdown from an axis's own error to its group reaction. Started in the cycle the error
// is raised (bit 31 shows from that cycle), stepped once in every monitor phase: due in the cycle
// `cycles` later (0: the same cycle, INSTANTANEOUS). While it runs the axis shows StateDWord bit
// 6 (ErrorPropagationDelayed).
struct PropagationDelay {
  bool pending = false;
  uint64_t left = 0;

  void start(uint64_t cycles) noexcept {
    pending = true;
    left = cycles;
  }
  void cancel() noexcept { pending = false; }
  // The monitor phase of each cycle; `raised_now`: the error was raised in this cycle (the
  // countdown starts with the next one). True in the one cycle the group reaction is due.
  bool step(bool raised_now) noexcept {
    if (!pending) return false;
    if (!raised_now && left > 0) --left;
    if (left > 0) return false;
    pending = false;
    return true;
  }
  // Bit 6: the delay runs (shown after step() in the same cycle).
  bool delayed() const noexcept { return pending; }
};

// The whole NC cycles of a delay in seconds (round to nearest), saturated for a delay of years.
inline uint64_t delay_cycles(double delay, double cycle_time) noexcept {
  const double n = std::round(delay / cycle_time);
  return n < 1e15 ? static_cast<uint64_t>(n) : uint64_t{1000000000000000};
}

// What the slaves of an axis follow while it drives them by its actual values (C8): its
// measured position through a first-order filter with time constant `filter_time`. A filtered
// speed below `window` counts as standstill: the filtered position holds, so encoder steps and
// noise below window × filter time do not creep the slaves; it moves on once the actual
// position is that far away. Velocity and acceleration are the filtered position's differences.
struct ActualValueFilter {
  bool active = false;
  KinematicState out{};

  void begin(double from) noexcept {
    active = true;
    out = KinematicState{from, 0.0, 0.0};
  }
  void end() noexcept { active = false; }
  void step(double measured, double cycle_time, double filter_time, double window) noexcept {
    const double gain = 1.0 - std::exp(-cycle_time / filter_time);
    const double next = out.p + gain * (measured - out.p);
    double v = (next - out.p) / cycle_time;
    double p = next;
    if (std::abs(v) < window) {
      p = out.p;
      v = 0.0;
    }
    out.a = (v - out.v) / cycle_time;
    out.v = v;
    out.p = p;
  }
};

}  // namespace nc::detail
