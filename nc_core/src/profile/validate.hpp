// Input checks shared by the plan functions (internal): every bad input gets its own code.
#pragma once

#include <algorithm>
#include <cmath>

#include "nc_core/profile.hpp"
#include "profile/velocity_change.hpp"

namespace nc::detail {

// The numeric range the planner works in (docs/behaviour.md, "Profile"). Every limit (V, A+, A-,
// J, a stop's deceleration and jerk) lies in [kMinLimit, kMaxLimit] and every |p|, |v|, |a| of
// the start and |target| is at most kMaxMagnitude. Outside, the closed forms (A²/J, V²/A, …)
// overflow or underflow and a double no longer resolves the 1e-9 relative end state the planner
// promises. The planner suites span V 1e-2…1e5, A 1e-1…1e7, J 1…1e9, distances 1e-6…1e5: both
// ends stay at least 1e6 away from them. A start velocity or acceleration (and plan_velocity's
// target velocity) is 0 or at least kMinMagnitude in size: subnormal values (fuzz: v = 4.9e-324,
// a = 1.4e-322) lose their precision in the planner's products and quotients.
inline constexpr double kMinLimit = 1e-9;
inline constexpr double kMaxLimit = 1e12;
inline constexpr double kMaxMagnitude = 1e12;
inline constexpr double kMinMagnitude = 1e-100;

inline bool within_magnitude(double value) noexcept {
  return std::abs(value) <= kMaxMagnitude;
}

// 0, or |value| in [kMinMagnitude, kMaxMagnitude].
inline bool velocity_in_range(double value) noexcept {
  return value == 0.0 || (std::abs(value) >= kMinMagnitude && within_magnitude(value));
}

// NaN / inf: kStateNotFinite; |p| beyond kMaxMagnitude, or v, a neither 0 nor within
// [kMinMagnitude, kMaxMagnitude]: the code of that quantity.
inline ErrorCode check_state(const KinematicState& s) noexcept {
  if (!std::isfinite(s.p) || !std::isfinite(s.v) || !std::isfinite(s.a)) {
    return ErrorCode::kStateNotFinite;
  }
  if (!within_magnitude(s.p)) return ErrorCode::kTargetPositionNotAllowed;
  if (!velocity_in_range(s.v)) return ErrorCode::kVelocityNotAllowed;
  if (!velocity_in_range(s.a)) return ErrorCode::kAccelerationNotAllowed;
  return ErrorCode::kNone;
}

// NaN / inf: kParameterNotFinite; <= 0 or outside [kMinLimit, kMaxLimit]: `not_allowed`.
inline ErrorCode check_positive(double value, ErrorCode not_allowed) noexcept {
  if (!std::isfinite(value)) return ErrorCode::kParameterNotFinite;
  if (!(value >= kMinLimit && value <= kMaxLimit)) return not_allowed;
  return ErrorCode::kNone;
}

inline ErrorCode check_limits(const Limits& l) noexcept {
  ErrorCode e = check_positive(l.velocity, l.velocity > 0.0 ? ErrorCode::kVelocityNotAllowed
                                                            : ErrorCode::kVelocityNotPositive);
  if (e == ErrorCode::kNone) e = check_positive(l.acceleration, ErrorCode::kAccelerationNotAllowed);
  if (e == ErrorCode::kNone) e = check_positive(l.deceleration, ErrorCode::kDecelerationNotAllowed);
  if (e == ErrorCode::kNone) e = check_positive(l.jerk, ErrorCode::kJerkNotAllowed);
  return e;
}

// How far outside its limits a start may lie (fuzz finding P2): |a| at most kMaxStartRatio times
// max(A+, A-), and |v| as well as the velocity the start's acceleration forces whatever is done,
// |v + a·|a| / 2J|, at most kMaxStartRatio times V. Beyond, bringing the start back takes
// kMaxStartRatio times the problem's own times and kMaxStartRatio² its distances (a = 1e17·A
// broke continuity at t = 3.6e33 s), and the state brought back keeps the rounding of the start's
// size: a few ulp of |a0| is ratio · 2.2e-16 of A, above the planner's 1e-9 from a ratio of about
// 4e6 (fuzz finding P8: a = 1e8·A ended its ramp 1e-8 above A+). The kernel's farthest start
// from an override alone (1 ppm at full speed) is 1e6; the outside-the-limits suites use <= 3.
inline constexpr double kMaxStartRatio = 2e6;
// The braking distance from the start, speed² / 2A- with that speed, at most kMaxStopDistance
// (fuzz finding P4: v = 1.6e6 against A- = 7e-9 must travel 1.9e26 to stop, and the profile broke
// continuity by 1e29). 1000 times the position range; the planner suites stay below 5e11.
inline constexpr double kMaxStopDistance = 1e15;

// The bound at which a start acceleration brought back at J (the planner's first ramp, and the
// envelope |a0| - J·t a start outside the limits is allowed) can end. Mirrored so that a0 > 0:
// with v0 >= 0 |v| grows, A+. With v0 < 0 the ramp crosses v = 0 at a = sqrt(a0² + 2J·v0) when
// that is real; a crossing above A+ goes on to A+ beyond it (fuzz finding P9: a = 0.695 crossed
// at 0.052 and ended its ramp at A+ = 7.3e-9; the same from within A- = 0.79, and from above a
// smaller A- that the ramp passed without holding). Otherwise a ramp from above A- ends at A-
// when it meets A- before v = 0 (a0² + 2J·v0 below A-²); a crossing within A+ ends it at v = 0,
// not at a bound (the larger bound is returned). A crossing above A+ by less than half the walk's
// rounding tolerance (kDecisionTolerance of a0², velocity_change.hpp) counts as within: the walk
// lands such a start on A+ exactly at v = 0.
inline double ramp_end_bound(const KinematicState& s, const Limits& l) noexcept {
  const double a0 = std::abs(s.a);
  const double v0 = s.a < 0.0 ? -s.v : s.v;
  const double ap = l.acceleration;
  const double am = l.deceleration;
  if (v0 >= 0.0) return ap;
  const double k = a0 * a0 + 2.0 * l.jerk * v0;
  const double k_tol = 0.5 * kDecisionTolerance * (ap * ap + a0 * a0 - 2.0 * l.jerk * v0);
  if (k - ap * ap > k_tol) return ap;
  if (a0 > am && k < am * am) return am;
  return std::max(ap, am);
}

// check_start_against's common case (issue 17): |a| within min(A+, A-), |v| within V, a^2 within
// J V (the forced velocity within 1.5 V) and V^2 within kMaxStopDistance A- / 4 pass every one of
// its tests, with a margin far above their rounding.
inline bool start_plainly_inside(const KinematicState& s, const Limits& l) noexcept {
  return std::abs(s.a) <= std::min(l.acceleration, l.deceleration) && std::abs(s.v) <= l.velocity &&
         s.a * s.a <= l.jerk * l.velocity &&
         l.velocity * l.velocity <= (0.25 * kMaxStopDistance) * l.deceleration;
}

// A start too far outside `l` (both already in range), or too fast to stop within
// kMaxStopDistance: kStartFarOutsideLimits. The acceleration counts against the bound where its
// ramp ends (ramp_end_bound): the profile's a there keeps a few ulp of |a0|, which must stay
// within the planner's 1e-9 of that bound (P8, P9).
inline ErrorCode check_start_against(const KinematicState& s, const Limits& l) noexcept {
  if (start_plainly_inside(s, l)) return ErrorCode::kNone;
  const double forced = std::abs(s.v + s.a * std::abs(s.a) / (2.0 * l.jerk));
  const double speed = std::max(std::abs(s.v), forced);
  if (!(std::abs(s.a) <= kMaxStartRatio * ramp_end_bound(s, l)) ||
      !(speed <= kMaxStartRatio * l.velocity) ||
      !(speed * speed <= 2.0 * l.deceleration * kMaxStopDistance)) {
    return ErrorCode::kStartFarOutsideLimits;
  }
  return ErrorCode::kNone;
}

// plan_position's end velocity (fuzz finding P16): the distance a change of v_end needs at the
// smaller acceleration bound, v_end² / 2·min(A+, A-), at most kMaxStopDistance, as the start's
// braking distance (P4). Beyond, the profile's excursions leave the range where a double keeps
// its continuity (v_end = 8.6e9 with A- = 3.6e-9: 1e28 mm; continuity broke by 517 mm at 8386 s).
// Refused as a velocity not allowed (0x4221), the code of |v_end| > V.
inline ErrorCode check_end_velocity(double v_end, const Limits& l) noexcept {
  const double bound = std::min(l.acceleration, l.deceleration);
  if (!(v_end * v_end <= 2.0 * bound * kMaxStopDistance)) {
    return ErrorCode::kVelocityNotAllowed;
  }
  return ErrorCode::kNone;
}

// A target position: NaN / inf kPositionNotFinite, beyond kMaxMagnitude kTargetPositionNotAllowed.
inline ErrorCode check_target(double target) noexcept {
  if (!std::isfinite(target)) return ErrorCode::kPositionNotFinite;
  if (!within_magnitude(target)) return ErrorCode::kTargetPositionNotAllowed;
  return ErrorCode::kNone;
}

// 0, or |x| at least kMinMagnitude (NaN fails): velocity_in_range where |x| <= kMaxMagnitude is
// known otherwise.
inline bool zero_or_not_tiny(double x) noexcept {
  return std::abs(x) >= kMinMagnitude || x == 0.0;
}

// The common case of check_plan (issue 17): every limit within [kMinLimit, kMaxLimit], |s.p| and
// |target| within kMaxMagnitude, v and a 0 or not below kMinMagnitude, and the start plainly
// inside its limits (start_plainly_inside: |v| <= V and |a| <= min(A+, A-) bound v and a by
// kMaxLimit = kMaxMagnitude as well, and fail for NaN). Then check_state, check_target,
// check_limits and check_start_against all give kNone; false says nothing.
inline bool plain_inputs(const KinematicState& s, double target, const Limits& l) noexcept {
  auto limit = [](double x) { return x >= kMinLimit && x <= kMaxLimit; };
  return limit(l.velocity) && limit(l.acceleration) && limit(l.deceleration) && limit(l.jerk) &&
         std::abs(s.p) <= kMaxMagnitude && std::abs(target) <= kMaxMagnitude &&
         zero_or_not_tiny(s.v) && zero_or_not_tiny(s.a) && start_plainly_inside(s, l);
}

// check_state(s), check_target(target), check_limits(l) and check_start_against(s, l), in this
// order: the first code found. Inputs plainly inside their ranges (plain_inputs, the common case)
// pass all four in one test.
inline ErrorCode check_plan(const KinematicState& s, double target, const Limits& l) noexcept {
  if (plain_inputs(s, target, l)) return ErrorCode::kNone;
  ErrorCode e = check_state(s);
  if (e == ErrorCode::kNone) e = check_target(target);
  if (e == ErrorCode::kNone) e = check_limits(l);
  if (e == ErrorCode::kNone) e = check_start_against(s, l);
  return e;
}

}  // namespace nc::detail
