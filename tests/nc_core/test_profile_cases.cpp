// Named planner scenarios of issue 3 with numbers worked out by hand from the elementary ramps
// (seed 000 §2.1: a velocity change dv between two states at a = 0 takes dv/A + A/J when
// dv ≥ A²/J, else 2·sqrt(dv/J), and covers (v_from + v_to)/2 times that). Unless a case says
// otherwise: V 2000 mm/s, A+ = A- = 5000 mm/s², J 50000 mm/s³ (Dynamics 1.1), so A²/J = 500 mm/s.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <limits>

#include "nc_core/profile.hpp"
#include "profile_checks.hpp"
#include "reference_planner.hpp"

namespace {

using nc::ErrorCode;
using nc::KinematicState;
using nc::Limits;
using nc::Profile;
using profile_checks::Finding;

const Limits kLimits{2000.0, 5000.0, 5000.0, 50000.0};

// Velocity sign changes over the whole profile, exactly per segment: v at each segment start and
// at each extremum of v (where a crosses 0); values within eps of 0 do not count as a sign.
int velocity_reversals(const Profile& prof, double eps) {
  int changes = 0;
  double last = 0.0;
  auto visit = [&](double v) {
    if (std::fabs(v) <= eps) return;
    if (last != 0.0 && (v > 0.0) != (last > 0.0)) ++changes;
    last = v;
  };
  for (std::size_t i = 0; i < prof.segment_count(); ++i) {
    const nc::Segment& s = prof.segment(i);
    visit(s.v);
    if (s.j != 0.0) {
      const double tau = -s.a / s.j;
      if (tau > 0.0 && tau < s.duration) visit(profile_checks::advance(s, tau).v);
    }
  }
  visit(prof.final_state().v);
  return changes;
}

// Largest and smallest v of a profile, exactly (segment ends and extrema).
struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
};

Range velocity_range(const Profile& prof, double t_from = 0.0, double t_to = 1e300) {
  Range r;
  auto take = [&](double t, double v) {
    if (t < t_from || t > t_to) return;
    r.lo = std::min(r.lo, v);
    r.hi = std::max(r.hi, v);
  };
  for (std::size_t i = 0; i < prof.segment_count(); ++i) {
    const nc::Segment& s = prof.segment(i);
    take(s.t0, s.v);
    take(s.t0 + s.duration, profile_checks::advance(s, s.duration).v);
    if (s.j != 0.0) {
      const double tau = -s.a / s.j;
      if (tau > 0.0 && tau < s.duration) take(s.t0 + tau, profile_checks::advance(s, tau).v);
    }
  }
  return r;
}

