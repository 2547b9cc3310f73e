// Position compensation of one axis (seed 000 §2.5, SPEC B7); see compensation.hpp.
#include "axis/compensation.hpp"

#include <algorithm>
#include <cmath>

#include "profile/validate.hpp"

namespace nc::detail {

namespace {
// As in MasterJob: a sample time this close below the duration counts as the end.
constexpr double kEndTolerance = 1e-9;  // s, relative to max(1 s, T)
// |D| - |done| above this (relative to max(1, |D|)) counts as "less than D" (warning 0x4243).
constexpr double kIncompleteTolerance = 1e-9;
}  // namespace

ErrorCode check_compensation(double distance, double length, double process_velocity,
                             double velocity_diff, double acceleration,
                             double deceleration) noexcept {
  if (!std::isfinite(distance)) return ErrorCode::kPositionNotFinite;
  if (!std::isfinite(length) || !std::isfinite(process_velocity) || !std::isfinite(velocity_diff) ||
      !std::isfinite(acceleration) || !std::isfinite(deceleration)) {
    return ErrorCode::kParameterNotFinite;
  }
  // Besides > 0: within the planner's numeric range [1e-9, 1e12] (profile/validate.hpp; fuzz
  // finding K3: denormal values passed "> 0" and the trapezoid was not finite).
  const auto in_range = [](double x) { return x >= kMinLimit && x <= kMaxLimit; };
  if (!in_range(std::abs(distance))) return ErrorCode::kCompensationParametersInvalid;
  if (!in_range(length)) return ErrorCode::kCompensationLengthInvalid;
  if (!in_range(velocity_diff) || !in_range(process_velocity)) {
    return ErrorCode::kCompensationVelocityInvalid;
  }
  if (!in_range(acceleration) || !in_range(deceleration)) {
    return ErrorCode::kCompensationAccelerationInvalid;
  }
  return ErrorCode::kNone;
}

ErrorCode Compensation::start(uint16_t number, double distance, double length,
                              double process_velocity, double velocity_diff, double acceleration,
                              double deceleration, double direction, double speed,
                              double cycle_time) noexcept {
  // "In any case, the parameters are chosen in such a way that compensation occurs over the
  // whole compensation length" (seed 000 §2.5): T = L / VP, the largest feasible D within it.
  const Trapezoid trapezoid = Trapezoid::plan(distance, length / process_velocity, velocity_diff,
                                              acceleration, deceleration);
  if (!trapezoid.ok()) return trapezoid.error();
  // The last line of defence: a trapezoid whose numbers are not finite is never run.
  if (!std::isfinite(trapezoid.duration() + trapezoid.distance() + trapezoid.peak_velocity())) {
    return ErrorCode::kCompensationParametersInvalid;
  }
  trapezoid_ = trapezoid;
  state_ = KinematicState{};
  requested_ = distance;
  direction_ = direction < 0.0 ? -1.0 : 1.0;
  length_ = length;
  process_velocity_ = process_velocity;
  lost_ = 0.0;
  previous_scale_ = std::min(1.0, speed / process_velocity);
  previous_p_ = 0.0;
  k_ = 0;
  cycle_time_ = cycle_time;
  number_ = number;
  running_ = true;
  stop_requested_ = false;
  time_over_ = false;
  return ErrorCode::kNone;
}

KinematicState Compensation::advance(double base_velocity, double base_acceleration,
                                     double cycle_time) noexcept {
  if (!running_) return KinematicState{};
  cycle_time_ = cycle_time;
  ++k_;
  const double t = static_cast<double>(k_) * cycle_time;
  const double end = trapezoid_.duration();
  time_over_ = t >= end - kEndTolerance * std::max(1.0, end);
  const KinematicState z =
      time_over_ ? KinematicState{trapezoid_.distance(), 0.0, 0.0} : trapezoid_.at(t);

  // SPEC B7: scale s = min(1, |v| / VP); the cycle's increment counts with the mean s of the
  // cycle. With s = 1 at both ends nothing is lost, so the offset stays exactly z.p.
  const double speed = std::abs(base_velocity);
  const bool slow = speed < process_velocity_;
  const double scale = slow ? speed / process_velocity_ : 1.0;
  const double mean_scale = 0.5 * (scale + previous_scale_);
  lost_ += (1.0 - mean_scale) * (z.p - previous_p_);
  previous_p_ = z.p;
  previous_scale_ = scale;
  // d|v|/dt, for the acceleration of the scaled extra velocity.
  double speed_rate = 0.0;
  if (slow) {
    speed_rate = (base_velocity < 0.0 ? -base_acceleration : base_acceleration) / process_velocity_;
    if (base_velocity == 0.0) speed_rate = std::abs(base_acceleration) / process_velocity_;
  }
  state_ = KinematicState{direction_ * (z.p - lost_), direction_ * z.v * scale,
                          direction_ * (z.a * scale + z.v * speed_rate)};
  return state_;
}

ErrorCode Compensation::request_stop() noexcept {
  if (!running_) return ErrorCode::kCompensationNotActive;
  if (k_ == 0) {
    // Stopped in the cycle it was accepted: nothing has moved yet, nothing will.
    trapezoid_ = Trapezoid::plan(0.0, 1.0, 1.0, 1.0, 1.0);
    stop_requested_ = true;
    return ErrorCode::kNone;
  }
  const double t = static_cast<double>(k_) * cycle_time_;
  if (time_over_ || t >= trapezoid_.ramp_up_time() + trapezoid_.hold_time()) {
    return ErrorCode::kCompensationStopNotAllowed;  // the braking phase of the compensation
  }
  trapezoid_ = trapezoid_.stopped_at(t);
  stop_requested_ = true;
  return ErrorCode::kNone;
}

double Compensation::finish() noexcept {
  running_ = false;
  state_.v = 0.0;
  state_.a = 0.0;
  return state_.p;
}

bool Compensation::incomplete() const noexcept {
  const double want = std::abs(requested_);
  return want - direction_ * state_.p * (requested_ < 0.0 ? -1.0 : 1.0) >
         kIncompleteTolerance * std::max(1.0, want);
}

}  // namespace nc::detail
