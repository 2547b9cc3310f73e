// The planner's numeric range (docs/behaviour.md, "Profile"; fuzz finding P1): limits in
// [1e-9, 1e12], |p|, |v|, |a| of the start and |target| at most 1e12, a start v, a 0 or at
// least 1e-100 in size. Outside, a problem is refused with the code of the quantity; at the edges
// of the range it is planned and keeps its contract.
#include <catch2/catch.hpp>

#include <cmath>

#include "nc_core/profile.hpp"
#include "plc_interface/error_code.hpp"
#include "profile_checks.hpp"

namespace {

using nc::ErrorCode;
using nc::KinematicState;
using nc::Limits;
using nc::Profile;

const Limits kLimits{2000.0, 5000.0, 5000.0, 50000.0};

void check_refused(const Profile& prof, ErrorCode code) {
  CHECK_FALSE(prof.ok());
  CHECK(prof.error() == code);
  CHECK(std::isfinite(prof.duration()));
  const KinematicState x = prof.at(0.5);
  CHECK((std::isfinite(x.p) && std::isfinite(x.v) && std::isfinite(x.a)));
}

// Planned, and within the planner tests' contract (`relief` for a start outside the limits).
void check_position_planned(const KinematicState& s, double target, const Limits& l,
                            const profile_checks::StartRelief& relief = {}) {
  const Profile prof = nc::plan_position(s, target, l);
  REQUIRE(prof.ok());
  CHECK(profile_checks::check_position_profile(prof, s, target, l, {}, relief).ok());
}
void check_velocity_planned(const KinematicState& s, double v1, const Limits& l,
                            const profile_checks::StartRelief& relief = {}) {
  const Profile prof = nc::plan_velocity(s, v1, l);
  REQUIRE(prof.ok());
  CHECK(profile_checks::check_velocity_profile(prof, s, v1, l, {}, relief).ok());
}

// plan_position from `s` refused as a start too far outside `l` (0x4F70).
void check_far_start_refused(const KinematicState& s, double target, const Limits& l) {
  check_refused(nc::plan_position(s, target, l), ErrorCode::kStartFarOutsideLimits);
}

// The checks' relief for a start acceleration outside the limits.
profile_checks::StartRelief acceleration_relief() {
  profile_checks::StartRelief r;
  r.over_acceleration = true;
  return r;
}

Limits with_field(Limits l, int field, double value) {
  (field == 0   ? l.velocity
   : field == 1 ? l.acceleration
   : field == 2 ? l.deceleration
                : l.jerk) = value;
  return l;
}

}  // namespace

TEST_CASE("limits outside [1e-9, 1e12] are refused with the code of the limit",
          "[profile][range]") {
  const KinematicState rest{0.0, 0.0, 0.0};
  const ErrorCode codes[] = {ErrorCode::kVelocityNotAllowed, ErrorCode::kAccelerationNotAllowed,
                             ErrorCode::kDecelerationNotAllowed, ErrorCode::kJerkNotAllowed};
  for (double bad : {0.99e-9, 4.4e-322, 1.01e12, 3.9e118, 1.7e308}) {
    INFO("bad value " << bad);
    for (int field = 0; field < 4; ++field) {
      const Limits l = with_field(kLimits, field, bad);
      check_refused(nc::plan_position(rest, 100.0, l), codes[field]);
      check_refused(nc::plan_velocity(rest, 0.0, l), codes[field]);
    }
    check_refused(nc::plan_stop(rest, bad, 50000.0), ErrorCode::kDecelerationNotAllowed);
    check_refused(nc::plan_stop(rest, 5000.0, bad), ErrorCode::kJerkNotAllowed);
  }
}

