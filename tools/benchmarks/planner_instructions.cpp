// One pass of the planner over bench_planner's problem sets for instruction counts, which (unlike
// the benchmark's times) do not depend on the load of the machine (issue 17):
//
//   valgrind --tool=callgrind --toggle-collect='plan_set*' planner_instructions state
//
// Argument: the set, "rest", "state" (any feasible state to rest), "passing" or "velocity".
// Instructions per plan = the collected total / 4096. The count includes the call from the loop
// and the returned Profile (docs/performance.md, "Planner").
#include <cstdio>
#include <cstring>
#include <vector>

#include "nc_core/profile.hpp"
#include "planner_sets.hpp"

namespace {

// Plans every problem of `set` (kept out of line so that callgrind can collect it alone).
template <class Plan>
[[gnu::noinline]] double plan_set(const std::vector<planner_sets::Problem>& set, Plan plan) {
  double sum = 0.0;
  for (const planner_sets::Problem& q : set) {
    const nc::Profile p = plan(q);
    sum += p.duration();
  }
  return sum;
}

nc::Profile to_rest(const planner_sets::Problem& q) {
  return nc::plan_position(q.start, q.target, q.limits);
}
nc::Profile passing(const planner_sets::Problem& q) {
  return nc::plan_position(q.start, q.target, q.end_velocity, q.limits);
}
nc::Profile to_velocity(const planner_sets::Problem& q) {
  return nc::plan_velocity(q.start, q.target, q.limits);
}

}  // namespace

int main(int argc, char** argv) {
  const char* which = argc > 1 ? argv[1] : "state";
  // The sets are drawn before the collected loop (drawing plans the moving starts).
  double sum = 0.0;
  if (std::strcmp(which, "rest") == 0) {
    const auto& set = planner_sets::rest_set();
    sum = plan_set(set, to_rest);
  } else if (std::strcmp(which, "state") == 0) {
    const auto& set = planner_sets::state_set();
    sum = plan_set(set, to_rest);
  } else if (std::strcmp(which, "passing") == 0) {
    const auto& set = planner_sets::passing_set();
    sum = plan_set(set, passing);
  } else if (std::strcmp(which, "velocity") == 0) {
    const auto& set = planner_sets::velocity_set();
    sum = plan_set(set, to_velocity);
  } else {
    std::fprintf(stderr, "usage: planner_instructions rest|state|passing|velocity\n");
    return 2;
  }
  std::printf("sum of durations %.17g\n", sum);
  return 0;
}
