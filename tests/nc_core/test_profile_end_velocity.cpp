// plan_position to a target passed at a velocity (issue 14 item 1): named cases, the identity
// with the three-argument call at v_end = 0, and refusals. Every profile is checked in full
// (profile_checks.hpp: continuity, limits, exact end state, at()); the random, Bellman and
// reference suites cover the rest.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "nc_core/profile.hpp"
#include "profile_checks.hpp"
#include "profile_problems.hpp"

namespace {

using nc::ErrorCode;
using nc::KinematicState;
using nc::Limits;
using nc::Profile;

// Seed 000 §2.1's Dynamics I limits: V 1000 mm/s here, A± 5000 mm/s², J 50000 mm/s³.
const Limits kLimits{1000.0, 5000.0, 5000.0, 50000.0};

Profile checked(const KinematicState& start, double target, double v_end,
                const Limits& l = kLimits) {
  const Profile prof = nc::plan_position(start, target, v_end, l);
  const profile_checks::Finding f =
      profile_checks::check_passing_profile(prof, start, target, v_end, l);
  INFO(profile_checks::to_string(f));
  CHECK(f.ok());
  CHECK(prof.final_state().p == target);
  CHECK(prof.final_state().v == v_end);
  CHECK(prof.final_state().a == 0.0);
  return prof;
}

// Smallest and largest position on the profile (sampled every 1 ms and at the segment starts).
std::pair<double, double> position_range(const Profile& prof) {
  double lo = prof.start_state().p;
  double hi = lo;
  for (double t = 0.0; t <= prof.duration(); t += 1e-3) {
    lo = std::min(lo, prof.at(t).p);
    hi = std::max(hi, prof.at(t).p);
  }
  return {lo, hi};
}

}  // namespace

TEST_CASE("passing a target at +V from rest: accelerate to V, cruise, arrive at V",
          "[profile][end_velocity]") {
  // 0 -> V takes V/A + A/J = 0.3 s over 150 mm; the other 850 mm at V take 0.85 s.
  const Profile prof = checked({0.0, 0.0, 0.0}, 1000.0, 1000.0);
  CHECK(prof.duration() == Approx(1.15).epsilon(1e-12));
  CHECK(prof.at(0.3).v == Approx(1000.0).epsilon(1e-12));
  CHECK(prof.holds_velocity());
  // Past the end the motion goes on at V.
  CHECK(prof.at(prof.duration() + 0.5).p == Approx(1500.0).epsilon(1e-12));
  // The same to -V, mirrored.
  CHECK(checked({0.0, 0.0, 0.0}, -1000.0, -1000.0).duration() == Approx(1.15).epsilon(1e-12));
}

TEST_CASE("passing a target at a velocity away from the start goes past it and turns",
          "[profile][end_velocity]") {
  // Target 100 mm ahead, to be passed at -500 mm/s: the motion must overshoot it and come back.
  const Profile prof = checked({0.0, 0.0, 0.0}, 100.0, -500.0);
  const auto range = position_range(prof);
  CHECK(range.second > 100.0);
  CHECK(range.first >= 0.0);
  // Re-planning from halfway gives the rest.
  const double t = 0.5 * prof.duration();
  CHECK(nc::plan_position(prof.at(t), 100.0, -500.0, kLimits).duration() ==
        Approx(prof.duration() - t).epsilon(1e-9));
}

TEST_CASE("a target behind the point the direct change ends needs a run-up backwards",
          "[profile][end_velocity]") {
  // At rest on the target, to pass it at +300 mm/s: back away first, then run up through it.
  const Profile from_rest = checked({0.0, 0.0, 0.0}, 0.0, 300.0);
  CHECK(position_range(from_rest).first < 0.0);
  // Already at the target with v != v_end: moving at 200 mm/s (it must come back), and at
  // -200 mm/s to pass at +500 (it must turn and run up).
  const Profile moving = checked({0.0, 200.0, 0.0}, 0.0, 500.0);
  CHECK(position_range(moving).second > 0.0);
  CHECK(position_range(moving).first < 0.0);
  const Profile reversing = checked({0.0, -200.0, 0.0}, 0.0, 500.0);
  CHECK(position_range(reversing).first < 0.0);
  // Already at the target at v_end: nothing to do.
  const Profile there = checked({0.0, 300.0, 0.0}, 0.0, 300.0);
  CHECK(there.duration() == 0.0);
}

