// plan_position with an end velocity where its switch point is hard to find (fuzz findings P10,
// P12, P14, P15, P17, P21; docs/reliability.md): the root of E(tau) = target inside a jump that the
// velocity change's rounding tolerance makes, a root far below the end of a very long push piece,
// the first of two crossings inside one push piece (issue 14 item 1, Bellman consistency) and a
// root past a stretch of the push where E(tau) is flat.
// Each profile keeps the planner tests' contract (profile_checks.hpp), with the numbers found.
#include <catch2/catch.hpp>

#include <cmath>

#include "nc_core/profile.hpp"
#include "profile_checks.hpp"

namespace {

using nc::KinematicState;
using nc::Limits;
using nc::Profile;

Profile planned(const KinematicState& s, double target, double v_end, const Limits& l) {
  const Profile prof = nc::plan_position(s, target, v_end, l);
  REQUIRE(prof.ok());
  profile_checks::StartRelief relief;
  relief.over_acceleration = true;
  const profile_checks::Finding f =
      profile_checks::check_passing_profile(prof, s, target, v_end, l, {}, relief);
  INFO(profile_checks::to_string(f));
  CHECK(f.ok());
  return prof;
}

// The last segment: a hold at v_end (a = 0, j = 0) of `duration`.
void check_ends_with_hold(const Profile& prof, double v_end, double duration) {
  REQUIRE(prof.segment_count() > 0);
  const nc::Segment& last = prof.segment(prof.segment_count() - 1);
  CHECK(last.j == 0.0);
  CHECK(last.a == 0.0);
  CHECK(last.v == Approx(v_end).epsilon(1e-12));
  CHECK(last.duration == Approx(duration).epsilon(1e-6));
}

}  // namespace

TEST_CASE("a target just past where the direct change ends holds v_end for the rest",
          "[profile][end_velocity]") {
  // P10 (seed 1701): from rest with a = -4.6e-6 to 0.0106 mm at 0.0106 mm/s, A- = J = 0.0106.
  // The target lies 1.3e-8 past the end of the direct change; the change snaps an overshoot of
  // the final curve within its tolerance to the curve, so E(tau) jumps by 1.3e-8 there and the
  // switch broke continuity by 1.3e-8 (the checks allow 1e-9). Now: the change from the lower
  // end of the jump, then 4.7e-8 s at v_end.
  const Limits l{0.010841535057602809, 0.065687037460898767, 0.010588235294117647,
                 0.010588235294117647};
  const Profile prof =
      planned({0.0, 0.0, -4.5777065690089267e-06}, 0.010588235294117647, 0.010588235294117647, l);
  check_ends_with_hold(prof, 0.010588235294117647, 4.6756511230276898e-08);
  CHECK(prof.duration() == Approx(2.0004324791683437).epsilon(1e-12));
}

TEST_CASE("with a tiny A- an overshoot of rounding size is no switch point: v_end is held",
          "[profile][end_velocity]") {
  // P12 (seed 1703): from v = 500 to 1000 mm at 2876 mm/s, A+ 5000, A- 6.1e-6. Past the point
  // where the push meets the final curve, an overshoot of v_end by dv costs a hold at A- of
  // 2876 · dv / 6.1e-6 mm: the 3e-10 mm/s the change takes as rounding is 137 mm of E(tau), and
  // the root (30 mm past the direct change) lay inside that jump: continuity broke by 29.8 mm.
  // Now the push ends at the curve and 0.01035 s at v_end cover the 29.8 mm.
  const Limits l{200000.0, 5000.076295109483, 6.1036087586785692e-06, 50212.863355458911};
  const Profile prof = planned({0.0, 500.00762951094833, 0.0}, 1000.0, 2876.0204470893414, l);
  check_ends_with_hold(prof, 2876.0204470893414, 0.010352937220367238);
  CHECK(prof.duration() == Approx(0.58512584719202976).epsilon(1e-12));
  // Seed 1704, the same with A- = 2.8e-4 from a = 16.9: 0.98 mm at v_end = 24.66 (0.0398 s).
  const Limits m{247058.82352941178, 24.705882352941178, 0.00027842802159904265,
                 24.675364309147785};
  const Profile prof2 =
      planned({0.0, 0.0, 16.893263141832612}, 24.705882352941178, 24.663157091630428, m);
  check_ends_with_hold(prof2, 24.663157091630428, 0.039783491070663354);
}

