// Parts of the two-speed sequencer (two_speed_sequencer.hpp): the geometry of the running
// positioning (TwoSpeedLeg: target, leg end, direction, start velocity and override, a stop's
// creep end) and the speed of the main travel phase (MainTravelSpeed: rapid, creep, and the
// rapid-to-creep delay between them). SPEC E1-E5, seed 004.
//
// Cycle functions only: noexcept, no allocation.
#pragma once

#include <cstdint>

#include "nc_core/axis_config.hpp"
#include "plc_interface/axis_ref.hpp"
#include "plc_interface/error_code.hpp"
#include "plc_interface/two_speed.hpp"

namespace nc::detail {

// The sequencer's view of AxisConfig: one side per direction of travel.
struct TwoSpeedParameters {
  struct Side {
    double creep_distance = 0.0;
    double braking_distance = 0.0;
    double brake_incidence_delay = 0.0;
  };
  Side positive;
  Side negative;
  double rapid_to_creep_delay = 0.0;
  double creep_distance_stop = 0.0;
  double brake_release_delay = 0.0;
  double looping_distance = 0.0;  // 0 when looping is off

  static TwoSpeedParameters from(const AxisConfig& config) noexcept;
};

class TwoSpeedLeg {
 public:
  // Start velocity above this is rapid, (0, this] creep (seed 004 "Velocity and override").
  static constexpr double kRapidVelocityThreshold = 50.0;
  // Override above this is rapid; below kOverrideStationary (0.01 %) the axis stands.
  static constexpr uint32_t kOverrideRapidAbove = plc::kOverrideFull / 2;
  static constexpr uint32_t kOverrideStationary = plc::kOverrideFull / 10'000;

  explicit TwoSpeedLeg(const TwoSpeedParameters& params) noexcept : params_(params) {}
  const TwoSpeedParameters& params() const noexcept { return params_; }

  // A positioning to `target` moving `direction` (+1 / -1) at start velocity `velocity`: a
  // looping first leg to target + looping distance when the target lies on the looping side.
  void begin(double target, double direction, double velocity) noexcept;
  // A stop: creep off once the actual position passes `actual_position` + creep_distance_stop.
  void stop_from(double actual_position) noexcept {
    stopping_ = true;
    stop_end_ = actual_position + direction_ * params_.creep_distance_stop;
  }
  // The positioning or stop has ended: no stop and no return leg pending.
  void end() noexcept {
    stopping_ = false;
    return_leg_ = false;
  }
  // Looping: a return leg follows this one; it is now the running leg (reversed, to the target).
  bool turn() noexcept;

  // PlcToNc.Override, 0 … 1'000'000; above 100 %: 0x4238, the last valid value stays.
  plc::ErrorCode set_override(uint32_t value) noexcept;
  bool stopping() const noexcept { return stopping_; }
  double target() const noexcept { return target_; }
  double direction() const noexcept { return direction_; }
  // The distances and delay of this leg's direction of travel.
  const TwoSpeedParameters::Side& side() const noexcept {
    return direction_ > 0.0 ? params_.positive : params_.negative;
  }
  // Distance to the leg's end along its direction from the actual position p.
  double remaining(double p) const noexcept { return (leg_end_ - p) * direction_; }
  // Creep off: within the braking distance of the leg's end, or past a stop's creep end.
  bool creep_off_reached(double p) const noexcept {
    return remaining(p) <= side().braking_distance ||
           (stopping_ && (stop_end_ - p) * direction_ <= 0.0);
  }
  // The main travel speed the start velocity and the override ask for.
  plc::TwoSpeedVelocity wanted_velocity() const noexcept;

 private:
  TwoSpeedParameters params_;
  double target_ = 0.0;
  double leg_end_ = 0.0;     // target, or the reversal point of a looping first leg
  double direction_ = 1.0;   // +1 / -1 on this leg
  bool return_leg_ = false;  // a looping return leg follows this leg
  double velocity_ = 0.0;
  uint32_t override_ = plc::kOverrideFull;
  bool stopping_ = false;
  double stop_end_ = 0.0;  // stop: creep off when the actual position passes it
};

// The speed commanded in the main travel phase: rapid → creep always passes through the
// rapid-to-creep delay (rapid off, then creep), also when the override asks for it.
class MainTravelSpeed {
 public:
  void reset() noexcept {
    velocity_ = plc::TwoSpeedVelocity::kOff;
    switching_ = false;
    elapsed_ = 0.0;
  }
  // The time of a cycle that was not the phase's first.
  void tick(double dt) noexcept {
    if (switching_) elapsed_ += dt;
  }
  // Takes the `wanted` speed; rapid → creep waits `delay` s with both off.
  void drive(plc::TwoSpeedVelocity wanted, double delay) noexcept;
  plc::TwoSpeedVelocity velocity() const noexcept { return velocity_; }
  // Rapid is on, or switched off and the creep not yet on.
  bool rapid() const noexcept { return velocity_ == plc::TwoSpeedVelocity::kHigh || switching_; }

 private:
  plc::TwoSpeedVelocity velocity_ = plc::TwoSpeedVelocity::kOff;
  bool switching_ = false;  // rapid off, waiting to creep
  double elapsed_ = 0.0;    // s since the rapid went off
};

}  // namespace nc::detail
