// fuzz_planner (issue 16): raw doubles into plan_position / plan_velocity / plan_stop (SPEC B2).
// Invariant: the planner either refuses (ok() false with an error code) or returns a profile that
// is finite, starts at the given state, keeps V, A+ / A- (path-relative) and J — a start outside
// the limits only comes back inside them as fast as the limits allow (where the start's
// acceleration makes |v| pass V whatever is done, the unavoidable peak is the bound) — and ends
// exactly at the target (at rest, or passing it at plan_position's end velocity) or at the
// requested velocity. The checks are the planner tests' own (tests/support/profile_checks.hpp),
// with their tolerances. And plan_position takes no longer than a path through rest
// (detour_bound; P23: holds of 1e19 s at a tiny v_end kept every other check), and a velocity
// change or a stop no longer than a ramp of the start acceleration to 0 and a trapezoid.
#include <algorithm>
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

// An upper bound of the optimal time to (target, v_end, 0): a path that is not optimal but always
// reachable — the fastest change to v = 0 (plan_velocity), a move at rest to the point from which
// the change from rest to v_end ends at the target, and that change. A time-optimal profile takes
// no longer (to rounding); one that does has a detour (a hold that covers a rounding residual at
// a tiny v_end lasted 7.4e19 s instead of 0.051 s before d900542, and kept every other check).
// NaN where one of the three plans is refused (the bound is then unknown).
double detour_bound(const nc::KinematicState& s, double target, double v_end, const nc::Limits& l) {
  const nc::Profile stop = nc::plan_velocity(s, 0.0, l);
  if (!stop.ok()) return NAN;
  const nc::KinematicState rest = stop.final_state();
  double run_up = 0.0;
  double run_up_time = 0.0;
  if (v_end != 0.0) {
    const nc::Profile change = nc::plan_velocity({0.0, 0.0, 0.0}, v_end, l);
    if (!change.ok()) return NAN;
    run_up = change.final_state().p;
    run_up_time = change.duration();
  }
  const nc::Profile move = nc::plan_position({rest.p, 0.0, 0.0}, target - run_up, l);
  if (!move.ok()) return NAN;
  return stop.duration() + move.duration() + run_up_time;
}

// detour_bound with the positions' rounding (P24, P29): at 1.57e11 mm one ulp is 3e-5 mm, and
// where the path's time goes with a short distance at a small acceleration it inherits that
// ulp's share of the distance. The slowest of the paths to the target and to the doubles two
// ulps either side of it (NaN where the bound itself is NaN).
double rounded_detour_bound(const nc::KinematicState& s, double target, double v_end,
                            const nc::Limits& l) {
  const double bound = detour_bound(s, target, v_end, l);
  if (std::isnan(bound)) return bound;
  const double scale = std::max(std::fabs(s.p), std::fabs(target));
  const double ulp = std::nextafter(scale, INFINITY) - scale;
  double slowest = bound;
  for (const double shift : {-2.0 * ulp, 2.0 * ulp}) {
    const double shifted = detour_bound(s, target + shift, v_end, l);
    if (shifted > slowest) slowest = shifted;
  }
  return slowest;
}

// An upper bound of the optimal time of a velocity change from `s` to `v_goal` with a = 0: ramp
// the start acceleration to 0 at J (as fast as J allows; it passes v1 = v + a·|a| / 2J, the peak
// the limits let through), then change v1 to v_goal at `a_max`, the smaller of the accelerations
// the change may use, over a trapezoid (or a triangle, where the change is below a_max² / J). The
// planner's profile keeps the same limits and so takes no longer, to rounding. Infinite where a
// value overflows (no bound then).
double velocity_change_bound(const nc::KinematicState& s, double v_goal, double a_max, double j) {
  const double ramp = std::fabs(s.a) / j;
  const double v1 = s.v + s.a * std::fabs(s.a) / (2.0 * j);
  const double change = std::fabs(v_goal - v1);
  const double trapezoid =
      change >= a_max * a_max / j ? change / a_max + a_max / j : 2.0 * std::sqrt(change / j);
  return ramp + trapezoid;
}

// The time check of every call: slack 1e-3 of the bound and 1 µs (a fiftieth of the shortest NC
// cycle; problems at positions of 1e-108 mm take detours of 2e-8 s through their rounding, of no
// consequence). A time that hangs on a distance at a tiny acceleration inherits the positions'
// rounding (P24 in docs/reliability.md: one ulp at 1.57e11 mm was 1.9e-6 of the time). A bound
// that is NaN or infinite checks nothing.
bool above_bound(double duration, double bound) {
  return std::isfinite(bound) && duration > bound * (1.0 + 1e-3) + 1e-6;
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
  // Bit 7 with bit 0: plan_stop with the deceleration and jerk (the goal, V and A+ unused). No
  // kept input has both bits set, so every earlier input decodes as before.
  const bool stop = !position && (mode & 0x80U) != 0;
  const double v_end = passing ? next() : 0.0;
  const nc::Profile profile = passing    ? nc::plan_position(start, goal, v_end, limits)
                              : position ? nc::plan_position(start, goal, limits)
                              : stop     ? nc::plan_stop(start, limits.deceleration, limits.jerk)
                                         : nc::plan_velocity(start, goal, limits);
  const char* kind = passing    ? "plan_position (end velocity)"
                     : position ? "plan_position"
                     : stop     ? "plan_stop (A- and J used)"
                                : "plan_velocity";

  const auto check_time = [&](const nc::Profile& p, double bound, const char* path) {
    if (!above_bound(p.duration(), bound)) return;
    char what[200];
    std::snprintf(what, sizeof what, "duration %.17g s above the bound %.17g s of %s", p.duration(),
                  bound, path);
    report(kind, start, goal, v_end, limits, what);
  };

  if (!profile.ok()) {
    if (profile.error() == nc::ErrorCode::kNone)
      report(kind, start, goal, v_end, limits, "no code");
    return 0;  // a refusal is a valid answer to any input
  }
  if (stop) {
    // plan_stop takes only A- and J: those valid and a finite start; the profile is a velocity
    // change to 0 that keeps A- (for |a| both ways: a stop lets |v| grow only where an overshoot
    // through v = 0 cannot be avoided) and J, from a start outside A- as fast as J allows. It has
    // no V: the bound is the peak the start forces, |v| + a0² / 2J.
    const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
    if (!positive(limits.deceleration) || !positive(limits.jerk) || !finite_state(start))
      report(kind, start, goal, v_end, limits, "accepted invalid inputs");
    nc::Limits keep{(std::fabs(start.v) + start.a * start.a / (2.0 * limits.jerk)) * (1.0 + 1e-9),
                    limits.deceleration, limits.deceleration, limits.jerk};
    const pc::Finding finding =
        pc::check_velocity_profile(profile, start, 0.0, keep, {}, relief_for(start, keep));
    if (!finding.ok()) report(kind, start, goal, v_end, limits, pc::to_string(finding));
    check_time(profile, velocity_change_bound(start, 0.0, limits.deceleration, limits.jerk),
               "a ramp of a to 0 and a trapezoid at A-");
    return 0;
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
  // A check for detours, not for optimality (the Bellman and reference suites do that).
  if (position) {
    check_time(profile, rounded_detour_bound(start, goal, v_end, limits), "a path through rest");
  } else {
    check_time(profile,
               velocity_change_bound(
                   start, goal, std::min(limits.acceleration, limits.deceleration), limits.jerk),
               "a ramp of a to 0 and a trapezoid at min(A+, A-)");
  }
  return 0;
}