TEST_CASE("a start or target beyond 1e12 is refused with the code of the quantity",
          "[profile][range]") {
  for (double bad : {1.01e12, -1.01e12, 1e300, -1.7e308}) {
    INFO("bad value " << bad);
    check_refused(nc::plan_position({bad, 0.0, 0.0}, 0.0, kLimits),
                  ErrorCode::kTargetPositionNotAllowed);
    check_refused(nc::plan_position({0.0, 0.0, 0.0}, bad, kLimits),
                  ErrorCode::kTargetPositionNotAllowed);
    check_refused(nc::plan_position({0.0, bad, 0.0}, 100.0, kLimits),
                  ErrorCode::kVelocityNotAllowed);
    check_refused(nc::plan_velocity({0.0, 0.0, bad}, 0.0, kLimits),
                  ErrorCode::kAccelerationNotAllowed);
    check_refused(nc::plan_stop({0.0, bad, 0.0}, 5000.0, 50000.0), ErrorCode::kVelocityNotAllowed);
    // The four-argument call checks its target the same way (fuzz finding P11: it took any
    // finite target).
    check_refused(nc::plan_position({0.0, 0.0, 0.0}, bad, 100.0, kLimits),
                  ErrorCode::kTargetPositionNotAllowed);
    check_refused(nc::plan_position({bad, 0.0, 0.0}, 0.0, -100.0, kLimits),
                  ErrorCode::kTargetPositionNotAllowed);
  }
  // 1e12 itself is planned.
  const Profile edge = nc::plan_position({1e12 - 1000.0, 0.0, 0.0}, 1e12, 100.0, kLimits);
  REQUIRE(edge.ok());
  CHECK(profile_checks::check_passing_profile(edge, {1e12 - 1000.0, 0.0, 0.0}, 1e12, 100.0, kLimits)
            .ok());
}

TEST_CASE("a subnormal start velocity or acceleration is refused, 1e-100 is planned",
          "[profile][range]") {
  // The fuzz input planner-subnormal-start-state: v = -4.9e-324, a = 1.4e-322 broke continuity.
  const Limits small{0.0157, 0.0106, 0.0106, 0.0106};
  check_refused(nc::plan_position({0.0, -4.9406564584124654e-324, 0.0}, 0.0106, small),
                ErrorCode::kVelocityNotAllowed);
  check_refused(nc::plan_position({0.0, 0.0, 1.3833838083554903e-322}, 0.0106, small),
                ErrorCode::kAccelerationNotAllowed);
  check_refused(nc::plan_velocity({0.0, 0.0, 0.0}, 1e-300, small), ErrorCode::kVelocityNotAllowed);
  // An end velocity of plan_position's four-argument call, as plan_velocity's target (fuzz
  // finding P11): subnormal or below 1e-100 refused, 1e-100 planned.
  for (double bad : {4.9406564584124654e-324, -2.2e-308, 1e-300}) {
    INFO("end velocity " << bad);
    check_refused(nc::plan_position({0.0, 0.0, 0.0}, 0.0106, bad, small),
                  ErrorCode::kVelocityNotAllowed);
  }
  const Profile slow = nc::plan_position({0.0, 0.0, 0.0}, 0.0106, -1e-100, small);
  REQUIRE(slow.ok());
  CHECK(profile_checks::check_passing_profile(slow, {0.0, 0.0, 0.0}, 0.0106, -1e-100, small).ok());
  const KinematicState tiny{0.0, 1e-100, -1e-100};
  const Profile prof = nc::plan_position(tiny, 0.0106, small);
  REQUIRE(prof.ok());
  CHECK(profile_checks::check_position_profile(prof, tiny, 0.0106, small).ok());
}

TEST_CASE("problems at the edges of the range are planned and keep the contract",
          "[profile][range]") {
  // The kept fuzz input of P1 (J = 3.9e118 with A = 100) is refused above; J = 1e12 with A = 100
  // and the smallest limits are planned exactly.
  const Limits big_jerk{2000.0, 100.0, 100.0, 1e12};
  const Profile a = nc::plan_position({0.0, 0.0, 0.0}, 4900.0, big_jerk);
  REQUIRE(a.ok());
  CHECK(profile_checks::check_position_profile(a, {0.0, 0.0, 0.0}, 4900.0, big_jerk).ok());

  const Limits small{1e-9, 1e-9, 1e-9, 1e-9};
  const Profile b = nc::plan_position({0.0, 0.0, 0.0}, 1e-6, small);
  REQUIRE(b.ok());
  CHECK(profile_checks::check_position_profile(b, {0.0, 0.0, 0.0}, 1e-6, small).ok());

  const Limits large{1e12, 1e12, 1e12, 1e12};
  const KinematicState far{-1e12, 0.0, 0.0};
  const Profile c = nc::plan_position(far, 1e12, large);
  REQUIRE(c.ok());
  CHECK(profile_checks::check_position_profile(c, far, 1e12, large).ok());
}