void require_valid(const Profile& prof, const KinematicState& start, double target, const Limits& l,
                   const profile_checks::StartRelief& relief = {}) {
  REQUIRE(prof.ok());
  const Finding f = profile_checks::check_position_profile(prof, start, target, l, {}, relief);
  INFO(profile_checks::to_string(f));
  CHECK(f.ok());
  CHECK(prof.final_state().p == target);
  CHECK(prof.final_state().v == 0.0);
  CHECK(prof.final_state().a == 0.0);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Short moves: V not reached.

TEST_CASE("a short move peaks at the largest reachable velocity, trapezoidal acceleration",
          "[profile][cases]") {
  // 200 mm: vp·(vp/5000 + 0.1) = 200 → vp = 780.776406404415 ≥ 500, T = 2·(vp/5000 + 0.1).
  for (double sign : {1.0, -1.0}) {
    const KinematicState start{-50.0, 0.0, 0.0};
    const double target = -50.0 + sign * 200.0;
    const Profile prof = nc::plan_position(start, target, kLimits);
    require_valid(prof, start, target, kLimits);
    CHECK(prof.duration() == Approx(0.512310562561766).epsilon(1e-9));
    const Range r = velocity_range(prof);
    CHECK(std::max(std::fabs(r.lo), std::fabs(r.hi)) == Approx(780.776406404415).epsilon(1e-9));
    CHECK(velocity_reversals(prof, 1e-9 * kLimits.velocity) == 0);
  }
}

TEST_CASE("a very short move peaks at the largest reachable velocity, triangular acceleration",
          "[profile][cases]") {
  // 10 mm: A is not reached either; 10 = 2·vp·sqrt(vp/J) → vp = 107.72173450159416,
  // T = 4·sqrt(vp/J) = 4·(10/(2J))^(1/3) = 0.18566355334451112 s; the peak acceleration
  // sqrt(vp·J) = 2320.8 stays below A.
  for (double sign : {1.0, -1.0}) {
    const KinematicState start{0.0, 0.0, 0.0};
    const Profile prof = nc::plan_position(start, sign * 10.0, kLimits);
    require_valid(prof, start, sign * 10.0, kLimits);
    CHECK(prof.duration() == Approx(0.18566355334451112).epsilon(1e-9));
    const Range r = velocity_range(prof);
    CHECK(std::max(std::fabs(r.lo), std::fabs(r.hi)) == Approx(107.72173450159416).epsilon(1e-9));
    CHECK(std::fabs(prof.at(prof.duration() / 4.0).a) ==
          Approx(std::sqrt(107.72173450159416 * 50000.0)).epsilon(1e-9));
  }
}

TEST_CASE("an asymmetric short move uses A+ and A- each and beats the vendor's min(A+, A-) rule",
          "[profile][cases]") {
  // A+ 5000, A- 10000, 300 mm. Ours (SPEC B2): up with A+ (trapezoid), down with A- (triangle,
  // vp < A-²/J = 2000): vp = 1018.4505772947045, T = 0.58913020756861 s. The seed's symmetric
  // rule (A± = min = 5000) needs vp = 1000, T = 0.6 s.
  const Limits l{2000.0, 5000.0, 10000.0, 50000.0};
  for (double sign : {1.0, -1.0}) {
    const KinematicState start{1000.0, 0.0, 0.0};
    const double target = 1000.0 + sign * 300.0;
    const Profile prof = nc::plan_position(start, target, l);
    require_valid(prof, start, target, l);
    CHECK(prof.duration() == Approx(0.58913020756861).epsilon(1e-9));
    CHECK(prof.duration() < 0.6);
    const Range r = velocity_range(prof);
    CHECK(std::max(std::fabs(r.lo), std::fabs(r.hi)) == Approx(1018.4505772947045).epsilon(1e-9));
  }
}

// ---------------------------------------------------------------------------------------------
// Moving starts.

TEST_CASE("moving toward the target: up from v0 to V, cruise, stop; no reversal",
          "[profile][cases]") {
  // (v0 = 1000) → V: dv 1000 ≥ 500: 0.3 s over 450 mm; stop from 2000: 0.5 s over 500 mm;
  // cruise 50 mm: 0.025 s. T = 0.825 s.
  for (double sign : {1.0, -1.0}) {
    const KinematicState start{0.0, sign * 1000.0, 0.0};
    const Profile prof = nc::plan_position(start, sign * 1000.0, kLimits);
    require_valid(prof, start, sign * 1000.0, kLimits);
    CHECK(prof.duration() == Approx(0.825).epsilon(1e-9));
    CHECK(velocity_reversals(prof, 1e-9 * kLimits.velocity) == 0);
    CHECK(prof.at(0.3).v == Approx(sign * 2000.0).epsilon(1e-9));
    CHECK(prof.at(0.3).p == Approx(sign * 450.0).epsilon(1e-9));
  }
}

TEST_CASE("moving away from the target: one continuous ramp through v = 0 towards it",
          "[profile][cases]") {
  // (v0 = -1000) → +2000: dv 3000: 0.7 s over (-1000 + 2000)/2·0.7 = 350 mm, with a = A all the
  // way through v = 0 (A+ = A-); stop 500 mm; cruise 150 mm: 0.075 s. T = 1.275 s.
  for (double sign : {1.0, -1.0}) {
    const KinematicState start{0.0, -sign * 1000.0, 0.0};
    const Profile prof = nc::plan_position(start, sign * 1000.0, kLimits);
    require_valid(prof, start, sign * 1000.0, kLimits);
    CHECK(prof.duration() == Approx(1.275).epsilon(1e-9));
    CHECK(velocity_reversals(prof, 1e-9 * kLimits.velocity) == 1);
    // v passes 0 at t = 0.1 + (1000 - 250)/5000 = 0.25 s with a = A.
    CHECK(prof.at(0.25).v == Approx(0.0).margin(1e-9 * 2000.0));
    CHECK(prof.at(0.25).a == Approx(sign * 5000.0).epsilon(1e-9));
  }
}

TEST_CASE("a target the axis cannot stop before: one continuous profile reversing through v = 0",
          "[profile][cases]") {
  // From v = 2000 the shortest stop needs 500 mm; the target is 100 mm ahead. Brake at -A through
  // v = 0 (at t = 0.45 s, p = 200 - 8.333 + 1750²/10000 = 497.91666666666663 mm) on to -vp,
  // then stop at the target: (2000 - vp)/2·t(2000 + vp) - vp/2·t(vp) = 100 gives
  // vp = 1186.140661634507 and T = t(2000 + vp) + t(vp) = 1.074456264653803 s.
  for (double sign : {1.0, -1.0}) {
    for (double p0 : {0.0, 54321.0}) {
      const KinematicState start{p0, sign * 2000.0, 0.0};
      const double target = p0 + sign * 100.0;
      const Profile prof = nc::plan_position(start, target, kLimits);
      require_valid(prof, start, target, kLimits);
      CHECK(prof.duration() == Approx(1.074456264653803).epsilon(1e-9));
      CHECK(velocity_reversals(prof, 1e-9 * kLimits.velocity) == 1);
      const KinematicState turn = prof.at(0.45);
      CHECK(turn.v == Approx(0.0).margin(1e-9 * 2000.0));
      CHECK(turn.a == Approx(-sign * 5000.0).epsilon(1e-9));
      CHECK(turn.p - p0 == Approx(sign * 497.91666666666663).epsilon(1e-9));
      const Range r = velocity_range(prof);
      CHECK(sign * (sign > 0 ? r.lo : r.hi) == Approx(-1186.140661634507).epsilon(1e-9));
    }
  }
}

TEST_CASE("a start acceleration at the limit is held, then ramped down to arrive exactly at V",
          "[profile][cases]") {
  // (500, 5000): hold A until 1750 (0.25 s), ramp down 0.1 s to V = 2000 after 472.91666 mm,
  // cruise 27.08333 mm, stop 500 mm: T = 0.35 + 0.0135416666 + 0.5 = 0.8635416666666667 s.
  for (double sign : {1.0, -1.0}) {
    const KinematicState start{0.0, sign * 500.0, sign * 5000.0};
    const Profile prof = nc::plan_position(start, sign * 1000.0, kLimits);
    require_valid(prof, start, sign * 1000.0, kLimits);
    CHECK(prof.duration() == Approx(0.8635416666666667).epsilon(1e-9));
    CHECK(prof.at(0.25).a == Approx(sign * 5000.0).epsilon(1e-9));
    CHECK(prof.at(0.25).v == Approx(sign * 1750.0).epsilon(1e-9));
    CHECK(prof.at(0.35).v == Approx(sign * 2000.0).epsilon(1e-9));
    CHECK(prof.at(0.35).a == Approx(0.0).margin(1e-9 * 5000.0));
  }
}

TEST_CASE("a start acceleration inside the limit ramps up to the limit first", "[profile][cases]") {
  // (500, 2500): ramp up 0.05 s (v 687.5), hold to 1750, ramp down to V after 479.8177083 mm,
  // cruise, stop: T = 0.3625 + 0.0100911458 + 0.5 = 0.8725911458333334 s.
  for (double sign : {1.0, -1.0}) {
    const KinematicState start{0.0, sign * 500.0, sign * 2500.0};
    const Profile prof = nc::plan_position(start, sign * 1000.0, kLimits);
    require_valid(prof, start, sign * 1000.0, kLimits);
    CHECK(prof.duration() == Approx(0.8725911458333334).epsilon(1e-9));
    CHECK(prof.jerk_at(0.025) == sign * 50000.0);
    CHECK(prof.at(0.05).a == Approx(sign * 5000.0).epsilon(1e-9));
    CHECK(prof.at(0.05).v == Approx(sign * 687.5).epsilon(1e-9));
  }
}

// ---------------------------------------------------------------------------------------------
// Start states outside the limits.

TEST_CASE("above V the velocity comes down to V as fast as A- allows and never undershoots it",
          "[profile][cases]") {
  // v0 = 3000 > V = 2000 (a lower override): ramp 1000 down in 0.2 + 0.1 = 0.3 s over 750 mm,
  // hold V, stop over the last 500 mm. Target 10000: cruise 8750 mm = 4.375 s, T = 5.175 s.
  profile_checks::StartRelief relief;
  relief.over_speed = true;
  for (double sign : {1.0, -1.0}) {
    const KinematicState start{0.0, sign * 3000.0, 0.0};
    const Profile prof = nc::plan_position(start, sign * 10000.0, kLimits);
    require_valid(prof, start, sign * 10000.0, kLimits, relief);
    CHECK(prof.duration() == Approx(5.175).epsilon(1e-9));
    CHECK(prof.at(0.3).v == Approx(sign * 2000.0).epsilon(1e-9));
    CHECK(prof.at(0.3).a == Approx(0.0).margin(1e-9 * 5000.0));
    CHECK(prof.at(0.3).p == Approx(sign * 750.0).epsilon(1e-9));
    // No undershoot: until the final stop begins (T - 0.5 s), |v| never drops below V.
    const Range before_stop = velocity_range(prof, 0.0, prof.duration() - 0.5);
    const double slowest = sign > 0 ? before_stop.lo : -before_stop.hi;
    CHECK(slowest >= 2000.0 * (1.0 - 1e-9));
    // And v only ever decreases in magnitude: |v| is never above v0.
    const double fastest = sign > 0 ? before_stop.hi : -before_stop.lo;
    CHECK(fastest <= 3000.0 * (1.0 + 1e-12));
  }
}

TEST_CASE("above V with the target too close: down to V, no undershoot, one reversal",
          "[profile][cases]") {
  // From 3000 mm/s the shortest stop takes 1050 mm; a target 800 mm ahead forces a reversal.
  profile_checks::StartRelief relief;
  relief.over_speed = true;
  const KinematicState start{0.0, 3000.0, 0.0};
  const Profile prof = nc::plan_position(start, 800.0, kLimits);
  require_valid(prof, start, 800.0, kLimits, relief);
  CHECK(velocity_reversals(prof, 1e-9 * kLimits.velocity) == 1);
  // Full braking from the start: a reaches -A- after 0.1 s (v 2750) and stays there through V
  // (at 0.1 + 750/5000 = 0.25 s, sooner than the 0.3 s of the far target, where a must come
  // back to 0 at V) and through v = 0 at 0.1 + 2750/5000 = 0.65 s.
  CHECK(prof.jerk_at(0.05) == -50000.0);
  CHECK(prof.at(0.25).v == Approx(2000.0).epsilon(1e-9));
  CHECK(prof.at(0.25).a == Approx(-5000.0).epsilon(1e-9));
  CHECK(prof.at(0.65).v == Approx(0.0).margin(1e-9 * 2000.0));
}

TEST_CASE("an acceleration above A+ decreases at exactly J until it is inside",
          "[profile][cases]") {
  // (v 1000, a 8000) with A+ = 5000: a must fall at -J for (8000 - 5000)/J = 0.06 s; after it
  // v = 1390 and the ramp to V continues within the limits.
  profile_checks::StartRelief relief;
  relief.over_acceleration = true;
  for (double sign : {1.0, -1.0}) {
    const KinematicState start{0.0, sign * 1000.0, sign * 8000.0};
    const Profile prof = nc::plan_position(start, sign * 10000.0, kLimits);
    require_valid(prof, start, sign * 10000.0, kLimits, relief);
    for (double t : {1e-6, 0.01, 0.03, 0.059})
      CHECK(prof.jerk_at(t) == -sign * 50000.0);
    CHECK(prof.at(0.06).a == Approx(sign * 5000.0).epsilon(1e-9));
    CHECK(prof.at(0.06).v == Approx(sign * 1390.0).epsilon(1e-9));
    CHECK(prof.at(0.06).p == Approx(sign * 72.6).epsilon(1e-9));
  }
}

TEST_CASE("a deceleration above A- decreases at exactly J until it is inside", "[profile][cases]") {
  // (v 1500, a -12000) with A- = 10000 and the target far ahead: a rises at +J; inside after
  // 0.04 s at a = -10000.
  const Limits l{2000.0, 5000.0, 10000.0, 50000.0};
  profile_checks::StartRelief relief;
  relief.over_acceleration = true;
  for (double sign : {1.0, -1.0}) {
    const KinematicState start{0.0, sign * 1500.0, -sign * 12000.0};
    const Profile prof = nc::plan_position(start, sign * 10000.0, l);
    require_valid(prof, start, sign * 10000.0, l, relief);
    for (double t : {1e-6, 0.02, 0.039})
      CHECK(prof.jerk_at(t) == sign * 50000.0);
    CHECK(prof.at(0.04).a == Approx(-sign * 10000.0).epsilon(1e-9));
  }
}

// ---------------------------------------------------------------------------------------------
// plan_velocity

TEST_CASE("plan_velocity reaches either sign from rest and holds it", "[profile][cases]") {
  // 0 → ±1000: dv 1000 ≥ 500: 0.2 + 0.1 = 0.3 s over 150 mm.
  for (double v : {1000.0, -1000.0}) {
    const KinematicState start{10.0, 0.0, 0.0};
    const Profile prof = nc::plan_velocity(start, v, kLimits);
    REQUIRE(prof.ok());
    const Finding f = profile_checks::check_velocity_profile(prof, start, v, kLimits);
    INFO(profile_checks::to_string(f));
    CHECK(f.ok());
    CHECK(prof.duration() == Approx(0.3).epsilon(1e-9));
    CHECK(prof.final_state().v == v);
    CHECK(prof.final_state().a == 0.0);
    CHECK(prof.final_state().p == Approx(10.0 + 0.15 * v).epsilon(1e-9));
    CHECK(prof.holds_velocity());
    // Past the end it goes on at the held velocity.
    CHECK(prof.at(prof.duration() + 2.0).v == v);
    CHECK(prof.at(prof.duration() + 2.0).p ==
          Approx(prof.final_state().p + 2.0 * v).epsilon(1e-12));
  }
}

TEST_CASE("plan_velocity lowering the level lands on it exactly and never below",
          "[profile][cases]") {
  // 2000 → 500: dv 1500: 0.3 + 0.1 = 0.4 s.
  for (double sign : {1.0, -1.0}) {
    const KinematicState start{0.0, sign * 2000.0, 0.0};
    const Profile prof = nc::plan_velocity(start, sign * 500.0, kLimits);
    REQUIRE(prof.ok());
    const Finding f = profile_checks::check_velocity_profile(prof, start, sign * 500.0, kLimits);
    INFO(profile_checks::to_string(f));
    CHECK(f.ok());
    CHECK(prof.duration() == Approx(0.4).epsilon(1e-9));
    CHECK(prof.final_state().v == sign * 500.0);
    const Range r = velocity_range(prof);
    CHECK((sign > 0 ? r.lo : -r.hi) >= 500.0 * (1.0 - 1e-12));
  }
  // Still accelerating when told to go lower (V 2500; 2000 + 3000²/(2J) = 2090 ≤ V): the
  // acceleration is ramped down first, the level is still met from above without undershoot.
  const Limits l{2500.0, 5000.0, 5000.0, 50000.0};
  const KinematicState start{0.0, 2000.0, 3000.0};
  const Profile prof = nc::plan_velocity(start, 500.0, l);
  REQUIRE(prof.ok());
  const Finding f = profile_checks::check_velocity_profile(prof, start, 500.0, l);
  INFO(profile_checks::to_string(f));
  CHECK(f.ok());
  CHECK(velocity_range(prof).lo >= 500.0 * (1.0 - 1e-12));
  CHECK(prof.final_state().v == 500.0);
}

TEST_CASE("plan_velocity to the opposite sign passes v = 0 once in one ramp", "[profile][cases]") {
  // -1000 → +1000 with A+ = A-: one ramp of dv 2000: 0.4 + 0.1 = 0.5 s, ending where it began
  // (mean velocity 0).
  const KinematicState start{0.0, -1000.0, 0.0};
  const Profile prof = nc::plan_velocity(start, 1000.0, kLimits);
  REQUIRE(prof.ok());
  const Finding f = profile_checks::check_velocity_profile(prof, start, 1000.0, kLimits);
  INFO(profile_checks::to_string(f));
  CHECK(f.ok());
  CHECK(prof.duration() == Approx(0.5).epsilon(1e-9));
  CHECK(velocity_reversals(prof, 1e-9 * kLimits.velocity) == 1);
  CHECK(prof.final_state().p == Approx(0.0).margin(1e-9));
}

TEST_CASE("plan_velocity above V is refused", "[profile][cases]") {
  const Profile prof = nc::plan_velocity({0.0, 0.0, 0.0}, 2000.5, kLimits);
  CHECK_FALSE(prof.ok());
  CHECK(prof.error() == ErrorCode::kVelocityNotAllowed);
}

// ---------------------------------------------------------------------------------------------
// plan_stop

TEST_CASE("plan_stop from constant velocity takes v/A + A/J, or 2·sqrt(v/J) below A²/J",
          "[profile][cases]") {
  struct Stop {
    double v;
    double expected;
  };
  // 2000 ≥ 500: 0.4 + 0.1 = 0.5 s; 300 < 500: 2·sqrt(300/50000) = 0.15491933384829668 s.
  for (const Stop& s : {Stop{2000.0, 0.5}, Stop{-2000.0, 0.5}, Stop{300.0, 0.15491933384829668},
                        Stop{-300.0, 0.15491933384829668}}) {
    const KinematicState start{7.0, s.v, 0.0};
    const Profile prof = nc::plan_stop(start, 5000.0, 50000.0);
    REQUIRE(prof.ok());
    CHECK(prof.duration() == Approx(s.expected).epsilon(1e-9));
    CHECK(prof.duration() ==
          Approx(reference::stop_time_from_constant_velocity(s.v, 5000.0, 50000.0)).epsilon(1e-12));
    // A symmetric ramp covers v·T/2.
    CHECK(prof.final_state().p == Approx(7.0 + s.v * s.expected / 2.0).epsilon(1e-9));
    CHECK(prof.final_state().v == 0.0);
    CHECK(prof.final_state().a == 0.0);
    CHECK(velocity_reversals(prof, 1e-9 * 2000.0) == 0);
    const Finding f = profile_checks::check_position_profile(
        prof, start, prof.final_state().p, Limits{2000.0, 5000.0, 5000.0, 50000.0});
    INFO(profile_checks::to_string(f));
    CHECK(f.ok());
  }
}

TEST_CASE("plan_stop while still accelerating first ramps the acceleration down",
          "[profile][cases]") {
  // (1000, +3000): a falls at -J through 0 to -A (0.16 s), v peaks at 1000 + 3000²/(2J) = 1090.
  const KinematicState start{0.0, 1000.0, 3000.0};
  const Profile prof = nc::plan_stop(start, 5000.0, 50000.0);
  REQUIRE(prof.ok());
  CHECK(prof.jerk_at(0.0) == -50000.0);
  CHECK(velocity_range(prof).hi == Approx(1090.0).epsilon(1e-9));
  CHECK(prof.final_state().v == 0.0);
  // Equivalent to a stop from (1090, 0) started 0.06 s later: 0.06 + 1090/5000 + 0.1.
  CHECK(prof.duration() == Approx(0.06 + 1090.0 / 5000.0 + 0.1).epsilon(1e-9));
}

// ---------------------------------------------------------------------------------------------
// Degenerate and invalid inputs

TEST_CASE("a move to where the axis already rests takes no time", "[profile][cases]") {
  const Profile prof = nc::plan_position({5.0, 0.0, 0.0}, 5.0, kLimits);
  REQUIRE(prof.ok());
  CHECK(prof.duration() == 0.0);
  CHECK(prof.at(0.0).p == 5.0);
  CHECK(prof.at(1.0).p == 5.0);
  CHECK(prof.at(1.0).v == 0.0);
}

namespace {

// A refused profile: the code, and at() and final_state() finite (no NaN set value ever).
void check_refused(const Profile& prof, ErrorCode code) {
  CHECK_FALSE(prof.ok());
  CHECK(prof.error() == code);
  CHECK(std::isfinite(prof.duration()));
  for (double t : {-1.0, 0.0, 0.5, 1e9}) {
    const KinematicState x = prof.at(t);
    CHECK(std::isfinite(x.p));
    CHECK(std::isfinite(x.v));
    CHECK(std::isfinite(x.a));
  }
  CHECK(profile_checks::finite(prof.final_state()));
}

}  // namespace

TEST_CASE("invalid inputs are refused with a specific code and never give a NaN",
          "[profile][cases]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const KinematicState rest{0.0, 0.0, 0.0};
  for (double bad : {nan, inf, -inf}) {
    INFO("bad value " << bad);
    // Start state (p, v, a): kStateNotFinite for every planner.
    for (int field = 0; field < 3; ++field) {
      KinematicState s = rest;
      (field == 0 ? s.p : field == 1 ? s.v : s.a) = bad;
      check_refused(nc::plan_position(s, 100.0, kLimits), ErrorCode::kStateNotFinite);
      check_refused(nc::plan_velocity(s, 100.0, kLimits), ErrorCode::kStateNotFinite);
      check_refused(nc::plan_stop(s, 5000.0, 50000.0), ErrorCode::kStateNotFinite);
    }
    // Target position.
    check_refused(nc::plan_position(rest, bad, kLimits), ErrorCode::kPositionNotFinite);
    // Target velocity.
    check_refused(nc::plan_velocity(rest, bad, kLimits), ErrorCode::kParameterNotFinite);
    // Limits.
    for (int field = 0; field < 4; ++field) {
      Limits l = kLimits;
      (field == 0   ? l.velocity
       : field == 1 ? l.acceleration
       : field == 2 ? l.deceleration
                    : l.jerk) = bad;
      check_refused(nc::plan_position(rest, 100.0, l), ErrorCode::kParameterNotFinite);
      check_refused(nc::plan_velocity(rest, 100.0, l), ErrorCode::kParameterNotFinite);
    }
    check_refused(nc::plan_stop(rest, bad, 50000.0), ErrorCode::kParameterNotFinite);
    check_refused(nc::plan_stop(rest, 5000.0, bad), ErrorCode::kParameterNotFinite);
  }
  for (double bad : {0.0, -0.0, -1.0, -std::numeric_limits<double>::min()}) {
    INFO("bad value " << bad);
    const ErrorCode codes[] = {ErrorCode::kVelocityNotPositive, ErrorCode::kAccelerationNotAllowed,
                               ErrorCode::kDecelerationNotAllowed, ErrorCode::kJerkNotAllowed};
    for (int field = 0; field < 4; ++field) {
      Limits l = kLimits;
      (field == 0   ? l.velocity
       : field == 1 ? l.acceleration
       : field == 2 ? l.deceleration
                    : l.jerk) = bad;
      check_refused(nc::plan_position(rest, 100.0, l), codes[field]);
      check_refused(nc::plan_velocity(rest, 0.0, l), codes[field]);
    }
    check_refused(nc::plan_stop(rest, bad, 50000.0), ErrorCode::kDecelerationNotAllowed);
    check_refused(nc::plan_stop(rest, 5000.0, bad), ErrorCode::kJerkNotAllowed);
  }
}
