// The planner suites are only as good as their checks (tests/support/profile_checks.hpp). Here
// hand-built profiles (Profile::reset/append/close) that break one rule each must be caught, and
// the same motion without the fault must pass — including faults that exist only inside a
// segment, where sampling at boundaries would miss them.
#include <catch2/catch.hpp>

#include "nc_core/profile.hpp"
#include "profile_checks.hpp"
#include "reference_planner.hpp"

namespace {

using nc::KinematicState;
using nc::Limits;
using nc::Profile;
using profile_checks::Check;

const Limits kLimits{2000.0, 5000.0, 5000.0, 50000.0};

// Dynamics 1.1 (seed 000 §2.1) built from the reference's pieces: 0 → 1000 mm in 1.0 s.
Profile dynamics_1_1(const KinematicState* exact_end) {
  Profile prof;
  prof.reset({0.0, 0.0, 0.0});
  for (const reference::Piece& pc : reference::rest_to_rest_pieces(1000.0, kLimits))
    prof.append(pc.duration, pc.jerk);
  prof.close(exact_end);
  return prof;
}

}  // namespace

TEST_CASE("a correct hand-built profile passes every check", "[profile][checks]") {
  const KinematicState end{1000.0, 0.0, 0.0};
  const Profile prof = dynamics_1_1(&end);
  REQUIRE(prof.duration() == Approx(1.0).epsilon(1e-12));
  const profile_checks::Finding f =
      profile_checks::check_position_profile(prof, {0.0, 0.0, 0.0}, 1000.0, kLimits);
  INFO(profile_checks::to_string(f));
  CHECK(f.ok());
}

TEST_CASE("the checks catch a profile faster than V, also between segment boundaries",
          "[profile][checks]") {
  const KinematicState end{1000.0, 0.0, 0.0};
  Limits slower = kLimits;
  slower.velocity = 1999.0;
  CHECK(profile_checks::check_limits(dynamics_1_1(&end), slower).check == Check::kVelocity);

  // v = 1900 + 1000·t - 25000·t²: 1900 at both ends of the 0.04 s segment, 1910 at t = 0.02.
  Profile prof;
  prof.reset({0.0, 1900.0, 1000.0});
  prof.append(0.04, -50000.0);
  prof.close();
  Limits v1905 = kLimits;
  v1905.velocity = 1905.0;
  CHECK(profile_checks::check_limits(prof, v1905).check == Check::kVelocity);
  v1905.velocity = 1910.0 * (1.0 + 1e-12);
  CHECK(profile_checks::check_limits(prof, v1905).ok());
}

TEST_CASE(
    "the checks apply A+ while |v| grows and A- while it shrinks, also at v = 0 inside a "
    "segment",
    "[profile][checks]") {
  const Limits l{2000.0, 5000.0, 10000.0, 50000.0};  // A+ 5000 < A- 10000
  // Braking at -10000 is allowed while v > 0; held past v = 0 it accelerates the axis the other
  // way at 10000 > A+.
  Profile held;
  held.reset({0.0, 1000.0, -10000.0});
  held.append(0.1, 0.0);   // v 1000 -> 0: shrinking, within A-
  held.append(0.05, 0.0);  // v 0 -> -500: growing at 10000
  held.close();
  CHECK(profile_checks::check_limits(held, l).check == Check::kAcceleration);
  Profile stopped;
  stopped.reset({0.0, 1000.0, -10000.0});
  stopped.append(0.1, 0.0);
  stopped.close();
  CHECK(profile_checks::check_limits(stopped, l).ok());

  // One segment: v = 500 - 10000·t + 25000·t², a = -10000 + 50000·t over 0.12 s. Both ends are
  // inside (start: shrinking at 10000 = A-; end: v -340, a -4000, growing below A+), but v
  // crosses 0 at t = 0.0586 with |a| = 7071 > A+.
  Profile crossing;
  crossing.reset({0.0, 500.0, -10000.0});
  crossing.append(0.12, 50000.0);
  crossing.close();
  CHECK(profile_checks::check_limits(crossing, l).check == Check::kAcceleration);
  // With A+ = A- = 10000 the same motion is fine.
  CHECK(profile_checks::check_limits(crossing, Limits{2000.0, 10000.0, 10000.0, 50000.0}).ok());
}