TEST_CASE("a start more than 2e6 times outside the limits is refused with 0x4F70",
          "[profile][range]") {
  CHECK(plc::to_id(ErrorCode::kStartFarOutsideLimits) == 0x4F70U);
  // The kept fuzz input of P2: a = -5.96e8 against limits of 7.04e-9 (8.5e16 times A) broke
  // continuity at t = 3.6e33 s; now refused by every plan function that takes limits.
  const double tiny = 7.041529113171147e-09;
  const Limits small{tiny, tiny, tiny, tiny};
  const KinematicState p2{tiny, 7.0415291131975135e-09, -595821443.509712};
  check_refused(nc::plan_position(p2, tiny, small), ErrorCode::kStartFarOutsideLimits);
  check_refused(nc::plan_velocity(p2, 0.0, small), ErrorCode::kStartFarOutsideLimits);
  check_refused(nc::plan_position(p2, tiny, 0.5 * tiny, small), ErrorCode::kStartFarOutsideLimits);

  // |a| above 2e6·max(A+, A-): A± = 1, a = 2.02e6 (its forced velocity a²/2J = 2 mm/s is far
  // below 2e6·V with J = 1e12).
  const Limits soft{2000.0, 1.0, 1.0, 1e12};
  check_refused(nc::plan_position({0.0, 0.0, 2.02e6}, 100.0, soft),
                ErrorCode::kStartFarOutsideLimits);
  check_refused(nc::plan_velocity({0.0, 0.0, -2.02e6}, 0.0, soft),
                ErrorCode::kStartFarOutsideLimits);
  // |v| above 2e6·V: V = 1e-3, v = 2020 mm/s.
  const Limits creep{1e-3, 5000.0, 5000.0, 50000.0};
  check_refused(nc::plan_position({0.0, 2020.0, 0.0}, 100.0, creep),
                ErrorCode::kStartFarOutsideLimits);
  check_refused(nc::plan_velocity({0.0, -2020.0, 0.0}, 0.0, creep),
                ErrorCode::kStartFarOutsideLimits);
  // The velocity a forces whatever is done, v + a·|a|/2J, above 2e6·V: kLimits (V 2000,
  // J 50000), a = 2.1e7 (4200 times A) forces 4.41e9 mm/s > 4e9.
  check_refused(nc::plan_position({0.0, 0.0, 2.1e7}, 100.0, kLimits),
                ErrorCode::kStartFarOutsideLimits);
}

TEST_CASE("a start whose braking distance is above 1e15 is refused with 0x4F70",
          "[profile][range]") {
  // Fuzz finding P4: v = -1.6e6 mm/s (5.4e4 times V) against A- = 7e-9 needs 1.9e26 mm to stop;
  // the profile broke continuity by 1.3e29 at t = 2.3e14 s.
  const Limits p4{30.243137254883315, 7.0415291131711472e-09, 7.0415291132121761e-09,
                  1064510.2433593273};
  check_refused(
      nc::plan_position({7.0415308689085601e-09, -1622465.2431446458, 7.0415291131712373e-09},
                        7.0415291131643709e-09, p4),
      ErrorCode::kStartFarOutsideLimits);
  // At 2000 mm/s: A- = 1.9e-9 brakes over 1.05e15 (refused), 2.1e-9 over 9.5e14 (planned).
  const KinematicState fast{0.0, 2000.0, 0.0};
  check_refused(nc::plan_position(fast, 0.0, Limits{2000.0, 5000.0, 1.9e-9, 50000.0}),
                ErrorCode::kStartFarOutsideLimits);
  check_refused(nc::plan_velocity(fast, 0.0, Limits{2000.0, 5000.0, 1.9e-9, 50000.0}),
                ErrorCode::kStartFarOutsideLimits);
  check_velocity_planned(fast, 0.0, Limits{2000.0, 5000.0, 2.1e-9, 50000.0});
}

TEST_CASE("a start 1e6 times above V (override 1 ppm at full speed) is planned",
          "[profile][range]") {
  // The kernel's farthest start from an override alone: v = 2000 mm/s, the level 1 ppm of it.
  const Limits slow{0.002, 5000.0, 5000.0, 50000.0};
  const KinematicState full{0.0, 2000.0, 0.0};
  profile_checks::StartRelief relief;
  relief.over_speed = true;
  check_velocity_planned(full, 0.002, slow, relief);
  check_position_planned(full, 1000.0, slow, relief);
}