TEST_CASE("a root far below the end of a very long push piece is found",
          "[profile][end_velocity]") {
  // P14 (seed 1711): from rest at p = 0 with a = 9.06 back to 0 at v_end = 3.4e-44 (towards
  // -), A+ = 7.6e-6, V = 1000: the push towards the target is a hold at A+ for 1.3e8 s, the
  // root at 0.051 s. The search (Illinois, 200 steps) crawled from the near end and stopped at
  // 3.93 s: continuity broke by 5.9e-5. Now its first point follows E ~ tau^2 and the profile
  // takes 0.051 s, as the three-argument call to rest does.
  const Limits l{1000.0, 7.6295109483482109e-06, 5312.5810635538264, 227389.94430457009};
  const KinematicState s{0.0, 0.0, 9.0626382848859386};
  const Profile prof = planned(s, 0.0, 3.4331812393645485e-44, l);
  const Profile rest = nc::plan_position(s, 0.0, l);
  REQUIRE(rest.ok());
  CHECK(prof.duration() == Approx(rest.duration()).epsilon(1e-9));
  CHECK(prof.duration() == Approx(0.051009498038301328).epsilon(1e-12));
}

TEST_CASE("a residual of E's rounding is no reason for a hold at a tiny v_end, for every sign",
          "[profile][end_velocity]") {
  // P14's problem with the signs of a0 and v_end turned (found with P21): the switch search ends
  // 7.8e-25 from the goal (the rounding of E at a goal of 0), and for two of the four sign pairs
  // the hold that covered such a residual at |v_end| = 3.4e-44 lasted 7.4e19 s. And the same with
  // V = 937.5, A+ = 7.48e-6, |v_end| = 9.0e-44 (found by fuzz_planner's detour bound): there the
  // push goes 1e-8 mm out and comes back, E carries the rounding of that path, and all four pairs
  // held for 1.1e19-1.2e20 s. A residual within 1e-11 of the switch's path (the push's and the
  // change's) is left as it is: every pair takes the plan to rest's time.
  struct Problem {
    Limits limits;
    double v_end;
    double duration;
  };
  const Problem problems[] = {
      {{1000.0, 7.6295109483482109e-06, 5312.5810635538264, 227389.94430457009},
       3.4331812393645485e-44,
       0.051009498038301328},
      {{937.49904631113145, 7.4769207293812475e-06, 5312.5810635538264, 227389.94430457009},
       8.9683101716788293e-44,
       0.051526377523177833},
  };
  for (const Problem& problem : problems) {
    for (const double a0 : {9.0626382848859386, -9.0626382848859386}) {
      for (const double sign : {1.0, -1.0}) {
        const double v_end = sign * problem.v_end;
        INFO("V = " << problem.limits.velocity << ", a0 = " << a0 << ", v_end = " << v_end);
        const KinematicState s{0.0, 0.0, a0};
        const Profile prof = planned(s, 0.0, v_end, problem.limits);
        CHECK(prof.duration() == Approx(problem.duration).epsilon(1e-12));
        const Profile rest = nc::plan_position(s, 0.0, problem.limits);
        CHECK(prof.duration() == Approx(rest.duration()).epsilon(1e-12));
      }
    }
  }
}

