// The extra motion of position compensation (seed 000 §2.5, SPEC B7): a 3-phase trapezoidal
// velocity profile, not jerk-limited, that adds the distance D over the time T on top of the basic
// positioning. The velocity ramps to a peak (at most VK) with the slope AK+, holds it, and ramps
// back to 0 with AK-; for D < 0 the first ramp is a deceleration and uses AK-, the last AK+
// (seed 000 §2.5 note 4). It always spans the whole time T; when D is not feasible within T, VK
// and the slopes, the largest feasible |D| (same sign) is planned and complete() is false.
//
// Pure value type; all functions are cycle functions (noexcept, no allocation).
#pragma once

#include "nc_core/profile.hpp"

namespace nc {

class Trapezoid {
 public:
  Trapezoid() = default;

  // Extra distance `distance` (either sign; 0 gives the empty profile) over `duration` T > 0 with
  // peak velocity VK > 0 and slopes AK+ (`acceleration`) and AK- (`deceleration`), all > 0.
  // Errors: kPositionNotFinite (distance), kParameterNotFinite, kCompensationLengthInvalid
  // (T <= 0), kCompensationVelocityInvalid (VK <= 0), kCompensationAccelerationInvalid.
  static Trapezoid plan(double distance, double duration, double peak_velocity, double acceleration,
                        double deceleration) noexcept;

  bool ok() const noexcept { return error_ == ErrorCode::kNone; }
  ErrorCode error() const noexcept { return error_; }

  double requested_distance() const noexcept { return requested_; }
  double distance() const noexcept { return distance_; }  // what is planned (signed)
  bool complete() const noexcept { return distance_ == requested_; }
  double duration() const noexcept { return t1_ + t2_ + t3_; }
  double peak_velocity() const noexcept { return peak_; }  // signed
  double ramp_up_time() const noexcept { return t1_; }
  double hold_time() const noexcept { return t2_; }
  double ramp_down_time() const noexcept { return t3_; }

  // The extra position, velocity and acceleration at time t since the start; before the start
  // zero, after the end (distance(), 0, 0).
  KinematicState at(double t) const noexcept;

  // Compensation stop at time t (seed 000 §2.5): from t on the velocity ramps down at once with
  // the closing slope, and D is replaced by the distance then reached. No effect once the closing
  // ramp has begun (the braking phase of the compensation) or before the start.
  Trapezoid stopped_at(double t) const noexcept;

 private:
  double peak_ = 0.0;  // signed peak velocity (first: an axis publishes it every cycle)
  double requested_ = 0.0;
  double distance_ = 0.0;
  double slope_up_ = 0.0;    // signed acceleration of the first ramp
  double slope_down_ = 0.0;  // signed acceleration of the closing ramp
  double t1_ = 0.0, t2_ = 0.0, t3_ = 0.0;
  ErrorCode error_ = ErrorCode::kNone;
};

}  // namespace nc