TEST_CASE("a start at V with an acceleration of rounding size cruises at a = 0",
          "[profile][range]") {
  // Fuzz finding P3: v just below V, a = -1.5e-23 (2e-15 of A), target 1.3e11 mm away at V =
  // 7.04e-9 mm/s. The push to V took the start as at (V, 0) within its rounding tolerance and
  // gave no piece, so the cruise of 1.84e19 s carried the start's a: its end lay 2.5e15 mm short
  // of the stop that follows it.
  const Limits l{7.0415291131711472e-09, 7.0415291131711472e-09, 7.0419991054345708e-09,
                 2.3093894380261804e-08};
  const KinematicState start{7.0415291131711472e-09, 7.0415291131710959e-09,
                             -1.4895713343675384e-23};
  const double target = 129641627198.24313;
  const Profile prof = nc::plan_position(start, target, l);
  REQUIRE(prof.ok());
  CHECK(prof.duration() == Approx(1.8411004927289029e+19).epsilon(1e-12));
  // A ramp of |a| / J = 6.45e-16 s takes a to 0; the cruise holds a = 0.
  REQUIRE(prof.segment_count() == 5);
  CHECK(prof.segment(0).duration == Approx(6.450065588074504e-16).epsilon(1e-9));
  CHECK(prof.segment(1).a == 0.0);
  const profile_checks::Finding f = profile_checks::check_position_profile(prof, start, target, l);
  INFO(profile_checks::to_string(f));
  CHECK(f.ok());
}

TEST_CASE("a landing onto the end velocity keeps J when 2J|v| dwarfs a squared",
          "[profile][range]") {
  // Fuzz finding P5: a = A+ = 4.77e-4 just below v1 = V (1.08e-18 short) with J = 9.06e9. The
  // rounding tolerance of the final curve, taken on a² + 2Jv = 8.6e6, counted the start as on
  // it, and the exact landing ramp's jerk a² / 2(v1 - v) was 1.05e11, 11.6 times J. Now a ramp
  // at J (5.26e-14 s) ends at v1.
  const double x = 0.00047679227941176469;
  const Limits l{x, x, 0.00047679227941088969, 9059681856.0};
  const KinematicState start{x, 0.00047679227941176361, x};
  const Profile prof = nc::plan_velocity(start, x, l);
  REQUIRE(prof.ok());
  REQUIRE(prof.segment_count() == 1);
  CHECK(prof.segment(0).j == -9059681856.0);
  CHECK(prof.duration() == Approx(x / 9059681856.0).epsilon(1e-12));
  Limits keep = l;
  keep.velocity = (start.v + x * x / (2.0 * l.jerk)) * (1.0 + 1e-9);  // the forced overshoot
  CHECK(profile_checks::check_velocity_profile(prof, start, x, keep).ok());
}

TEST_CASE("an acceleration left at the end velocity ramps to 0 at J however short the ramp",
          "[profile][range]") {
  // Fuzz finding P6: from rest at a = A+ = 7.04e-9 to v1 = 30.24 mm/s with J = 5.96e8. After the
  // hold at A+ (4.29e9 s) the velocity change took v1 as reached (the acceleration lay below its
  // rounding tolerance, 1.3e-8) and left out the final ramp: the acceleration jumped from A+ to 0.
  // Now the ramp of A+ / J = 1.18e-17 s ends the profile.
  const Limits l{30.243137254883315, 7.0415291131711472e-09, 7.0415291132121761e-09,
                 595754495.99408698};
  const KinematicState start{7.0228844789209513e-09, 2.594760871615113e-35, 7.0415291131711472e-09};
  const double v1 = 30.243137254872856;
  const Profile prof = nc::plan_velocity(start, v1, l);
  REQUIRE(prof.ok());
  REQUIRE(prof.segment_count() == 2);
  CHECK(prof.segment(1).j == -595754495.99408698);
  CHECK(prof.segment(1).duration == Approx(1.1819514851367627e-17).epsilon(1e-9));
  CHECK(profile_checks::check_velocity_profile(prof, start, v1, l).ok());
}

TEST_CASE("a long hold at A- ends where the bound changes, not past it", "[profile][range]") {
  // Fuzz finding P7: from v = -8578 mm/s with a 3e-14 above A- = 4.7679e-4 and a smaller
  // A+ = 4.7584e-4, J = 8.6e9. The hold was timed at A- but ran at the start's a: after 1.8e7 s
  // it had crossed v = 0 by 2.7e-10 mm/s, still at A- where A+ applies. That start (1.8e7 times
  // V) is now refused (P8); from v = -900 (1.9e6 times V) the hold of 1.9e6 s drifted 2.8e-11
  // past v = 0 the same way.
  const Limits l{0.00047679227941176469, 0.00047583860509535844, 0.00047679227941088969,
                 8589934592.0};
  const KinematicState start{0.00047679227941355493, -900.0, 0.00047679227941089749};
  profile_checks::StartRelief relief;
  relief.over_speed = true;
  relief.over_acceleration = true;
  check_velocity_planned(start, 0.00047679227941176469, l, relief);
}

