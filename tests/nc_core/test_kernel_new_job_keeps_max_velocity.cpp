// A new job that aborts a hard-accelerating motion keeps the axis's max velocity (fuzz finding
// K4): when its own, smaller jerk would ramp the acceleration down too slowly (v + a·|a| / 2J
// above the max velocity), it takes the running job's larger jerk (docs/behaviour.md, "Starts").
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "kernel_harness.hpp"

namespace {

// Seed axis (max velocity 2200 mm/s, default A 5000 mm/s², J 50000 mm/s³); a positioning at
// 2200 mm/s with A 20000 and J 1e6 until v >= 1700 mm/s (a = 20000 mm/s² there); then `next`.
double peak_after_abort(const plc::Command& next, plc::CommandState& next_state) {
  kt::Harness h;
  h.post(kt::move_absolute(100000.0, 2200.0, 20000.0, 20000.0, 1e6));
  REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetVelo >= 1700.0; }, 1000) > 0);
  REQUIRE(h.x->NcToPlc.SetAcc == Approx(20000.0));
  const uint16_t n = h.post(next);
  double peak = 0.0;
  for (int i = 0; i < 5000; ++i) {
    h.cycles(1);
    peak = std::max(peak, std::abs(h.x->NcToPlc.SetVelo));
  }
  next_state = h.state_of(n);
  return peak;
}

}  // namespace

TEST_CASE("a MoveVelocity with a smaller jerk aborting a hard acceleration keeps Vmax",
          "[kernel][starts]") {
  plc::CommandState state = plc::CommandState::kFree;
  // With its own J 50000 the acceleration of 20000 would add 20000² / (2·50000) = 4000 mm/s.
  const double peak = peak_after_abort(kt::move_velocity(500.0, 1), state);
  CHECK(peak <= 2200.0);
  CHECK(state == plc::CommandState::kReached);
}

TEST_CASE("a MoveAbsolute with a smaller jerk aborting a hard acceleration keeps Vmax",
          "[kernel][starts]") {
  plc::CommandState state = plc::CommandState::kFree;
  const double peak = peak_after_abort(kt::move_absolute(1000.0, 500.0), state);
  CHECK(peak <= 2200.0);
  CHECK(state == plc::CommandState::kDone);
}
