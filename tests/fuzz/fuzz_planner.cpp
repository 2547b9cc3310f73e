// fuzz_planner (issue 16): raw doubles into plan_position / plan_velocity (SPEC B2). Invariant:
// the planner either refuses (ok() false with an error code) or returns a profile that is finite,
// starts at the given state, keeps V, A+ / A- (path-relative) and J — a start outside the limits
// only comes back inside them as fast as the limits allow (where the start's acceleration makes
// |v| pass V whatever is done, the unavoidable peak is the bound) — and ends exactly at the target
// (at rest, or passing it at plan_position's end velocity) or at the requested velocity. The checks
// are the planner tests' own (tests/support/profile_checks.hpp), with their tolerances.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "byte_reader.hpp"
#include "fail.hpp"
#include "nc_core/profile.hpp"
#include "profile_checks.hpp"

namespace {

namespace pc = profile_checks;

bool valid_limits(const nc::Limits& l) {
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  return positive(l.velocity) && positive(l.acceleration) && positive(l.deceleration) &&
         positive(l.jerk);
}

bool finite_state(const nc::KinematicState& s) {
  return std::isfinite(s.p) && std::isfinite(s.v) && std::isfinite(s.a);
}

// The limits a profile from `s` can keep (profile.hpp: a start outside the limits comes back
// inside them as fast as the limits allow). Ramping a start acceleration a0 to 0 at J passes the
// velocity v0 + a0·|a0| / (2 J) whatever the planner does: when that lies beyond V, V cannot be
// kept and that peak is the bound instead.
nc::Limits keepable_limits(const nc::KinematicState& s, const nc::Limits& l) {
  nc::Limits k = l;
  const double unavoidable = std::fabs(s.v + s.a * std::fabs(s.a) / (2.0 * l.jerk));
  if (unavoidable > l.velocity) k.velocity = unavoidable * (1.0 + 1e-9);
  return k;
}

// Relief for a start outside the limits, as the planner's own suites give it.
pc::StartRelief relief_for(const nc::KinematicState& s, const nc::Limits& l) {
  pc::StartRelief r;
  r.over_speed = std::fabs(s.v) > l.velocity;
  r.over_acceleration = std::fabs(s.a) > std::min(l.acceleration, l.deceleration);
  return r;
}

[[noreturn]] void report(const char* kind, const nc::KinematicState& s, double target, double v_end,
                         const nc::Limits& l, const std::string& what) {
  std::fprintf(stderr, "%s\n%s\n", pc::describe_passing_problem(kind, s, target, v_end, l).c_str(),
               what.c_str());
  fuzz::fail("planner profile breaks its contract");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  fuzz::ByteReader in(data, size);
  const uint8_t mode = in.byte();
  // Either every value raw (any bit pattern) or drawn by class (specials and plausible values).
  const bool raw = (mode & 0x02U) != 0;
  const auto next = [&] { return raw ? in.raw_double() : in.number(); };
  nc::KinematicState start;
  start.p = next();
  start.v = next();
  start.a = next();
  const double goal = next();  // target position, or target velocity
  nc::Limits limits;
  limits.velocity = next();
  limits.acceleration = next();
  limits.deceleration = next();
  limits.jerk = next();

  const bool position = (mode & 0x01U) == 0;
  // Bit 7: plan_position's four-argument call, its end velocity read after the limits (issue 14;
  // inputs without bit 7 decode as before).
  const bool passing = position && (mode & 0x80U) != 0;
  const double v_end = passing ? next() : 0.0;
  const nc::Profile profile = passing    ? nc::plan_position(start, goal, v_end, limits)
                              : position ? nc::plan_position(start, goal, limits)
                                         : nc::plan_velocity(start, goal, limits);
  const char* kind = passing    ? "plan_position (end velocity)"
                     : position ? "plan_position"
                                : "plan_velocity";

  if (!profile.ok()) {
    if (profile.error() == nc::ErrorCode::kNone)
      report(kind, start, goal, v_end, limits, "no code");
    return 0;  // a refusal is a valid answer to any input
  }
  // Accepted: the inputs must have been valid …
  if (!valid_limits(limits) || !finite_state(start) || !std::isfinite(goal) ||
      !std::isfinite(v_end) || std::fabs(v_end) > limits.velocity) {
    report(kind, start, goal, v_end, limits, "accepted invalid inputs");
  }
  // … and the profile keeps its contract.
  const nc::Limits keep = keepable_limits(start, limits);
  const pc::StartRelief relief = relief_for(start, keep);
  const pc::Finding finding =
      position ? pc::check_passing_profile(profile, start, goal, v_end, keep, {}, relief)
               : pc::check_velocity_profile(profile, start, goal, keep, {}, relief);
  if (!finding.ok()) report(kind, start, goal, v_end, limits, pc::to_string(finding));
  return 0;
}
