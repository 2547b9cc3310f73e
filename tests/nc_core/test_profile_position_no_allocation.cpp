// No allocation in plan_position and plan_velocity on the paths issue 17 changed (brief:
// real-time discipline): the push walked only up to the piece holding the switch (PushScan), the
// stop point's written-out derivatives and their jet fallback (a start acceleration beyond A-,
// the final curve), the one-test input check and its slow path that names the code. 4 000
// random problems from feasible states, the fuzz findings' extreme starts (P19: a < -A-), and
// refused inputs of each kind. A counting global operator new counts 0. Runs only in the plain
// build.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "counting_allocator.hpp"
#include "nc_core/profile.hpp"
#include "profile_problems.hpp"

namespace {

struct Case {
  nc::KinematicState start;
  double target = 0.0;
  nc::Limits limits;
};

}  // namespace

TEST_CASE("plan_position and plan_velocity allocate nothing on the paths of issue 17",
          "[no_allocation][profile]") {
  const nc::Limits unit{1.0, 1.0, 1.0, 1.0};
  std::vector<Case> cases = {
      // P19: a start acceleration against the push beyond A- (the jet fallback of the stop).
      {{0.0, 1e-9, -7e-9}, 1.0, {1.0, 3.5e-9, 3.5e-9, 3.5e-9}},
      // A start on the final curve of its stop (v_nat = 0), the target ahead.
      {{0.0, 0.5, -1.0}, 2.0, unit},
      // A start decelerating at A- exactly, pushed on (the stop's hold without its rise).
      {{0.0, 3.0, -1.0}, 10.0, unit},
  };
  const std::vector<Case> refused = {
      {{NAN, 0.0, 0.0}, 1.0, unit},                    // kStateNotFinite
      {{0.0, 1e-200, 0.0}, 1.0, unit},                 // kVelocityNotAllowed
      {{0.0, 0.0, 0.0}, 2e12, unit},                   // kTargetPositionNotAllowed
      {{0.0, 0.0, 0.0}, 1.0, {1.0, 1.0, 1.0, 1e-10}},  // kJerkNotAllowed
      {{0.0, 0.0, 0.0}, 1.0, {-1.0, 1.0, 1.0, 1.0}},   // kVelocityNotPositive
      {{0.0, 0.0, 1e7}, 1.0, unit},                    // kStartFarOutsideLimits
  };
  profile_problems::Rng rng(0x17A110CULL);
  for (int k = 0; k < 4000; ++k) {
    const profile_problems::Problem pr = profile_problems::random_position_problem(rng, 0.1);
    cases.push_back({pr.start, pr.target, pr.limits});
  }
  long planned = 0;
  long refusals = 0;
  ca::g_allocations = 0;
  ca::g_counting = true;
  for (const Case& c : cases) {
    const nc::Profile position = nc::plan_position(c.start, c.target, c.limits);
    const nc::Profile velocity =
        nc::plan_velocity(c.start, std::fmod(c.target, c.limits.velocity), c.limits);
    planned += (position.ok() ? 1 : 0) + (velocity.ok() ? 1 : 0);
  }
  for (const Case& c : refused) {
    refusals += nc::plan_position(c.start, c.target, c.limits).ok() ? 0 : 1;
    refusals += nc::plan_velocity(c.start, 0.5, c.limits).ok() ? 0 : 1;
  }
  ca::g_counting = false;
  CHECK(ca::g_allocations == 0);
  CHECK(planned == 2 * static_cast<long>(cases.size()));
  // Every refused input is refused by both calls but the target beyond range (plan_velocity has
  // no target).
  CHECK(refusals == 2 * static_cast<long>(refused.size()) - 1);
}
