// Position compensation's trapezoid (seed 000 §2.5). With ramp slopes r1 (opening) and r2
// (closing), k = 1/r1 + 1/r2, a peak vp over the time T gives D(vp) = vp T - k vp^2 / 2, rising up
// to the triangle vp = T / k. So the largest feasible |D| is D(min(VK, T / k)), and a feasible D
// has the smaller root vp = 2|D| / (T + sqrt(T^2 - 2k|D|)) (no cancellation).
#include "nc_core/trapezoid.hpp"

#include <algorithm>
#include <cmath>

namespace nc {

Trapezoid Trapezoid::plan(double distance, double duration, double peak_velocity,
                          double acceleration, double deceleration) noexcept {
  Trapezoid z;
  if (!std::isfinite(distance)) {
    z.error_ = ErrorCode::kPositionNotFinite;
  } else if (!std::isfinite(duration) || !std::isfinite(peak_velocity) ||
             !std::isfinite(acceleration) || !std::isfinite(deceleration)) {
    z.error_ = ErrorCode::kParameterNotFinite;
  } else if (!(duration > 0.0)) {
    z.error_ = ErrorCode::kCompensationLengthInvalid;
  } else if (!(peak_velocity > 0.0)) {
    z.error_ = ErrorCode::kCompensationVelocityInvalid;
  } else if (!(acceleration > 0.0) || !(deceleration > 0.0)) {
    z.error_ = ErrorCode::kCompensationAccelerationInvalid;
  }
  if (!z.ok()) return z;
  z.requested_ = distance;
  if (distance == 0.0) return z;

  const double sign = distance > 0.0 ? 1.0 : -1.0;
  // D > 0 opens with an acceleration increase (AK+), D < 0 with a deceleration increase (AK-).
  const double r1 = sign > 0.0 ? acceleration : deceleration;
  const double r2 = sign > 0.0 ? deceleration : acceleration;
  const double k = 1.0 / r1 + 1.0 / r2;
  const double vp_max = std::min(peak_velocity, duration / k);
  const double d_max = vp_max * (duration - 0.5 * k * vp_max);
  const double want = std::abs(distance);
  double vp;
  if (want < d_max) {
    vp = 2.0 * want / (duration + std::sqrt(std::max(duration * duration - 2.0 * k * want, 0.0)));
    z.distance_ = distance;
  } else {
    vp = vp_max;
    z.distance_ = want == d_max ? distance : sign * d_max;
  }
  z.peak_ = sign * vp;
  z.slope_up_ = sign * r1;
  z.slope_down_ = -sign * r2;
  z.t1_ = vp / r1;
  z.t3_ = vp / r2;
  z.t2_ = std::max(duration - z.t1_ - z.t3_, 0.0);
  return z;
}

KinematicState Trapezoid::at(double t) const noexcept {
  if (!(t > 0.0) || !ok()) return KinematicState{};
  if (t < t1_) return KinematicState{0.5 * slope_up_ * t * t, slope_up_ * t, slope_up_};
  const double p1 = 0.5 * peak_ * t1_;
  if (t < t1_ + t2_) return KinematicState{p1 + peak_ * (t - t1_), peak_, 0.0};
  const double left = t1_ + t2_ + t3_ - t;
  if (left > 0.0) {
    // Back from the end, so the end is exactly distance().
    return KinematicState{distance_ + 0.5 * slope_down_ * left * left, -slope_down_ * left,
                          slope_down_};
  }
  return KinematicState{distance_, 0.0, 0.0};
}

Trapezoid Trapezoid::stopped_at(double t) const noexcept {
  if (!ok() || !(t > 0.0) || t >= t1_ + t2_) return *this;
  Trapezoid z = *this;
  if (t < t1_) {
    z.t1_ = t;
    z.t2_ = 0.0;
    z.peak_ = slope_up_ * t;
  } else {
    z.t2_ = t - t1_;
  }
  z.t3_ = -z.peak_ / slope_down_;
  z.distance_ = 0.5 * z.peak_ * z.t1_ + z.peak_ * z.t2_ + 0.5 * z.peak_ * z.t3_;
  return z;
}

}  // namespace nc
