// Random property suite of the planner (issue 3): a million position problems over the whole mm
// range of the issue, from rest and from arbitrary feasible states, plus velocity and stop
// problems. Every profile must be ok, finite, continuous, inside V, the path-relative A± and J
// (exactly, per segment: see profile_checks.hpp), and end at the requested state:
// |p - target| <= 1e-9·max(1, |p0|, |target|) + 1e-8 mm, v and a zero to 1e-9 of V and A.
// The seed is fixed and printed; failures are counted by kind and the first ones printed with
// full precision for reproduction (NCSDK_PROFILE_SEED=<n> explores another seed).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "nc_core/profile.hpp"
#include "profile_checks.hpp"
#include "profile_problems.hpp"

namespace {

using profile_checks::Check;
using profile_checks::Extremes;
using profile_checks::Finding;
using profile_problems::Rng;

#ifdef NCSDK_SANITIZED
constexpr long kPositionProblems = 30'000;
constexpr long kVelocityProblems = 6'000;
constexpr long kStopProblems = 3'000;
constexpr long kOutsideProblems = 3'000;
constexpr long kPassingProblems = 20'000;
#else
constexpr long kPositionProblems = 1'000'000;
constexpr long kVelocityProblems = 200'000;
constexpr long kStopProblems = 100'000;
constexpr long kOutsideProblems = 200'000;
constexpr long kPassingProblems = 300'000;
#endif

constexpr int kPrintedFailures = 8;

// Failures by kind, the first few problems, and the largest errors seen.
class Tally {
 public:
  explicit Tally(const char* suite) : suite_(suite) {}

  void record(const Finding& f, const std::string& problem) {
    ++problems_;
    if (f.ok()) return;
    ++failures_;
    ++by_check_[static_cast<std::size_t>(f.check)];
    if (examples_.size() < kPrintedFailures)
      examples_.push_back(problem + "\n    -> " + profile_checks::to_string(f));
  }
  bool needs_example() const { return examples_.size() < kPrintedFailures; }

  void print(uint64_t seed, const Extremes& e) const {
    std::printf("[%s] seed 0x%016llx: %ld problems, %ld failures\n", suite_,
                static_cast<unsigned long long>(seed), problems_, failures_);
    for (std::size_t i = 1; i < by_check_.size(); ++i)
      if (by_check_[i] > 0)
        std::printf("    %-17s %ld\n", profile_checks::check_name(static_cast<Check>(i)),
                    by_check_[i]);
    std::printf(
        "    worst (value/limit - 1): v %.3g, a %.3g beyond rounding (raw %.3g), j %.3g; worst "
        "end error: p %.3g (of max(1,|p0|,|target|,|p| on the way)), v %.3g (of V), a %.3g (of "
        "A); worst jump %.3g\n",
        e.velocity, e.acceleration_net, e.acceleration, e.jerk, e.end_position, e.end_velocity,
        e.end_acceleration, e.continuity);
    for (const std::string& s : examples_)
      std::printf("  %s\n", s.c_str());
    std::fflush(stdout);
  }
  long failures() const { return failures_; }
  long problems() const { return problems_; }

 private:
  const char* suite_;
  long problems_ = 0;
  long failures_ = 0;
  std::array<long, static_cast<std::size_t>(Check::kCount)> by_check_{};
  std::vector<std::string> examples_;
};

}  // namespace

TEST_CASE("a million random position problems end exactly at rest and never exceed a limit",
          "[profile][random]") {
  const uint64_t seed = profile_problems::suite_seed(0x1D0C5EEDull);
  Rng rng(seed);
  Tally tally("plan_position");
  Extremes worst;
  for (long k = 0; k < kPositionProblems; ++k) {
    // Half from rest, half from an arbitrary feasible state (moving toward, away, at V, ...).
    const profile_problems::Problem pr = profile_problems::random_position_problem(rng, 0.5);
    const nc::Profile prof = nc::plan_position(pr.start, pr.target, pr.limits);
    Extremes e;
    const Finding f =
        profile_checks::check_position_profile(prof, pr.start, pr.target, pr.limits, {}, {}, &e);
    worst.merge(e);
    tally.record(
        f, f.ok() || !tally.needs_example()
               ? std::string()
               : profile_checks::describe_problem("plan_position", pr.start, pr.target, pr.limits));
  }
  tally.print(seed, worst);
  CHECK(tally.problems() == kPositionProblems);
  CHECK(tally.failures() == 0);
}

