// The problem sets of bench_planner (issue 3), shared with planner_instructions: fixed random
// sets (seed 20240503, 4096 problems each) of rest to rest, any feasible state to rest, any
// feasible state to a target passed at a velocity (issue 14), and velocity changes, with
// distances 1e-6…1e5 mm, V 1e-2…1e5 mm/s, A 1e-1…1e7 mm/s², J 1…1e9 mm/s³ (log-uniform).
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "nc_core/profile.hpp"

namespace planner_sets {

inline constexpr std::uint64_t kSeed = 20240503;
inline constexpr std::size_t kSetSize = 4096;

struct Problem {
  nc::KinematicState start;
  double target = 0.0;  // position, or velocity for the velocity set
  nc::Limits limits;
  double end_velocity = 0.0;  // the passing set's v_end (never 0 there)
};

class Draw {
 public:
  explicit Draw(std::uint64_t seed) : rng_(seed) {}
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  double sign() { return uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0; }
  nc::Limits limits() {
    nc::Limits l;
    l.velocity = log_uniform(1e-2, 1e5);
    l.acceleration = log_uniform(1e-1, 1e7);
    l.deceleration = log_uniform(1e-1, 1e7);
    l.jerk = log_uniform(1.0, 1e9);
    return l;
  }
  double distance() { return sign() * log_uniform(1e-6, 1e5); }
  // A feasible moving state: one taken from another time-optimal profile with the same limits.
  nc::KinematicState moving_state(const nc::Limits& l) {
    const double d = distance();
    const nc::Profile other = nc::plan_position({-d * uniform(0.0, 1.0), 0.0, 0.0}, d, l);
    nc::KinematicState s = other.at(uniform(0.0, other.duration()));
    s.p = 0.0;
    return s;
  }

 private:
  std::mt19937_64 rng_;
};

// kSetSize problems drawn with `seed`, each filled by `fill(draw, problem)` in order.
template <class Fill>
std::vector<Problem> draw_set(std::uint64_t seed, Fill fill) {
  Draw draw(seed);
  std::vector<Problem> v(kSetSize);
  for (Problem& q : v)
    fill(draw, q);
  return v;
}

inline const std::vector<Problem>& rest_set() {
  static const std::vector<Problem> set = draw_set(kSeed, [](Draw& draw, Problem& q) {
    q.limits = draw.limits();
    q.target = draw.distance();
  });
  return set;
}

// Limits, a feasible moving start and a target distance: the state set's problem.
inline void draw_moving(Draw& draw, Problem& q) {
  q.limits = draw.limits();
  q.start = draw.moving_state(q.limits);
  q.target = draw.distance();
}

inline const std::vector<Problem>& state_set() {
  static const std::vector<Problem> set = draw_set(kSeed + 1, draw_moving);
  return set;
}

inline const std::vector<Problem>& passing_set() {
  static const std::vector<Problem> set = draw_set(kSeed + 3, [](Draw& draw, Problem& q) {
    draw_moving(draw, q);
    const double u = draw.uniform(-1.0, 1.0);
    q.end_velocity = (u != 0.0 ? u : 1.0) * q.limits.velocity;
  });
  return set;
}

inline const std::vector<Problem>& velocity_set() {
  static const std::vector<Problem> set = draw_set(kSeed + 2, [](Draw& draw, Problem& q) {
    q.limits = draw.limits();
    q.start = draw.moving_state(q.limits);
    q.target = draw.uniform(-1.0, 1.0) * q.limits.velocity;
  });
  return set;
}

}  // namespace planner_sets