TEST_CASE("the checks catch a jerk above J", "[profile][checks]") {
  const KinematicState end{1000.0, 0.0, 0.0};
  Limits softer = kLimits;
  softer.jerk = 49999.0;
  CHECK(profile_checks::check_limits(dynamics_1_1(&end), softer).check == Check::kJerk);
}

TEST_CASE("the checks catch a jump to the final state and a missed target", "[profile][checks]") {
  const profile_checks::Scales sc = profile_checks::scales_for({}, 1000.0, kLimits);
  // The final state claims the target, the segments end 1e-3 mm before it.
  const KinematicState wrong_end{1000.001, 0.0, 0.0};
  const Profile jumps = dynamics_1_1(&wrong_end);
  CHECK(profile_checks::check_continuity(jumps, sc).check == Check::kContinuity);
  CHECK(profile_checks::check_position_profile(jumps, {}, 1000.001, kLimits).check ==
        Check::kContinuity);
  // Segments and final state agree, but not with the target.
  const Profile misses = dynamics_1_1(nullptr);
  CHECK(profile_checks::check_continuity(misses, sc).ok());
  CHECK(profile_checks::check_end(misses, {}, 1000.001, 0.0, sc).check == Check::kEndPosition);
  // A wrong end velocity.
  CHECK(profile_checks::check_end(misses, {}, 1000.0, 1e-3, sc).check == Check::kEndVelocity);
}

TEST_CASE("the checks catch a profile that does not start at the given state",
          "[profile][checks]") {
  const KinematicState end{1000.0, 0.0, 0.0};
  CHECK(profile_checks::check_structure(dynamics_1_1(&end), {0.0, 1e-9, 0.0}).check ==
        Check::kStart);
  CHECK(
      profile_checks::check_structure(Profile::failure(nc::ErrorCode::kJerkNotAllowed), {}).check ==
      Check::kNotOk);
}

TEST_CASE(
    "a start far above its acceleration bound is held to its ramp at J, to the rounding of "
    "absolute time",
    "[profile][checks]") {
  profile_checks::StartRelief relief;
  relief.over_speed = true;
  relief.over_acceleration = true;
  // Fuzz finding P27 (a mistake of the checker): from a0 = 0.122 = 1.7e7 A+ the plan ramps at J
  // to A+ and reaches it at t = 512 s, 0.6 ulp of t after the kink (a0 - A+) / J of the envelope
  // a0 - J t; a at the kink was 2.3e-9 of A+ above the bound. Within the resolution of the times.
  const KinematicState start{2.9040813893882147e-315, -31.247058823529411, 0.12205882352941438};
  const Limits l{0.00047683302386134277, 7.0415291271033577e-09, 0.00047679239582708652,
                 0.00023839613970588235};
  const Profile prof = nc::plan_position(start, 0.00047679227941176469, l);
  REQUIRE(prof.ok());
  const profile_checks::Finding f = profile_checks::check_limits(prof, l, {}, relief);
  INFO(profile_checks::to_string(f));
  CHECK(f.ok());

  // A ramp from a0 = 1e7 A+ that stops 1e-8 s early and holds what it reached, 1e-5 of A+ above
  // A+ (ten thousand times the rounding the envelope allows): caught; the ramp that ends on A+
  // and holds it: not.
  const Limits far{1e9, 1e-3, 1e-3, 1.0};
  const double ramp = (1e4 - far.acceleration) / far.jerk;
  for (const double early : {0.0, 1e-8}) {
    INFO("ramp stopped " << early << " s early");
    Profile held;
    held.reset({0.0, 0.0, 1e4});
    held.append(ramp - early, -far.jerk);
    held.append(100.0, 0.0);
    held.close();
    const profile_checks::Finding g = profile_checks::check_limits(held, far, {}, relief);
    INFO(profile_checks::to_string(g));
    CHECK((early == 0.0 ? g.ok() : g.check == Check::kAcceleration));
  }
}
