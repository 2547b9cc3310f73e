// Input checks shared by the plan functions (internal): every bad input gets its own code.
#pragma once

#include <cmath>

#include "nc_core/profile.hpp"

namespace nc::detail {

inline ErrorCode check_state(const KinematicState& s) noexcept {
  if (!std::isfinite(s.p) || !std::isfinite(s.v) || !std::isfinite(s.a)) {
    return ErrorCode::kStateNotFinite;
  }
  return ErrorCode::kNone;
}

inline ErrorCode check_positive(double value, ErrorCode not_positive) noexcept {
  if (!std::isfinite(value)) return ErrorCode::kParameterNotFinite;
  if (!(value > 0.0)) return not_positive;
  return ErrorCode::kNone;
}

inline ErrorCode check_limits(const Limits& l) noexcept {
  ErrorCode e = check_positive(l.velocity, ErrorCode::kVelocityNotPositive);
  if (e == ErrorCode::kNone) e = check_positive(l.acceleration, ErrorCode::kAccelerationNotAllowed);
  if (e == ErrorCode::kNone) e = check_positive(l.deceleration, ErrorCode::kDecelerationNotAllowed);
  if (e == ErrorCode::kNone) e = check_positive(l.jerk, ErrorCode::kJerkNotAllowed);
  return e;
}

// The last line of defence against overflow with extreme (finite) inputs: a profile whose
// numbers are not all finite is never handed out. x * 0 is 0 for a finite x and NaN otherwise,
// so one sum replaces a test per value.
inline bool profile_finite(const Profile& profile) noexcept {
  const KinematicState f = profile.final_state();
  double zero = profile.duration() * 0.0 + f.p * 0.0 + f.v * 0.0 + f.a * 0.0;
  for (std::size_t i = 0; i < profile.segment_count(); ++i) {
    const Segment& s = profile.segment(i);
    zero += (s.p * 0.0 + s.v * 0.0) + (s.a * 0.0 + s.duration * 0.0);
  }
  return zero == 0.0;
}

}  // namespace nc::detail
