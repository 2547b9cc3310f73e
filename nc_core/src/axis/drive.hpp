// The simulated drive and encoder of a continuous servo axis (SPEC A3).
//
// The drive receives a velocity command once per NC cycle and holds it for the cycle. Models:
// - ideal: the drive's velocity equals its (delayed, saturated) input;
// - first-order lag: v' = (u - v) / tau, integrated exactly over the cycle for a constant input,
//   so the result does not depend on the step size beyond the hold itself.
// Both take the dead time (whole NC cycles, a ring buffer reserved at set-up) and the optional
// velocity saturation (drive_max_velocity). The encoder quantises the true position to whole
// increments (round to nearest).
//
// configure() is a set-up function (allocates the dead-time line); the rest are cycle
// functions.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "axis/rounding.hpp"
#include "nc_core/axis_config.hpp"

namespace nc::detail {

class Drive {
 public:
  // Set-up: reserves the dead-time line; `position` is where the axis stands.
  void configure(const AxisConfig& config, double cycle_time, double position);

  // Cycle function: apply `command` (mm/s) for one cycle; `enabled` false = drive off (its input
  // is 0; a lagging drive runs down with its own time constant).
  void step(double command, bool enabled) noexcept;

  // Sets the true position (and the measured one) without motion: used to place an axis.
  void place(double position) noexcept;
  // Position setting (MC_Home): the measured position shows `position` from now on; the drive
  // does not move. Later positions are the raw encoder's plus the same offset.
  void set_measured(double position) noexcept;
  // The encoder's own position (no position setting applied, not quantised): where its zero
  // pulses lie.
  double raw_position() const noexcept { return position_; }
  double offset() const noexcept { return offset_; }
  // Encoder / virtual axis: the actual values are given (no quantisation, no dynamics).
  void follow(double position, double velocity, double acceleration) noexcept;

  double true_position() const noexcept { return position_ + offset_; }
  double measured_position() const noexcept { return measured_; }
  double velocity() const noexcept { return velocity_; }
  double acceleration() const noexcept { return acceleration_; }
  // The dead-time line's slot the next step() reads and writes (the line's end without a dead
  // time): the kernel's loop asks for its cache line ahead (servo_axis.hpp).
  const double* next_slot() const noexcept { return delay_line_.data() + delay_head_; }

 private:
  double quantise(double p) const noexcept;

  bool lag_ = false;
  double cycle_time_ = 0.001;
  double tau_ = 0.0;
  double decay_ = 0.0;  // exp(-T / tau)
  double max_velocity_ = 0.0;
  double increment_ = 0.0;
  std::vector<double> delay_line_;
  std::size_t delay_head_ = 0;

  double position_ = 0.0;  // raw
  double offset_ = 0.0;    // displayed − raw (position setting)
  double measured_ = 0.0;
  double velocity_ = 0.0;
  double acceleration_ = 0.0;
};

// Inline: the drive phase runs them for every axis in every cycle.
inline double Drive::quantise(double p) const noexcept {
  if (increment_ <= 0.0) return p;
  return round_exact(p / increment_) * increment_;
}

inline void Drive::step(double command, bool enabled) noexcept {
  double input = enabled ? command : 0.0;
  if (!delay_line_.empty()) {
    const double delayed = delay_line_[delay_head_];
    delay_line_[delay_head_] = input;
    delay_head_ = delay_head_ + 1 == delay_line_.size() ? 0 : delay_head_ + 1;
    input = delayed;
  }
  if (max_velocity_ > 0.0) input = std::clamp(input, -max_velocity_, max_velocity_);

  const double before = velocity_;
  if (lag_) {
    // Exact solution of v' = (u - v)/tau over one cycle with u held constant.
    const double gap = before - input;
    position_ += input * cycle_time_ + gap * tau_ * (1.0 - decay_);
    velocity_ = input + gap * decay_;
  } else {
    position_ += input * cycle_time_;
    velocity_ = input;
  }
  acceleration_ = (velocity_ - before) / cycle_time_;
  measured_ = offset_ == 0.0 ? quantise(position_) : quantise(position_) + offset_;
}

}  // namespace nc::detail
