// The axis monitors of SPEC A4: following error, target position window, position range
// window, software limit switches.
//
// Times become whole NC cycles once, at set-up:
// - following error: an error when |lag| > limit has been seen in more consecutive cycles than
//   fit in the filter time (count · T > filter time);
// - target window: InTargetPosition once |p_act - target| <= window has held, after the end of
//   set-value generation, for count · T >= window time (0 → at the first cycle in the window);
// - position range: InPositionArea while |p_act - target| <= window after the end of set-value
//   generation (TwinCAT checks both windows only once the positioning phase has ended).
// A disabled window reports "in" as soon as the generation has ended, so "done" never waits on
// a monitor that is switched off.
//
// configure() is set-up; the rest are cycle functions.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "nc_core/axis_config.hpp"
#include "plc_interface/axis_ref.hpp"

namespace nc::detail {

class Monitors {
 public:
  void configure(const AxisConfig& config, double cycle_time) noexcept;

  // Following error: true in the cycle the error must be raised. `armed` false (drive off, axis
  // already in error) resets the filter.
  bool following_error(double lag, bool armed) noexcept;
  // following_error(lag, true) when it is false without counting (the filter starts again, as
  // there); false, with nothing changed, when it would count: the steady lane (steady_lane.hpp)
  // then runs the full monitors.
  bool lag_within(double lag) noexcept {
    if (fe_enabled_ && std::abs(lag) > fe_limit_) return false;
    fe_count_ = 0;
    return true;
  }

  // Target and range windows. `settled` = the set-value generation of a positioning (or stop)
  // has ended; false resets the target-window timer.
  void windows(double actual, double target, bool settled) noexcept;
  void reset_windows() noexcept;
  bool in_target_position() const noexcept { return (window_bits_ & kInTarget) != 0; }
  bool in_position_area() const noexcept { return (window_bits_ & kInArea) != 0; }
  // The two as StateDWord has them (InPositionArea, InTargetPosition; the other bits 0): the
  // steady cycle's publish ors them in at once.
  uint32_t window_state_bits() const noexcept { return window_bits_; }

  // Software limits on a position (true: beyond an enabled limit). They count only while the
  // axis is referenced (homed): an axis that has not homed does not know where its limits are.
  // (One comparison each: the bounds in force are ±inf while a limit does not count.)
  bool below_min(double p) const noexcept { return p < low_; }
  bool above_max(double p) const noexcept { return p > high_; }
  // The same, at or beyond (a continuous start standing on the limit; p is finite).
  bool at_or_below_min(double p) const noexcept { return p <= low_; }
  bool at_or_above_max(double p) const noexcept { return p >= high_; }
  // Every position in [lo, hi] is within the limits in force (no test of them can fire).
  bool limits_clear(double lo, double hi) const noexcept { return low_ <= lo && hi <= high_; }
  void set_referenced(bool referenced) noexcept {
    referenced_ = referenced;
    set_bounds();
  }

 private:
  // The flags together: an axis's hot members are packed (docs/performance.md "Kernel cycle").
  static constexpr uint8_t kInArea = 1U << plc::kStateInPositionArea;
  static constexpr uint8_t kInTarget = 1U << plc::kStateInTargetPosition;

  bool fe_enabled_ = true;
  bool tw_enabled_ = true;
  bool pr_enabled_ = true;
  uint8_t window_bits_ = 0;  // kInArea, kInTarget
  bool referenced_ = true;
  bool min_enabled_ = false;
  bool max_enabled_ = false;

  double fe_limit_ = 5.0;
  uint64_t fe_filter_cycles_ = 0;
  uint64_t fe_count_ = 0;

  double tw_window_ = 2.0;
  uint64_t tw_cycles_ = 1;
  uint64_t tw_count_ = 0;

  double pr_window_ = 5.0;

  double min_ = 0.0;
  double max_ = 0.0;
  // The software limits in force: min_ / max_ while enabled and referenced, else -inf / +inf.
  double low_ = -std::numeric_limits<double>::infinity();
  double high_ = std::numeric_limits<double>::infinity();

  void set_bounds() noexcept {
    low_ = referenced_ && min_enabled_ ? min_ : -std::numeric_limits<double>::infinity();
    high_ = referenced_ && max_enabled_ ? max_ : std::numeric_limits<double>::infinity();
  }
};

// Cycle functions, inline: the monitor phase calls them for every axis in every cycle.
inline bool Monitors::following_error(double lag, bool armed) noexcept {
  if (!fe_enabled_ || !armed || !(std::abs(lag) > fe_limit_)) {
    fe_count_ = 0;
    return false;
  }
  ++fe_count_;
  return fe_count_ > fe_filter_cycles_;
}

inline void Monitors::windows(double actual, double target, bool settled) noexcept {
  if (!settled) {
    reset_windows();
    return;
  }
  const double distance = std::abs(actual - target);
  const bool in_area = !pr_enabled_ || distance <= pr_window_;
  bool in_target = true;
  if (tw_enabled_) {
    if (distance <= tw_window_) {
      if (tw_count_ < tw_cycles_) ++tw_count_;
    } else {
      tw_count_ = 0;
    }
    in_target = tw_count_ >= tw_cycles_;
  }
  window_bits_ = static_cast<uint8_t>((in_area ? kInArea : 0U) | (in_target ? kInTarget : 0U));
}

inline void Monitors::reset_windows() noexcept {
  tw_count_ = 0;
  window_bits_ = 0;
}

}  // namespace nc::detail