TEST_CASE("random position problems with an end velocity end exactly on it within the limits",
          "[profile][random]") {
  const uint64_t seed = profile_problems::suite_seed(0xB1E4DEDull);
  Rng rng(seed);
  Tally tally("plan_position to a moving target state");
  Extremes worst;
  for (long k = 0; k < kPassingProblems; ++k) {
    const profile_problems::Problem pr = profile_problems::random_position_problem(rng, 0.3);
    const double v_end = profile_problems::random_end_velocity(rng, pr.limits);
    const nc::Profile prof = nc::plan_position(pr.start, pr.target, v_end, pr.limits);
    Extremes e;
    const Finding f = profile_checks::check_passing_profile(prof, pr.start, pr.target, v_end,
                                                            pr.limits, {}, {}, &e);
    worst.merge(e);
    tally.record(f, f.ok() || !tally.needs_example()
                        ? std::string()
                        : profile_checks::describe_passing_problem("plan_position", pr.start,
                                                                   pr.target, v_end, pr.limits));
  }
  tally.print(seed, worst);
  CHECK(tally.problems() == kPassingProblems);
  CHECK(tally.failures() == 0);
}

namespace {

// A start outside the limits (SPEC B2): above V with a not pushing |v| further up, or |a| above
// its path-relative bound (up to 3x) without a forced overshoot of V or a forced reversal above
// A+. Returns false when the drawn speed leaves no such acceleration.
bool random_outside_state(Rng& rng, const nc::Limits& l, nc::KinematicState& s,
                          profile_checks::StartRelief& relief) {
  const double V = l.velocity;
  const double J = l.jerk;
  const double dir = rng.sign();
  relief = {};
  if (rng.chance(0.4)) {
    // Above V (a lower override or a new velocity), braking or not accelerating.
    const double speed = V * rng.uniform(1.0 + 1e-6, 3.0);
    const profile_problems::AccelerationRange r =
        profile_problems::feasible_acceleration_range(speed, l);
    s.v = dir * speed;
    s.a = rng.chance(0.3) ? 0.0 : -dir * rng.uniform(0.0, r.shrink);
    relief.over_speed = true;
    return true;
  }
  relief.over_acceleration = true;
  if (rng.chance(0.5)) {
    // Growing |v| with a above A+, but ramping a down at J still stays within V.
    const double speed = V * rng.uniform();
    const double cap = std::min(3.0 * l.acceleration, std::sqrt(2.0 * J * (V - speed)));
    if (!(cap > l.acceleration * (1.0 + 1e-6))) return false;
    s.v = dir * speed;
    s.a = dir * rng.uniform(l.acceleration * (1.0 + 1e-6), cap);
    return true;
  }
  // Shrinking |v| with a above A-, without a forced reversal beyond V or through v = 0 above A+.
  const double speed = V * rng.uniform(1e-3, 1.0);
  const double cap = std::min({3.0 * l.deceleration, std::sqrt(2.0 * J * (V + speed)),
                               std::sqrt(l.acceleration * l.acceleration + 2.0 * J * speed)});
  if (!(cap > l.deceleration * (1.0 + 1e-6))) return false;
  s.v = dir * speed;
  s.a = -dir * rng.uniform(l.deceleration * (1.0 + 1e-6), cap);
  return true;
}

}  // namespace

TEST_CASE("random starts outside the limits come back inside as the limits allow and end exactly",
          "[profile][random]") {
  const uint64_t seed = profile_problems::suite_seed(0x0075D1DEull);
  Rng rng(seed);
  Tally tally("plan_position, start outside the limits");
  Extremes worst;
  long k = 0;
  while (k < kOutsideProblems) {
    const nc::Limits l = profile_problems::random_limits(rng);
    nc::KinematicState start{profile_problems::random_position(rng), 0.0, 0.0};
    profile_checks::StartRelief relief;
    if (!random_outside_state(rng, l, start, relief)) continue;
    ++k;
    const double target = start.p + profile_problems::random_distance(rng);
    const nc::Profile prof = nc::plan_position(start, target, l);
    Extremes e;
    const Finding f =
        profile_checks::check_position_profile(prof, start, target, l, {}, relief, &e);
    worst.merge(e);
    tally.record(f, f.ok() || !tally.needs_example()
                        ? std::string()
                        : profile_checks::describe_problem("plan_position", start, target, l));
  }
  tally.print(seed, worst);
  CHECK(tally.failures() == 0);
}

