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

}  // namespace nc::detail