TEST_CASE("a start acceleration 1e8 times A is refused: its rounding would pass A+",
          "[profile][range]") {
  // Fuzz finding P8: a = -0.695 against A± = 7.3e-9 / 7.0e-9 (1e8 times), J = 2. Ramping a back
  // by 0.695 leaves a few ulp of 0.695, 1e-8 of A: the next segment began 1e-8 above A+.
  const Limits l{31.24609375, 7.2750489832789158e-09, 7.0415318020474887e-09, 2.0004863739013672};
  check_refused(
      nc::plan_position({8.2572993763189198e-317, 0.12012095731847426, -0.69521963456097768},
                        0.00047679227918706601, l),
      ErrorCode::kStartFarOutsideLimits);
  // 1.9e6 times A+ is planned within the contract.
  profile_checks::StartRelief relief;
  relief.over_acceleration = true;
  check_velocity_planned({0.0, 0.0, -1.9e6 * 7.2750489832789158e-09}, 0.0, l, relief);
}

TEST_CASE("a start acceleration 1e8 times the bound its ramp ends at is refused",
          "[profile][range]") {
  // Fuzz finding P9: v = 0.12, a = -0.695 with A+ = 7.3e-9, A- = 4.6e-4, J = 2: 1.5e3 times
  // max(A+, A-), inside P8's bound. The ramp of a back at J crosses v = 0 at a = -0.052 and ends
  // at A+ (|v| grows again): a = -A+ - 1.3e-16 there, a few ulp of 0.695 and 1.8e-8 of A+. The
  // start counts against the bound its ramp ends at: 9.5e7 times A+, refused.
  const Limits l{9074.0000000791624, 7.2752683738651311e-09, 0.00046147382817898422,
                 2.0004863739013672};
  const KinematicState p9{8.2572993763189198e-317, 0.12012095731847509, -0.6952196903821245};
  check_refused(nc::plan_position(p9, 0.00047679222188957981, l),
                ErrorCode::kStartFarOutsideLimits);
  check_refused(nc::plan_velocity(p9, 0.0, l), ErrorCode::kStartFarOutsideLimits);
  check_refused(nc::plan_position(p9, 0.00047679222188957981, -1e-3, l),
                ErrorCode::kStartFarOutsideLimits);

  // The same from within A- (the second input of P9, seed 1702): a = -0.699 below A- = 0.79
  // still crosses v = 0 at a = -0.022, 3e6 times A+, and ends its ramp at A+.
  check_far_start_refused(
      {1.061823625420268e-313, 0.12012095731847509, -0.69888269381952017}, 0.00047631558754869519,
      {9074.0000000791624, 7.2752683738651311e-09, 0.78884840011055968, 2.0308818817138672});
  // And from above a smaller A- = 0.125 (seed 1721): a position profile that pushes the other
  // way ramps through A- without holding it, crosses v = 0 at a = -0.053 and ends at A+.
  check_far_start_refused(
      {8.2572993763189198e-317, 0.12012095731847426, -0.69521963456097768}, 0.00047679227918706601,
      {31.24609375, 7.2750489972109146e-09, 0.12460704083719688, 2.0004863739013672});

  const profile_checks::StartRelief relief = acceleration_relief();
  // P9's start with A+ = |a0| / 1.9e6: the ramp crossing v = 0 at a = -0.052 and ending at A+
  // is planned within the contract.
  const double a0 = 0.6952196903821245;
  Limits near = l;
  near.acceleration = a0 / 1.9e6;
  check_position_planned({0.0, 0.12012095731847509, -a0}, 1e-3, near, relief);
  check_velocity_planned({0.0, 0.12012095731847509, -a0}, 0.0, near, relief);
  // The ramp meets A- before v = 0 (a0² + 2J·v0 < A-²): it counts against A- = 4.6e-4, 1.5e3
  // times, and is planned although it lies 9.5e7 times above A+.
  const KinematicState before_zero{0.0, 0.2, -a0};
  CHECK(a0 * a0 - 2.0 * l.jerk * 0.2 < l.deceleration * l.deceleration);
  check_position_planned(before_zero, 1.0, l, relief);
  check_velocity_planned(before_zero, 0.0, l, relief);
  // Growing |v| (v and a of one sign): the ramp ends at A+ from the start; 2.1e6 times A+ with
  // A- 1e5 times larger is refused, 1.9e6 times planned.
  const Limits lopsided{1e5, 1e-3, 100.0, 50.0};
  check_far_start_refused({0.0, 1.0, 2.1e3}, 100.0, lopsided);
  check_position_planned({0.0, 1.0, 1.9e3}, 100.0, lopsided, relief);
}