TEST_CASE("random starts outside the limits reach a target at an end velocity exactly",
          "[profile][random]") {
  const uint64_t seed = profile_problems::suite_seed(0x0B1E0075ull);
  Rng rng(seed);
  Tally tally("plan_position to a moving target state, start outside the limits");
  Extremes worst;
  long k = 0;
  while (k < kOutsideProblems / 2) {
    const nc::Limits l = profile_problems::random_limits(rng);
    nc::KinematicState start{profile_problems::random_position(rng), 0.0, 0.0};
    profile_checks::StartRelief relief;
    if (!random_outside_state(rng, l, start, relief)) continue;
    ++k;
    const double target = start.p + profile_problems::random_distance(rng);
    const double v_end = profile_problems::random_end_velocity(rng, l);
    const nc::Profile prof = nc::plan_position(start, target, v_end, l);
    Extremes e;
    const Finding f =
        profile_checks::check_passing_profile(prof, start, target, v_end, l, {}, relief, &e);
    worst.merge(e);
    tally.record(f, f.ok() || !tally.needs_example()
                        ? std::string()
                        : profile_checks::describe_passing_problem("plan_position", start, target,
                                                                   v_end, l));
  }
  tally.print(seed, worst);
  CHECK(tally.failures() == 0);
}

TEST_CASE("random velocity problems reach the velocity exactly and never exceed a limit",
          "[profile][random]") {
  const uint64_t seed = profile_problems::suite_seed(0x7E10C17Eull);
  Rng rng(seed);
  Tally tally("plan_velocity");
  Extremes worst;
  for (long k = 0; k < kVelocityProblems; ++k) {
    const nc::Limits l = profile_problems::random_limits(rng);
    const nc::KinematicState start =
        profile_problems::random_feasible_state(rng, l, profile_problems::random_position(rng));
    // Target velocity: either sign, the edges 0 and ±V included.
    const double u = rng.uniform();
    const double v_target = u < 0.1    ? 0.0
                            : u < 0.25 ? rng.sign() * l.velocity
                                       : rng.uniform(-l.velocity, l.velocity);
    const nc::Profile prof = nc::plan_velocity(start, v_target, l);
    Extremes e;
    const Finding f = profile_checks::check_velocity_profile(prof, start, v_target, l, {}, {}, &e);
    worst.merge(e);
    std::string problem;
    if (!f.ok() && tally.needs_example()) {
      char buf[64];
      std::snprintf(buf, sizeof buf, " velocity=%.17g", v_target);
      problem = profile_checks::describe_problem("plan_velocity", start, start.p, l) + buf;
    }
    tally.record(f, problem);
  }
  tally.print(seed, worst);
  CHECK(tally.failures() == 0);
}

TEST_CASE("random stops end at rest, decelerate within the limit and never exceed the jerk",
          "[profile][random]") {
  const uint64_t seed = profile_problems::suite_seed(0x5707ull);
  Rng rng(seed);
  Tally tally("plan_stop");
  Extremes worst;
  for (long k = 0; k < kStopProblems; ++k) {
    const nc::Limits l = profile_problems::random_limits(rng);
    const nc::KinematicState start =
        profile_problems::random_feasible_state(rng, l, profile_problems::random_position(rng));
    // The stop uses A- and J only; the start is feasible for l, so |a0| may exceed A- only
    // while |v| grows (then it is <= A+): the stop ramps that down at J.
    const nc::Profile prof = nc::plan_stop(start, l.deceleration, l.jerk);
    nc::Limits check_limits = l;
    check_limits.acceleration = std::max(l.acceleration, l.deceleration);
    Finding f = profile_checks::check_structure(prof, start);
    Extremes e;
    if (f.ok()) {
      // The stop position is the planner's to choose; everything else is checked.
      const double stop_at = prof.final_state().p;
      const profile_checks::Scales sc = profile_checks::scales_for(start, stop_at, l);
      f = profile_checks::check_continuity(prof, sc, {}, &e);
      if (f.ok()) f = profile_checks::check_end(prof, start, stop_at, 0.0, sc, {}, &e);
      if (f.ok()) f = profile_checks::check_limits(prof, check_limits, {}, {}, &e);
      if (f.ok()) f = profile_checks::check_at(prof, sc);
    }
    worst.merge(e);
    tally.record(f, f.ok() || !tally.needs_example()
                        ? std::string()
                        : profile_checks::describe_problem("plan_stop", start, 0.0, l));
  }
  tally.print(seed, worst);
  CHECK(tally.failures() == 0);
}
