#include "two_speed/two_speed_plant.hpp"

#include <cmath>
#include <limits>

namespace nc::detail {

TwoSpeedPlant::TwoSpeedPlant(const AxisConfig& config, double position)
    : rapid_velocity_(config.rapid_velocity),
      creep_velocity_(config.creep_velocity),
      ramp_rate_(config.two_speed_ramp_time > 0.0
                     ? config.rapid_velocity / config.two_speed_ramp_time
                     : std::numeric_limits<double>::infinity()),
      brake_rate_(kBrakeRampFactor * ramp_rate_),
      increment_(config.encoder_increment),
      position_(position) {}

void TwoSpeedPlant::step(const plc::NCTOIO_DRIVE_TWO_SPEED& image, double dt) noexcept {
  const plc::TwoSpeedDriveCommand command = plc::read_control_byte(image.nControlByte);
  double target = 0.0;
  if (!command.brake) {
    if (command.velocity == plc::TwoSpeedVelocity::kHigh) target = rapid_velocity_;
    if (command.velocity == plc::TwoSpeedVelocity::kLow) target = creep_velocity_;
    if (command.direction == plc::TwoSpeedDirection::kNegative) target = -target;
  }
  const double rate = command.brake ? brake_rate_ : ramp_rate_;
  const double change = target - velocity_;
  if (std::abs(change) <= rate * dt) {
    // Reaches the target speed within the cycle: ramp for t1, then hold.
    const double t1 = std::isinf(rate) ? 0.0 : std::abs(change) / rate;
    position_ += 0.5 * (velocity_ + target) * t1 + target * (dt - t1);
    velocity_ = target;
  } else {
    const double a = change > 0.0 ? rate : -rate;
    position_ += velocity_ * dt + 0.5 * a * dt * dt;
    velocity_ += a * dt;
  }
}

double TwoSpeedPlant::position() const noexcept {
  if (!(increment_ > 0.0)) return position_;
  return std::round(position_ / increment_) * increment_;
}

}  // namespace nc::detail