TEST_CASE("a residual of E's rounding after a long path is left as a step, not held at v_end",
          "[profile][end_velocity]") {
  // Found by fuzz_planner's detour bound (P23). P17's start with v_end = 1e-42, A- = 8.0e-9,
  // J = 7.0e-9: a residual of 1.3e-19 mm was held for 1.35e23 s. And from v = 31.24 with
  // a = 4.8e-4 to a target 3.05e-5 ahead at v_end = 1.1e-19 with A- = 2.3e-9: a run-up of
  // 2.1e11 mm out and back left 0.57 mm (1.3e-12 of its path), held for 5.3e18 s. Both are left
  // as a position step now (within 1e-11 of the path and the positions' scale); the plans take
  // 2.00001 s and 2.7e10 s, no longer than a path through rest (2.00029 s, 2.7e10 s).
  {
    const Limits l{1982014.243136033, 7.0415291166948042e-09, 8.0294609917413229e-09,
                   7.041529113169559e-09};
    const KinematicState s{6.5715143469463669e-110, 7.041529113169559e-09, 9.9741677046594516e-43};
    const Profile prof = planned(s, 7.0415291131643709e-09, 9.9741677046594516e-43, l);
    CHECK(prof.duration() == Approx(2.000012612928828).epsilon(1e-9));
  }
  {
    const Limits l{2589308.4901807462, 31.244602158483978, 2.2997679229248524e-09,
                   31.244602188890209};
    const KinematicState s{6.5715143469463327e-110, 31.244602158482163, 0.00047673244193634478};
    const Profile prof = planned(s, 3.0517567111197432e-05, 1.0842021724855044e-19, l);
    CHECK(prof.duration() == Approx(27171961006.876804).epsilon(1e-9));
    // The run-up: the stop at A- from 31.24 takes v / A- = 1.36e10 s, and the way back as long.
    CHECK(prof.duration() == Approx(2.0 * s.v / l.deceleration).epsilon(1e-6));
  }
}

TEST_CASE("the first switch inside a push piece that slows the motion is taken",
          "[profile][end_velocity]") {
  // Issue 14 item 1, the Bellman suite's seed 3: from v = -V = -3.29 with a = 4.8 to 0.072 mm
  // at 2.03 mm/s, J = 3.3. Along the push's first piece (which still brings a back) E(tau) rose
  // above the target and fell back below it, and the switch was taken at a later crossing: the
  // profile took 3.741 s, while re-planning from its state at 0.88 s reached the target in
  // 1.316 s. The first crossing gives 2.089 s, and re-planning from any sampled state gives the
  // rest of it.
  const Limits l{3.2898764527582767, 6546.635221418459, 20454.983581909062, 3.3288370245999088};
  const KinematicState s{0.0, -3.2898764527582767, 4.7973199386656624};
  const double target = 0.071945387924975804;
  const double v_end = 2.033291143442896;
  const Profile prof = planned(s, target, v_end, l);
  CHECK(prof.duration() == Approx(2.0892070007501911).epsilon(1e-9));
  for (double t : {0.3, 0.88, 1.2, 1.9}) {
    INFO("re-planned at t = " << t);
    const Profile rest = nc::plan_position(prof.at(t), target, v_end, l);
    REQUIRE(rest.ok());
    CHECK(std::abs(rest.duration() - (prof.duration() - t)) <= 1e-7 * prof.duration());
  }
}

TEST_CASE("an acceleration left on the final curve within rounding ramps to 0 at J",
          "[profile][end_velocity]") {
  // P15 (seed 1771, after 1.3e7 executions): v 2.1e-21 below v_end = 7.04e-9, a = 4e-40,
  // A+ = 2.06e-6, J = 4.77e-4, the target 1.6e-18 ahead. The push ended at a = 1.1e-13, on the
  // final curve within the rise's rounding tolerance but below the final ramp's, and the change
  // from there gave no piece: a jumped from 1.1e-13 to 0 (5e-8 of A+). Now the change ramps it
  // to 0 at -J (1.16e-10 s) and the profile is a rise and a fall of 1.16e-10 s each.
  const Limits l{1.8026314529717053e-06, 2.0574137664720906e-06, 7.0418701876165225e-09,
                 0.00047673244193634565};
  const Profile prof =
      planned({6.5715143469463669e-110, 7.041529113169559e-09, 3.9592891430598328e-40},
              1.6395921293743496e-18, 7.041529113171679e-09, l);
  REQUIRE(prof.segment_count() == 2);
  CHECK(prof.segment(1).j == -l.jerk);
  CHECK(prof.segment(1).duration == Approx(1.1642301714750205e-10).epsilon(1e-9));
  CHECK(prof.duration() == Approx(2.3284603429500409e-10).epsilon(1e-9));
}

