// Re-planning every cycle (issue 3, the way the NC re-plans on override and velocity changes):
// a stop or a velocity change re-planned from the state the previous plan reaches one cycle later,
// again and again, must add up to the first plan's duration. Bellman consistency re-plans once
// from the original profile; a chain re-plans from re-planned profiles, so a decision that flips
// between neighbouring states (a snap to the final ramp, a rounding-sized reversal) shows up here
// as many small extra pieces that add up.
// 200 cycles per problem, random feasible starts, asymmetric limits; tolerance 2e-8 of T.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "nc_core/profile.hpp"
#include "profile_checks.hpp"
#include "profile_problems.hpp"

namespace {

#ifdef NCSDK_SANITIZED
constexpr long kProblems = 1'000;
#else
constexpr long kProblems = 20'000;
#endif
constexpr int kCycles = 200;
constexpr double kRelative = 2e-8;

}  // namespace

TEST_CASE(
    "a stop or velocity change re-planned every cycle from the last plan's state ends when the "
    "first plan ends",
    "[profile][chain]") {
  const uint64_t seed = profile_problems::suite_seed(0xC4A1ull);
  profile_problems::Rng rng(seed);
  long failures = 0;
  double worst = 0.0;
  std::string example;
  for (long k = 0; k < kProblems; ++k) {
    const nc::Limits l = profile_problems::random_limits(rng);
    const nc::KinematicState start = profile_problems::random_feasible_state(rng, l, 0.0);
    const bool stop = rng.chance(0.3);
    const double v1 = stop ? 0.0 : rng.uniform(-l.velocity, l.velocity);
    auto plan = [&](const nc::KinematicState& x) {
      return stop ? nc::plan_stop(x, l.deceleration, l.jerk) : nc::plan_velocity(x, v1, l);
    };
    nc::Profile current = plan(start);
    const double T = current.duration();
    if (!current.ok() || !(T > 0.0)) {
      failures += current.ok() ? 0 : 1;
      continue;
    }
    // A cycle that does not divide T, so the chain ends inside a plan.
    const double cycle = T / kCycles * (1.0 + 1e-3 * rng.uniform());
    double elapsed = 0.0;
    bool ok = true;
    for (int n = 0; ok && current.duration() > cycle && n < 2 * kCycles; ++n) {
      current = plan(current.at(cycle));
      ok = current.ok();
      elapsed += cycle;
    }
    const double err = ok ? std::fabs(elapsed + current.duration() - T) / T : 1.0;
    worst = std::max(worst, err);
    if (err > kRelative) {
      ++failures;
      if (example.empty()) {
        char buf[160];
        std::snprintf(buf, sizeof buf, " velocity=%.17g: chained %.17g, first plan %.17g", v1,
                      elapsed + current.duration(), T);
        example =
            profile_checks::describe_problem(stop ? "plan_stop" : "plan_velocity", start, 0.0, l) +
            buf;
      }
    }
  }
  std::printf(
      "[re-plan chain] seed 0x%016llx: %ld problems x %d cycles, %ld failures, worst "
      "|chained - T| / T = %.3g\n",
      static_cast<unsigned long long>(seed), kProblems, kCycles, failures, worst);
  if (!example.empty()) std::printf("  %s\n", example.c_str());
  CHECK(failures == 0);
}
