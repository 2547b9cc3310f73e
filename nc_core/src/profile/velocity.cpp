// plan_velocity and plan_stop: one velocity change (profile/velocity_change.hpp) each.
#include <cmath>

#include "nc_core/profile.hpp"
#include "profile/profile_writer.hpp"
#include "profile/validate.hpp"
#include "profile/velocity_walk.hpp"

namespace nc {
namespace {

Profile build_change(const KinematicState& start, double v1, const detail::Bounds& bounds,
                     bool holds) noexcept {
  // One returned object (no copy of the profile on return).
  Profile profile = detail::ProfileWriter::begin();
  detail::ProfileWriter writer(profile, start);
  detail::walk::WriterSink sink{writer};
  if (detail::walk::change(start.v, start.a, v1, bounds, sink) < 0) {
    detail::ProfileWriter::fail(profile, ErrorCode::kPlannerNoSolution);
    return profile;
  }
  const KinematicState end{writer.end_state().p, v1, 0.0};
  writer.close(&end, holds);
  // Integrated forward, each segment's p takes the previous one's t, p, v, a and j: the end's p
  // and the total duration stand for a test of every segment's values (no profile with a number
  // that is not finite is handed out; issue 17: it was a loop over them).
  if (!std::isfinite(end.p + profile.duration()))
    detail::ProfileWriter::fail(profile, ErrorCode::kPlannerNoSolution);
  return profile;
}

}  // namespace

// Both flattened (issue 17): the checks, the walk and the profile writer in one body, where the
// writer's running state stays in registers (the walk through velocity_change's entry kept it in
// memory across the call).
[[gnu::flatten]] Profile plan_velocity(const KinematicState& start, double velocity,
                                       const Limits& limits) noexcept {
  // (check_plan's target check passes for 0: the checks of the state, the limits and the start.)
  // The common case in one test (issue 17): with the limits in range, |velocity| <= V bounds it
  // by kMaxMagnitude and fails for NaN and infinity.
  if (!(detail::plain_inputs(start, 0.0, limits) && std::abs(velocity) <= limits.velocity &&
        detail::zero_or_not_tiny(velocity))) {
    ErrorCode e = detail::check_plan(start, 0.0, limits);
    if (e == ErrorCode::kNone && !std::isfinite(velocity)) e = ErrorCode::kParameterNotFinite;
    if (e == ErrorCode::kNone &&
        (std::abs(velocity) > limits.velocity || !detail::velocity_in_range(velocity))) {
      e = ErrorCode::kVelocityNotAllowed;
    }
    if (e != ErrorCode::kNone) return Profile::failure(e);
  }
  return build_change(start, velocity, {limits.acceleration, limits.deceleration, limits.jerk},
                      true);
}

[[gnu::flatten]] Profile plan_stop(const KinematicState& start, double deceleration,
                                   double jerk) noexcept {
  ErrorCode e = detail::check_state(start);
  if (e == ErrorCode::kNone) {
    e = detail::check_positive(deceleration, ErrorCode::kDecelerationNotAllowed);
  }
  if (e == ErrorCode::kNone) e = detail::check_positive(jerk, ErrorCode::kJerkNotAllowed);
  if (e != ErrorCode::kNone) return Profile::failure(e);
  // A stop only lets |v| grow where an overshoot through v = 0 cannot be avoided; the
  // deceleration bounds |a| there as well.
  return build_change(start, 0.0, {deceleration, deceleration, jerk}, false);
}

}  // namespace nc
