#include "axis/drive.hpp"

#include "axis/rounding.hpp"

#include <algorithm>
#include <cmath>

namespace nc::detail {

void Drive::configure(const AxisConfig& config, double cycle_time, double position) {
  cycle_time_ = cycle_time;
  lag_ = config.drive_model == DriveModel::kFirstOrderLag && config.drive_time_constant > 0.0;
  tau_ = config.drive_time_constant;
  decay_ = lag_ ? std::exp(-cycle_time / tau_) : 0.0;
  max_velocity_ = config.drive_max_velocity;
  increment_ = config.encoder_increment;
  // The dead time is a whole number of NC cycles (axis_config.hpp: rounded).
  const double dead =
      config.drive_model == DriveModel::kFirstOrderLag ? config.drive_dead_time : 0.0;
  const auto cycles = static_cast<std::size_t>(std::llround(dead / cycle_time));
  delay_line_.assign(cycles, 0.0);
  delay_head_ = 0;
  place(position);
}

void Drive::place(double position) noexcept {
  position_ = position - offset_;
  measured_ = quantise(position_) + offset_;
  velocity_ = 0.0;
  acceleration_ = 0.0;
  std::fill(delay_line_.begin(), delay_line_.end(), 0.0);
}

void Drive::set_measured(double position) noexcept {
  offset_ = position - quantise(position_);
  measured_ = position;
}

void Drive::follow(double position, double velocity, double acceleration) noexcept {
  position_ = position - offset_;
  measured_ = position;
  velocity_ = velocity;
  acceleration_ = acceleration;
}

double Drive::quantise(double p) const noexcept {
  if (increment_ <= 0.0) return p;
  return round_exact(p / increment_) * increment_;
}

void Drive::step(double command, bool enabled) noexcept {
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