TEST_CASE("a push hold along which E(tau) stays flat is searched from the end of that stretch",
          "[profile][end_velocity]") {
  // P17 (seed 1791): from v = 7.04e-9 to a target 7.04e-9 ahead passed at v_end = 1.1e-8, with
  // A+ ~ A- ~ 7.04e-9 and J = 1.4e6. The change from the push's hold (towards V, 2.8e14 s long)
  // to v_end holds the same A+ until v_end, so E(tau) stayed at E(0), 1.87e-9 short of the
  // target, for the first 0.571 s; the search ended inside that flat stretch, and continuity
  // broke by 1.87e-9. Now the search starts where the flat stretch ends: the velocity
  // overshoots v_end to the peak that covers the distance, then comes back at A-.
  const Limits l{1982014.243136033, 7.0415291132253573e-09, 7.0415291131581728e-09,
                 1392190.2470443724};
  const KinematicState s{6.5715143469463669e-110, 7.041529113169559e-09, 9.9741677046594516e-43};
  const double target = 7.0415291131643709e-09;
  const double v_end = 1.1061837756334599e-08;
  const Profile prof = planned(s, target, v_end, l);
  // The ramps last 5e-15 s: to 1e-6, a rise at A to v_peak and a fall at A back to v_end cover
  // the distance D, (v_peak^2 - v^2) / 2A + (v_peak^2 - v_end^2) / 2A = D.
  const double a = l.acceleration;
  const double d = target - s.p;
  const double v_peak = std::sqrt(a * d + 0.5 * (s.v * s.v + v_end * v_end));
  REQUIRE(prof.segment_count() == 5);
  CHECK(prof.segment(3).v == Approx(v_peak).epsilon(1e-6));
  CHECK(prof.segment(3).v == Approx(1.1642887341697178e-08).epsilon(1e-12));
  CHECK(prof.segment(3).a == -l.deceleration);
  const double expected = (v_peak - s.v) / a + (v_peak - v_end) / a;
  CHECK(prof.duration() == Approx(expected).epsilon(1e-6));
  CHECK(prof.duration() == Approx(0.73597761658926975).epsilon(1e-9));
  // Shorter than reaching v_end at A+ and holding it for the 1.87e-9 left (0.740 s).
  CHECK(prof.duration() < (v_end - s.v) / a + 1.8735378199693483e-09 / v_end - 1e-3);
}

TEST_CASE(
    "a target inside the jump with v_end away from the push holds v_end from the bracket's upper "
    "end",
    "[profile][end_velocity]") {
  // P21 (CI's 60 s run at a2f0d73): from v = 31.2446 with a = 4.8e-4, far above A± ~ 7.04e-9
  // (J = 1.36e6), to a target 3.05e-5 ahead passed at v_end = v + 7.3e-12 (2.3e-13 of v). The
  // direct change holds A+ for 1.0e-3 s and ends 0.0319 ahead, past the target: the push goes
  // the other way (v_end points away from it). Along the push's first ramp the change's rounding
  // tolerance takes v_end as reached (one ramp of 5e-15 s), and E(tau) jumps from 0.0319 to
  // 1.1e-8, past the target; the search ended in the jump and continuity broke by 3.04e-5.
  // Now the push ends at that upper end and v_end is held for the rest: the target is passed
  // after D / v_end.
  const Limits l{1982014.243136033, 7.0415291132253573e-09, 7.0415291131581728e-09,
                 1360190.2450903798};
  const KinematicState s{6.5715143469463669e-110, 31.244602158483072, 0.00047673244193634565};
  const double target = 3.0451428656484566e-05;
  const double v_end = 31.244602158490355;
  const Profile prof = planned(s, target, v_end, l);
  REQUIRE(prof.segment_count() == 3);
  // The start acceleration ramps to A+ at J (3.5e-10 s, 1.1e-8 mm), then the hold at v_end.
  CHECK(prof.segment(0).duration == Approx((s.a - l.acceleration) / l.jerk).epsilon(1e-6));
  CHECK(prof.segment(2).p == Approx(s.v * prof.segment(2).t0).epsilon(1e-9));
  check_ends_with_hold(prof, v_end, (target - prof.segment(2).p) / v_end);
  CHECK(prof.duration() == Approx(9.7461406299935058e-07).epsilon(1e-9));
  CHECK(prof.duration() == Approx(target / v_end).epsilon(1e-3));
}
