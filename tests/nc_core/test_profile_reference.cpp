// The planner against a slow, obviously-correct reference for rest-to-rest moves
// (tests/support/reference_planner.hpp). The reference is first shown to be right on its own —
// it gives the seed's figures and its phases, integrated, are a valid motion to the target — and
// then the planner's durations must equal it to 1e-9 relative: never longer (not optimal), never
// shorter (impossible, so a limit must have been broken).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "nc_core/profile.hpp"
#include "profile_checks.hpp"
#include "profile_problems.hpp"
#include "reference_planner.hpp"

namespace {

using nc::Limits;
using profile_problems::Rng;

#ifdef NCSDK_SANITIZED
constexpr long kProblems = 20'000;
#else
constexpr long kProblems = 300'000;
#endif

constexpr double kRelative = 1e-9;

// Integrates the reference's pieces with the same constant-jerk formula the checks use.
nc::KinematicState integrate(const std::array<reference::Piece, 7>& pieces, double& peak_v,
                             double& peak_a_plus, double& peak_a_minus) {
  nc::Segment s;
  peak_v = peak_a_plus = peak_a_minus = 0.0;
  for (const reference::Piece& pc : pieces) {
    s.j = pc.jerk;
    const nc::KinematicState e = profile_checks::advance(s, pc.duration);
    s.p = e.p;
    s.v = e.v;
    s.a = e.a;
    peak_v = std::max(peak_v, std::fabs(s.v));
    // In a rest-to-rest move in + direction, a > 0 grows |v|, a < 0 shrinks it.
    peak_a_plus = std::max(peak_a_plus, s.a * (s.v >= 0.0 ? 1.0 : -1.0));
    peak_a_minus = std::max(peak_a_minus, -s.a * (s.v >= 0.0 ? 1.0 : -1.0));
  }
  return {s.p, s.v, s.a};
}

}  // namespace

TEST_CASE("the reference gives the seed's Dynamics figures", "[profile][reference]") {
  // Seed 000 §2.1, Dynamics I-III (A, J, V, distance -> duration).
  CHECK(reference::rest_to_rest(1000.0, {2000.0, 5000.0, 5000.0, 50000.0}).duration ==
        Approx(1.0).epsilon(1e-12));
  CHECK(reference::rest_to_rest(1000.0, {2000.0, 5000.0, 10000.0, 50000.0}).duration ==
        Approx(0.95).epsilon(1e-12));
  CHECK(reference::rest_to_rest(1000.0, {2000.0, 15000.0, 15000.0, 50000.0}).duration ==
        Approx(0.9).epsilon(1e-12));
  CHECK(reference::rest_to_rest(1000.0, {2000.0, 5000.0, 5000.0, 20000.0}).duration ==
        Approx(1.178708781).epsilon(1e-9));
  CHECK(reference::rest_to_rest(1000.0, {2000.0, 5000.0, 5000.0, 100000.0}).duration ==
        Approx(0.95).epsilon(1e-12));
  CHECK(reference::rest_to_rest(800.0, {1500.0, 5000.0, 5000.0, 50000.0}).duration ==
        Approx(0.933333333).epsilon(1e-9));
  CHECK(reference::rest_to_rest(800.0, {1750.0, 5000.0, 5000.0, 50000.0}).duration ==
        Approx(0.907142857).epsilon(1e-9));
  CHECK(reference::rest_to_rest(-800.0, {2000.0, 5000.0, 5000.0, 50000.0}).duration ==
        Approx(0.906225775).epsilon(1e-9));
}

TEST_CASE("the reference's phases are a valid motion that ends at rest at the target",
          "[profile][reference]") {
  Rng rng(0x4EFull);
  long bad = 0;
  for (int k = 0; k < 20000; ++k) {
    const Limits l = profile_problems::random_limits(rng);
    const double d = profile_problems::random_distance(rng);
    double pv = 0.0;
    double pa_plus = 0.0;
    double pa_minus = 0.0;
    const nc::KinematicState e =
        integrate(reference::rest_to_rest_pieces(d, l), pv, pa_plus, pa_minus);
    const bool good = std::fabs(e.p - d) <= 1e-9 * std::fabs(d) &&
                      std::fabs(e.v) <= 1e-9 * l.velocity &&
                      std::fabs(e.a) <= 1e-9 * std::max(l.acceleration, l.deceleration) &&
                      pv <= l.velocity * (1.0 + 1e-9) && pa_plus <= l.acceleration * (1.0 + 1e-9) &&
                      pa_minus <= l.deceleration * (1.0 + 1e-9);
    if (!good && bad++ < 5) {
      FAIL_CHECK(profile_checks::describe_problem("reference", {}, d, l)
                 << " ends at p=" << e.p << " v=" << e.v << " a=" << e.a);
    }
  }
  CHECK(bad == 0);
}

