// A simulated two-speed drive (SPEC E6): what a pole-changing motor with a brake and an encoder
// does with the 12-byte image, for tests and samples. It reads only nControlByte
// (plc::read_control_byte: contradicting travel bits drive nothing).
//
// - Two motor speeds, rapid_velocity and creep_velocity, in the commanded direction; no travel
//   bit: the motor runs down to 0.
// - Speed changes ramp at rapid_velocity / two_speed_ramp_time (0 = a step).
// - The brake, while applied, stops the axis at kBrakeRampFactor times that rate, whatever the
//   travel bits say: stopping distance v² / (2 · kBrakeRampFactor · rate), 0.025 mm from 50 mm/s
//   with the defaults (500 mm/s, 0.1 s).
// - The encoder rounds the position to encoder_increment (0 = exact).
// Each cycle is integrated exactly for the image held over it, so runs are bit-for-bit repeatable.
//
// The constructor is set-up; step() and the readers are cycle functions (noexcept, no allocation).
#pragma once

#include "nc_core/axis_config.hpp"
#include "plc_interface/two_speed.hpp"

namespace nc::detail {

class TwoSpeedPlant {
 public:
  static constexpr double kBrakeRampFactor = 10.0;

  TwoSpeedPlant(const AxisConfig& config, double position);

  // One NC cycle of length dt (> 0) with `image` held.
  void step(const plc::NCTOIO_DRIVE_TWO_SPEED& image, double dt) noexcept;

  double position() const noexcept;  // the encoder's reading (actual position)
  double exact_position() const noexcept { return position_; }
  double velocity() const noexcept { return velocity_; }  // actual velocity, mm/s

 private:
  double rapid_velocity_;
  double creep_velocity_;
  double ramp_rate_;   // mm/s², +inf for a step
  double brake_rate_;  // mm/s², +inf for a step
  double increment_;
  double position_;
  double velocity_ = 0.0;
};

}  // namespace nc::detail
