// Planner speed over fixed random problem sets (issue 3): rest to rest, any feasible state to
// rest, any feasible state to a target passed at a velocity (issue 14), and velocity changes, with
// distances 1e-6…1e5 mm, V 1e-2…1e5 mm/s, A 1e-1…1e7 mm/s², J 1…1e9 mm/s³ (log-uniform). Besides
// Google Benchmark's mean time per plan, each benchmark reports the median and the 99th percentile
// over the set (counters median_ns, p99_ns): every problem is timed alone, as the mean of a few
// repeated plans.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "nc_core/profile.hpp"
#include "planner_sets.hpp"

namespace {

using planner_sets::passing_set;
using planner_sets::Problem;
using planner_sets::rest_set;
using planner_sets::state_set;
using planner_sets::velocity_set;

nc::Profile plan_position(const Problem& q) {
  return nc::plan_position(q.start, q.target, q.limits);
}
nc::Profile plan_passing(const Problem& q) {
  return nc::plan_position(q.start, q.target, q.end_velocity, q.limits);
}
nc::Profile plan_velocity(const Problem& q) {
  return nc::plan_velocity(q.start, q.target, q.limits);
}

// Times every problem alone (mean of kRepeat plans) and reports median and p99 in ns.
template <class Plan>
void report_distribution(benchmark::State& state, const std::vector<Problem>& set, Plan plan) {
  constexpr int kRepeat = 16;
  std::vector<double> ns;
  ns.reserve(set.size());
  for (const Problem& q : set) {
    const auto t0 = std::chrono::steady_clock::now();
    for (int r = 0; r < kRepeat; ++r) {
      nc::Profile p = plan(q);
      benchmark::DoNotOptimize(p);
    }
    const auto t1 = std::chrono::steady_clock::now();
    ns.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / kRepeat);
  }
  std::sort(ns.begin(), ns.end());
  state.counters["median_ns"] = ns[ns.size() / 2];
  state.counters["p99_ns"] = ns[ns.size() * 99 / 100];
  state.counters["max_ns"] = ns.back();
}

template <class Plan>
void run(benchmark::State& state, const std::vector<Problem>& set, Plan plan) {
  std::size_t i = 0;
  for (auto _ : state) {
    nc::Profile p = plan(set[i]);
    benchmark::DoNotOptimize(p);
    if (++i == set.size()) i = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  report_distribution(state, set, plan);
}

void BM_PlanPositionRestToRest(benchmark::State& state) {
  run(state, rest_set(), plan_position);
}
void BM_PlanPositionFromAnyState(benchmark::State& state) {
  run(state, state_set(), plan_position);
}
void BM_PlanPositionPassingAtVelocity(benchmark::State& state) {
  run(state, passing_set(), plan_passing);
}
void BM_PlanVelocity(benchmark::State& state) {
  run(state, velocity_set(), plan_velocity);
}

}  // namespace

BENCHMARK(BM_PlanPositionRestToRest);
BENCHMARK(BM_PlanPositionFromAnyState);
BENCHMARK(BM_PlanPositionPassingAtVelocity);
BENCHMARK(BM_PlanVelocity);
BENCHMARK_MAIN();