namespace {

// Planner durations against the reference's: counts, worst deviations, the first examples.
struct DurationTally {
  long compared = 0;
  long longer = 0;
  long shorter = 0;
  long not_ok = 0;
  double worst_longer = 0.0;
  double worst_shorter = 0.0;
  std::vector<std::string> examples;

  // `slack`: relative tolerance beyond kRelative; `problem` describes the problem for a failure.
  template <class Describe>
  void add(const nc::Profile& prof, double ref, double slack, Describe problem) {
    ++compared;
    if (!prof.ok()) {
      ++not_ok;
      return;
    }
    const double rel = (prof.duration() - ref) / ref;
    worst_longer = std::max(worst_longer, rel);
    worst_shorter = std::max(worst_shorter, -rel);
    if (std::fabs(rel) <= kRelative + slack) return;
    (rel > 0.0 ? longer : shorter)++;
    if (examples.size() < 8) {
      char buf[128];
      std::snprintf(buf, sizeof buf, "\n    -> planner %.17g s, reference %.17g s", prof.duration(),
                    ref);
      examples.push_back(problem() + buf);
    }
  }
  void print(const char* name, uint64_t seed) const {
    std::printf(
        "[%s] seed 0x%016llx: %ld problems, %ld longer, %ld shorter than the reference "
        "(tolerance %.0e), %ld not ok; worst: %.3g longer, %.3g shorter (relative)\n",
        name, static_cast<unsigned long long>(seed), compared, longer, shorter, kRelative, not_ok,
        worst_longer, worst_shorter);
    for (const std::string& s : examples)
      std::printf("  %s\n", s.c_str());
    std::fflush(stdout);
  }
};

}  // namespace

TEST_CASE("rest-to-rest durations equal the reference's: never longer, never shorter",
          "[profile][reference]") {
  const uint64_t seed = profile_problems::suite_seed(0x4EF4E5ull);
  Rng rng(seed);
  DurationTally tally;
  for (long k = 0; k < kProblems; ++k) {
    const Limits l = profile_problems::random_limits(rng);
    const double p0 = profile_problems::random_position(rng);
    const double target = p0 + profile_problems::random_distance(rng);
    const nc::Profile prof = nc::plan_position({p0, 0.0, 0.0}, target, l);
    // The reference is given the distance the planner really has to cover (target - p0 rounds).
    const double ref = reference::rest_to_rest(target - p0, l).duration;
    tally.add(prof, ref, 0.0, [&] {
      return profile_checks::describe_problem("rest-to-rest", {p0, 0.0, 0.0}, target, l);
    });
  }
  tally.print("reference, rest to rest", seed);
  CHECK(tally.compared == kProblems);
  CHECK(tally.not_ok == 0);
  CHECK(tally.longer == 0);
  CHECK(tally.shorter == 0);
}

TEST_CASE("durations to a target passed at a velocity equal the reference's (no reversal)",
          "[profile][reference]") {
  // Issue 14: from (v0, 0) to (target, v_end, 0), same direction, through one velocity peak or
  // trough (reference::through_extreme); problems that need a reversal are drawn again.
  const uint64_t seed = profile_problems::suite_seed(0x4EFB1E4Dull);
  Rng rng(seed);
  DurationTally tally;
  while (tally.compared < kProblems / 3) {
    const Limits l = profile_problems::random_limits(rng);
    const double dir = rng.sign();
    const double v0 = rng.chance(0.3) ? 0.0 : l.velocity * rng.uniform();
    const double v_end = rng.chance(0.2) ? l.velocity : l.velocity * rng.uniform(1e-6, 1.0);
    const double p0 = profile_problems::random_position(rng);
    const double target = p0 + dir * rng.log_uniform(1e-6, 1e5);
    const double ref = reference::through_extreme(v0, v_end, dir * (target - p0), l);
    if (std::isnan(ref)) continue;
    const nc::Profile prof = nc::plan_position({p0, dir * v0, 0.0}, target, dir * v_end, l);
    // Arriving within the end-position tolerance of the target at v_end is arriving: the
    // durations may also differ by the time that tolerance takes at v_end (a passing motion's
    // duration is only as exact as its end position, unlike one that ends at rest), and by what a
    // few ulp of the velocities move a hold at the smaller acceleration bound (both sides compute
    // such a hold from a difference of close velocities: 1e-12 s at 12000 mm/s and A- 0.7).
    const double slack =
        (profile_checks::end_position_tolerance({p0, 0.0, 0.0}, target) / v_end +
         4.0 * DBL_EPSILON * std::max(v0, v_end) / std::min(l.acceleration, l.deceleration)) /
        ref;
    tally.add(prof, ref, slack, [&] {
      return profile_checks::describe_passing_problem("passing", {p0, dir * v0, 0.0}, target,
                                                      dir * v_end, l);
    });
  }
  tally.print("reference, end velocity", seed);
  CHECK(tally.not_ok == 0);
  CHECK(tally.longer == 0);
  CHECK(tally.shorter == 0);
}