TEST_CASE("passing at v_end = ±V from a moving start far from 0", "[profile][end_velocity]") {
  checked({1e5, 400.0, 2000.0}, 1e5 + 50.0, 1000.0);
  checked({1e5, 400.0, 2000.0}, 1e5 + 50.0, -1000.0);
  checked({-1e5, -1000.0, 0.0}, -1e5 - 3.0, 1000.0);
  checked({-1e5, -1000.0, 0.0}, -1e5 - 3000.0, -1000.0);
}

TEST_CASE("v_end = 0 is the three-argument call, bit for bit", "[profile][end_velocity]") {
  profile_problems::Rng rng(0x1DE27ull);
  long differ = 0;
  for (int k = 0; k < 20000; ++k) {
    const profile_problems::Problem pr = profile_problems::random_position_problem(rng, 0.5);
    const Profile a = nc::plan_position(pr.start, pr.target, pr.limits);
    const Profile b = nc::plan_position(pr.start, pr.target, 0.0, pr.limits);
    bool same = a.ok() == b.ok() && a.duration() == b.duration() &&
                a.segment_count() == b.segment_count() && !b.holds_velocity();
    for (std::size_t i = 0; same && i < a.segment_count(); ++i) {
      const nc::Segment& x = a.segment(i);
      const nc::Segment& y = b.segment(i);
      same = x.t0 == y.t0 && x.duration == y.duration && x.p == y.p && x.v == y.v && x.a == y.a &&
             x.j == y.j;
    }
    if (!same) ++differ;
  }
  CHECK(differ == 0);
}

TEST_CASE("end velocities beyond V or not finite are refused with a code",
          "[profile][end_velocity]") {
  const KinematicState s{0.0, 0.0, 0.0};
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(nc::plan_position(s, 100.0, 1000.0 * (1.0 + 1e-12), kLimits).error() ==
        ErrorCode::kVelocityNotAllowed);
  CHECK(nc::plan_position(s, 100.0, -1001.0, kLimits).error() == ErrorCode::kVelocityNotAllowed);
  CHECK(nc::plan_position(s, 100.0, nan, kLimits).error() == ErrorCode::kParameterNotFinite);
  CHECK(nc::plan_position(s, 100.0, inf, kLimits).error() == ErrorCode::kParameterNotFinite);
  CHECK(nc::plan_position(s, 100.0, -inf, kLimits).error() == ErrorCode::kParameterNotFinite);
  // The other inputs keep their codes.
  CHECK(nc::plan_position(s, nan, 10.0, kLimits).error() == ErrorCode::kPositionNotFinite);
  CHECK(nc::plan_position({nan, 0.0, 0.0}, 1.0, 10.0, kLimits).error() ==
        ErrorCode::kStateNotFinite);
  CHECK(nc::plan_position(s, 1.0, 10.0, {0.0, 1.0, 1.0, 1.0}).error() ==
        ErrorCode::kVelocityNotPositive);
  CHECK(nc::plan_position(s, 1.0, 10.0, {1.0, 1.0, 1.0, -1.0}).error() ==
        ErrorCode::kJerkNotAllowed);
  // A refused plan is a failure profile, never a NaN.
  const Profile bad = nc::plan_position(s, 100.0, 2000.0, kLimits);
  CHECK_FALSE(bad.ok());
  CHECK(std::isfinite(bad.duration()));
}
