#include "two_speed/two_speed_sequencer.hpp"

#include <cmath>

#include "nc_core/config.hpp"

namespace nc::detail {

namespace {

using plc::ErrorCode;
using Velocity = plc::TwoSpeedVelocity;

// Delays are sums of cycle times; the tolerance keeps 0.05 s at 1 ms exactly 50 cycles.
constexpr double kTimeTolerance = 1e-9;  // s

bool reached(double elapsed, double delay) noexcept {
  return elapsed >= delay - kTimeTolerance;
}

// More than the longest chain one cycle can complete (brake release, main travel, 22, 23, 24,
// return leg 21, 23, 24, rest).
constexpr int kMaxTransitionsPerCycle = 16;

}  // namespace

TwoSpeedParameters TwoSpeedParameters::from(const AxisConfig& c) noexcept {
  TwoSpeedParameters p;
  p.positive = {c.creep_distance_positive, c.braking_distance_positive,
                c.brake_incidence_delay_positive};
  p.negative = {c.creep_distance_negative, c.braking_distance_negative,
                c.brake_incidence_delay_negative};
  p.rapid_to_creep_delay = c.rapid_to_creep_delay;
  p.creep_distance_stop = c.creep_distance_stop;
  p.brake_release_delay = c.brake_release_delay;
  p.looping_distance = c.looping_distance_enabled ? c.looping_distance : 0.0;
  return p;
}

void TwoSpeedLeg::begin(double target, double direction, double velocity) noexcept {
  // A positive looping distance approaches every target with negative velocity, a negative one
  // with positive velocity: a target in the other direction is first passed by the distance.
  const double loop = params_.looping_distance;
  return_leg_ = loop != 0.0 && (loop > 0.0) == (direction > 0.0);
  leg_end_ = return_leg_ ? target + loop : target;
  target_ = target;
  direction_ = direction;
  velocity_ = velocity;
  stopping_ = false;
}

bool TwoSpeedLeg::turn() noexcept {
  if (!return_leg_ || stopping_) return false;
  return_leg_ = false;
  direction_ = -direction_;
  leg_end_ = target_;
  return true;
}

ErrorCode TwoSpeedLeg::set_override(uint32_t value) noexcept {
  if (value > plc::kOverrideFull) return ErrorCode::kOverrideNotAllowed;
  override_ = value;
  return ErrorCode::kNone;
}

Velocity TwoSpeedLeg::wanted_velocity() const noexcept {
  if (override_ < kOverrideStationary) return Velocity::kOff;
  if (velocity_ > kRapidVelocityThreshold && override_ > kOverrideRapidAbove) {
    return Velocity::kHigh;
  }
  return Velocity::kLow;
}

void MainTravelSpeed::drive(Velocity wanted, double delay) noexcept {
  if (wanted != Velocity::kLow) {
    velocity_ = wanted;
    switching_ = false;
    return;
  }
  // Rapid → creep always passes through the rapid-to-creep delay, also by override.
  if (velocity_ == Velocity::kHigh) {
    velocity_ = Velocity::kOff;
    switching_ = true;
    elapsed_ = 0.0;
  }
  if (switching_) {
    if (!reached(elapsed_, delay)) return;
    switching_ = false;
  }
  velocity_ = Velocity::kLow;
}

TwoSpeedSequencer::TwoSpeedSequencer(const AxisConfig& config)
    : leg_(TwoSpeedParameters::from(config)) {
  validate_two_speed(config);
  write_image();
}

plc::TwoSpeedAxisState TwoSpeedSequencer::state() const noexcept {
  using S = plc::TwoSpeedAxisState;
  switch (phase_) {
    case Phase::kRest:
      return enabled_ && started_ ? S::kStopped : S::kInactive;
    case Phase::kBrakeRelease:
    case Phase::kMainTravel:
      return S::kMainTravel;
    case Phase::kHighToLowDelay:
      return S::kHighToLowDelay;
    case Phase::kCreep:
      return S::kLowSpeedTravel;
    case Phase::kBrakeIncidence:
      return S::kBrakeIncidenceDelay;
  }
  return S::kInactive;
}

void TwoSpeedSequencer::set_enabled(bool enabled) noexcept {
  if (enabled == enabled_) return;
  enabled_ = enabled;
  if (!enabled) {
    abort();
    started_ = false;
  }
}

void TwoSpeedSequencer::abort() noexcept {
  enter(Phase::kRest);
  leg_.end();
  pending_ = TwoSpeedEvent::kNone;
}

ErrorCode TwoSpeedSequencer::start(double target, double velocity,
                                   double actual_position) noexcept {
  if (!enabled_) return ErrorCode::kControllerEnableMissing;
  if (busy()) return ErrorCode::kFunctionNotAllowed;
  if (!std::isfinite(target)) return ErrorCode::kPositionNotFinite;
  if (!std::isfinite(velocity)) return ErrorCode::kParameterNotFinite;
  if (!(velocity > 0.0)) return ErrorCode::kVelocityNotPositive;  // seed 004: v <= 0 is an error
  if (!std::isfinite(actual_position)) return ErrorCode::kActualValueNotFinite;
  const double distance = target - actual_position;
  const double direction = distance > 0.0 ? 1.0 : -1.0;
  const TwoSpeedParameters& params = leg_.params();
  const auto& side = direction > 0.0 ? params.positive : params.negative;
  // Seed 004: a start only when the distance is larger than the braking distance.
  if (!(std::abs(distance) > side.braking_distance)) {
    return ErrorCode::kTwoSpeedDistanceTooShort;
  }
  leg_.begin(target, direction, velocity);
  started_ = true;
  pending_ = TwoSpeedEvent::kNone;
  enter(Phase::kBrakeRelease);
  fresh_ = true;
  return ErrorCode::kNone;
}

ErrorCode TwoSpeedSequencer::stop(double actual_position) noexcept {
  if (!enabled_) return ErrorCode::kControllerEnableMissing;
  if (phase_ == Phase::kRest) {
    pending_ = TwoSpeedEvent::kStopped;
    return ErrorCode::kNone;
  }
  if (leg_.stopping()) return ErrorCode::kNone;
  // Nothing travels yet, or no position to count the creep from: brake at once.
  if (phase_ == Phase::kBrakeRelease || !std::isfinite(actual_position)) {
    abort();
    pending_ = TwoSpeedEvent::kStopped;
    return ErrorCode::kNone;
  }
  leg_.stop_from(actual_position);
  if (phase_ == Phase::kMainTravel) {
    const bool rapid = main_speed_.rapid();
    const bool creep = main_speed_.velocity() == Velocity::kLow;
    // A stationary axis (override 0) has nothing to creep: it brakes.
    enter(rapid ? Phase::kHighToLowDelay : creep ? Phase::kCreep : Phase::kBrakeIncidence);
    fresh_ = true;
  }
  // In a braking phase the stop only brings the creep end closer (creep_off_reached).
  return ErrorCode::kNone;
}

TwoSpeedCycle TwoSpeedSequencer::step(double actual_position, double dt) noexcept {
  TwoSpeedCycle out;
  if (phase_ == Phase::kRest) {
    out.event = pending_;
    pending_ = TwoSpeedEvent::kNone;
  } else if (!std::isfinite(actual_position)) {
    abort();
    out.event = TwoSpeedEvent::kError;
    out.error = ErrorCode::kActualValueNotFinite;
  } else {
    if (fresh_) {
      fresh_ = false;
    } else {
      elapsed_ += dt;
      main_speed_.tick(dt);
    }
    out = advance(actual_position);
  }
  write_image();
  out.state = state();
  return out;
}

void TwoSpeedSequencer::enter(Phase phase) noexcept {
  phase_ = phase;
  elapsed_ = 0.0;
  fresh_ = false;
  main_speed_.reset();
}

TwoSpeedCycle TwoSpeedSequencer::advance(double p) noexcept {
  TwoSpeedCycle out;
  for (int i = 0; i < kMaxTransitionsPerCycle; ++i) {
    switch (phase_) {
      case Phase::kRest:
        return out;
      case Phase::kBrakeRelease:
        if (!reached(elapsed_, leg_.params().brake_release_delay)) return out;
        enter(Phase::kMainTravel);
        break;
      case Phase::kMainTravel: {
        if (leg_.creep_off_reached(p)) {
          enter(Phase::kBrakeIncidence);
          break;
        }
        if (leg_.remaining(p) <= leg_.side().creep_distance) {
          // Only a rapid that was on needs the rapid-to-creep delay before the creep.
          enter(main_speed_.rapid() ? Phase::kHighToLowDelay : Phase::kCreep);
          break;
        }
        main_speed_.drive(leg_.wanted_velocity(), leg_.params().rapid_to_creep_delay);
        return out;
      }
      case Phase::kHighToLowDelay:
        if (leg_.creep_off_reached(p)) {
          enter(Phase::kBrakeIncidence);
          break;
        }
        if (!reached(elapsed_, leg_.params().rapid_to_creep_delay)) return out;
        enter(Phase::kCreep);
        break;
      case Phase::kCreep:
        if (!leg_.creep_off_reached(p)) return out;
        enter(Phase::kBrakeIncidence);
        break;
      case Phase::kBrakeIncidence:
        if (!reached(elapsed_, leg_.side().brake_incidence_delay)) return out;
        if (leg_.turn()) {
          // Looping: the reversal point is reached; the return leg approaches the target from
          // the required side without braking in between.
          if (!(leg_.remaining(p) > leg_.side().braking_distance)) {
            abort();
            out.event = TwoSpeedEvent::kError;
            out.error = ErrorCode::kTwoSpeedDistanceTooShort;
            return out;
          }
          enter(Phase::kMainTravel);
          break;
        }
        out.event = leg_.stopping() ? TwoSpeedEvent::kStopped : TwoSpeedEvent::kDone;
        abort();  // brake on, at rest
        return out;
    }
  }
  return out;
}

void TwoSpeedSequencer::write_image() noexcept {
  plc::TwoSpeedDriveCommand command;
  command.direction = leg_.direction() > 0.0 ? plc::TwoSpeedDirection::kPositive
                                             : plc::TwoSpeedDirection::kNegative;
  command.brake = phase_ == Phase::kRest;
  if (phase_ == Phase::kMainTravel) command.velocity = main_speed_.velocity();
  if (phase_ == Phase::kCreep) command.velocity = Velocity::kLow;
  plc::write_control_bytes(image_, command);
}

}  // namespace nc::detail