TEST_CASE("an end velocity whose change needs more than 1e15 is refused with 0x4221",
          "[profile][range]") {
  // Fuzz finding P16 (seed 1781): v_end = 8.6e9 with A- = 3.6e-9 needs 1e28 mm to change at A-:
  // the profile broke continuity by 517 mm at t = 8386 s. Refused, as a start whose braking
  // distance is above 1e15 (P4).
  const Limits huge{164752293244.48627, 8589934592.0, 3.6390076368974896e-09, 164758387836.50589};
  check_refused(
      nc::plan_position({6.5715143469463669e-110, 3.0515277103438552e-05, 4.6570422518632973e-10},
                        6.0780413869071933e-86, 8589934592.0, huge),
      ErrorCode::kVelocityNotAllowed);
  // At 2000 mm/s: min(A+, A-) = 1.9e-9 needs 1.05e15, refused; with A- = 2.1e-9 (9.5e14) a
  // target passed at 2000 mm/s is planned within the contract. v_end = 0 is never refused so.
  const Limits slow{2000.0, 5000.0, 1.9e-9, 50000.0};
  check_refused(nc::plan_position({0.0, 0.0, 0.0}, 1e6, 2000.0, slow),
                ErrorCode::kVelocityNotAllowed);
  check_refused(nc::plan_position({0.0, 0.0, 0.0}, 1e6, -2000.0, slow),
                ErrorCode::kVelocityNotAllowed);
  REQUIRE(nc::plan_position({0.0, 0.0, 0.0}, 1e6, slow).ok());
  const Limits enough{2000.0, 5000.0, 2.1e-9, 50000.0};
  const Profile prof = nc::plan_position({0.0, 0.0, 0.0}, 1e6, 2000.0, enough);
  REQUIRE(prof.ok());
  CHECK(profile_checks::check_passing_profile(prof, {0.0, 0.0, 0.0}, 1e6, 2000.0, enough).ok());
}

TEST_CASE("a run-up backwards before a large end velocity is anchored at its v = 0 crossing",
          "[profile][range]") {
  // Fuzz finding P18 (seed 1801): P16's start and limits with v_end = 600 (4.9e13 mm to change at
  // A-, within the range): a hold at -A- to v = 0 (8386 s), a turn, 9500 s back at A- to v = 0,
  // then 1.2e-4 s up to 600. Anchored back from 600, the crossing's velocity carried 1 ulp of
  // 600 (1.1e-13 mm/s), and the 9500 s hold before it turned that into a jump of 1.08e-9 mm at
  // the switch. The crossing keeps its exact v = 0 now; the jump is at the positions' rounding.
  const Limits l{164752293244.48627, 8589934592.0, 3.6390076368974896e-09, 164456324477.9472};
  const KinematicState s{6.5715143469463669e-110, 3.0515277103438552e-05, 4.6570422518632973e-10};
  const double target = 6.0780413869071933e-86;
  const double v_end = 600.1572265625;
  const Profile prof = nc::plan_position(s, target, v_end, l);
  REQUIRE(prof.ok());
  const profile_checks::Finding f =
      profile_checks::check_passing_profile(prof, s, target, v_end, l, {}, acceleration_relief());
  INFO(profile_checks::to_string(f));
  CHECK(f.ok());
  REQUIRE(prof.segment_count() == 7);
  // The switch (segment 2 to 3): continuous to 1e-15 mm (it was 1.08e-9).
  const KinematicState end2 = profile_checks::advance(prof.segment(2), prof.segment(2).duration);
  CHECK(std::fabs(end2.p - prof.segment(3).p) <= 1e-15);
  // The hold at A- back to v = 0 and the crossing at exactly 0.
  const nc::Segment& hold = prof.segment(4);
  CHECK(hold.a == l.deceleration);
  CHECK(hold.duration == Approx(9499.7008888055734).epsilon(1e-12));
  CHECK(prof.segment(5).v == 0.0);
  CHECK(hold.v == Approx(-l.deceleration * hold.duration).epsilon(1e-14));
  CHECK(prof.duration() == Approx(17885.305039178773).epsilon(1e-12));
}
