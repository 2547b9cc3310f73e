// Random planner problems for the property, Bellman and reference tests (tests only).
//
// The generator is our own 64-bit SplitMix so that a seed gives the same problems with every
// standard library. Magnitudes are log-uniform over the ranges of the issue (mm units): distance
// 1e-6…1e5 mm, V 1e-2…1e5 mm/s, A± 1e-1…1e7 mm/s² (asymmetric too), J 1…1e9 mm/s³.
// A feasible start state is one from which the limits can be kept: |v0| <= V, |a0| within its
// path-relative bound, and ramping a to 0 at J neither overshoots V nor crosses v = 0 with |a|
// above A+ (SPEC B2: while |v| grows |a| <= A+).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "nc_core/profile.hpp"

namespace profile_problems {

class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  bool chance(double p) { return uniform() < p; }
  double sign() { return chance(0.5) ? 1.0 : -1.0; }

 private:
  uint64_t state_;
};

// The seed of a suite: the fixed default, or NCSDK_PROFILE_SEED from the environment to explore.
inline uint64_t suite_seed(uint64_t fixed) {
  if (const char* s = std::getenv("NCSDK_PROFILE_SEED")) return std::strtoull(s, nullptr, 0);
  return fixed;
}

inline nc::Limits random_limits(Rng& rng) {
  nc::Limits l;
  l.velocity = rng.log_uniform(1e-2, 1e5);
  l.acceleration = rng.log_uniform(1e-1, 1e7);
  l.deceleration = rng.chance(0.3) ? l.acceleration : rng.log_uniform(1e-1, 1e7);
  l.jerk = rng.log_uniform(1.0, 1e9);
  return l;
}

inline double random_distance(Rng& rng) {
  return rng.sign() * rng.log_uniform(1e-6, 1e5);
}

inline double random_position(Rng& rng) {
  return rng.chance(0.5) ? 0.0 : rng.sign() * rng.log_uniform(1e-3, 1e5);
}

// Path-relative range of a0 (positive = |v| grows) at speed |v| = s: [-shrink, grow].
struct AccelerationRange {
  double grow = 0.0;
  double shrink = 0.0;
};

inline AccelerationRange feasible_acceleration_range(double speed, const nc::Limits& l) {
  const double V = l.velocity;
  const double J = l.jerk;
  AccelerationRange r;
  // Growing: ramping a down at J adds a²/(2J) to |v|, which must stay <= V.
  r.grow = std::min(l.acceleration, std::sqrt(2.0 * J * std::max(0.0, V - speed)));
  if (speed == 0.0) {
    r.shrink = r.grow;  // at rest both directions are "growing"
    return r;
  }
  // Shrinking: |a| <= A-; if v crosses 0 while a ramps to 0, |a| there is sqrt(a0² - 2J|v0|),
  // which must be <= A+, and the reverse speed reached, a0²/(2J) - |v0|, must stay <= V.
  r.shrink = std::min({l.deceleration, std::sqrt(2.0 * J * (V + speed)),
                       std::sqrt(l.acceleration * l.acceleration + 2.0 * J * speed)});
  return r;
}

// A feasible start at position p: edge cases (at V, at rest, a at its bound) on purpose.
inline nc::KinematicState random_feasible_state(Rng& rng, const nc::Limits& l, double p) {
  const double u = rng.uniform();
  double speed;
  if (u < 0.12) {
    speed = l.velocity;
  } else if (u < 0.2) {
    speed = 0.0;
  } else if (u < 0.45) {
    speed = l.velocity * rng.log_uniform(1e-6, 1.0);
  } else {
    speed = l.velocity * rng.uniform();
  }
  const AccelerationRange r = feasible_acceleration_range(speed, l);
  const double w = rng.uniform();
  double a_path;
  if (w < 0.12) {
    a_path = r.grow;
  } else if (w < 0.24) {
    a_path = -r.shrink;
  } else if (w < 0.32) {
    a_path = 0.0;
  } else {
    a_path = rng.uniform(-r.shrink, r.grow);
  }
  const double dir = rng.sign();
  return {p, dir * speed, dir * a_path};
}

struct Problem {
  nc::KinematicState start;
  double target = 0.0;
  nc::Limits limits;
};

// From rest with probability rest_share, otherwise from a feasible moving state.
inline Problem random_position_problem(Rng& rng, double rest_share) {
  Problem pr;
  pr.limits = random_limits(rng);
  const double p0 = random_position(rng);
  pr.start = rng.chance(rest_share) ? nc::KinematicState{p0, 0.0, 0.0}
                                    : random_feasible_state(rng, pr.limits, p0);
  pr.target = p0 + random_distance(rng);
  return pr;
}

// An end velocity for plan_position's four-argument call: either sign, never 0, ±V included.
inline double random_end_velocity(Rng& rng, const nc::Limits& l) {
  const double u = rng.uniform();
  if (u < 0.15) return rng.sign() * l.velocity;
  if (u < 0.3) return rng.sign() * l.velocity * rng.log_uniform(1e-6, 1.0);
  const double v = rng.uniform(-l.velocity, l.velocity);
  return v != 0.0 ? v : l.velocity;
}

}  // namespace profile_problems
