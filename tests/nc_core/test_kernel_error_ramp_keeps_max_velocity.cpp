// The error ramp from a hard-accelerating motion keeps the axis's max velocity (fuzz finding K5,
// found by the soak): where the emergency jerk would ramp the acceleration down too slowly
// (v + a·|a| / 2J above the max velocity), the ramp takes the running job's larger jerk, as a new
// job does (K4; docs/behaviour.md, "Errors and reset").
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "kernel_harness.hpp"

namespace {

// The largest |SetVelo| over the next `cycles` cycles.
double peak_set_speed(kt::Harness& h, int cycles) {
  double peak = 0.0;
  for (int i = 0; i < cycles; ++i) {
    h.cycles(1);
    peak = std::max(peak, std::abs(h.x->NcToPlc.SetVelo));
  }
  return peak;
}

// The motion of the first case below, its plus feed enable removed (the error ramp starts at J
// 1e6), given back two cycles later and the axis reset: the ramp, which a reset lets finish, still
// brings a > 15000 mm/s² back. Returns the set velocity before the error.
double reset_during_error_ramp(kt::Harness& h) {
  h.post(kt::move_absolute(100000.0, 2200.0, 20000.0, 20000.0, 1e6));
  REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetVelo >= 1700.0; }, 1000) > 0);
  const double v0 = h.x->NcToPlc.SetVelo;
  kt::set_enables(*h.x, true, false, true);
  h.cycles(2);
  REQUIRE(h.x->NcToPlc.ErrorCode == 0x4358U);
  REQUIRE(std::abs(h.x->NcToPlc.SetAcc) > 15000.0);  // the ramp has only begun
  kt::set_enables(*h.x, true, true, true);
  h.post(kt::simple(plc::CommandType::kReset));
  h.cycles(1);
  REQUIRE(h.x->NcToPlc.ErrorCode == 0U);
  return v0;
}

}  // namespace

TEST_CASE("the error ramp from a hard acceleration keeps Vmax", "[kernel][errors]") {
  // Seed axis: max velocity 2200 mm/s, emergency deceleration 10000 mm/s², emergency jerk 1e5
  // mm/s³. A positioning at 2200 mm/s with A 20000 and J 1e6 until v >= 1700 mm/s (a = 20000
  // there), then the plus feed enable is removed (0x4358). At the emergency jerk the acceleration
  // would add 20000² / (2·1e5) = 2000 mm/s (3700 mm/s); at J 1e6 it adds 200 mm/s.
  kt::Harness h;
  h.post(kt::move_absolute(100000.0, 2200.0, 20000.0, 20000.0, 1e6));
  REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetVelo >= 1700.0; }, 1000) > 0);
  REQUIRE(h.x->NcToPlc.SetAcc == Approx(20000.0));
  const double v0 = h.x->NcToPlc.SetVelo;
  kt::set_enables(*h.x, true, false, true);
  const double peak = peak_set_speed(h, 5000);
  CHECK(h.x->NcToPlc.ErrorCode == 0x4358U);
  CHECK(peak <= 2200.0);
  CHECK(peak == Approx(v0 + 200.0).margin(25.0));  // a ramped out at J 1e6 (one cycle's a more)
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
}

TEST_CASE("a halt after a reset during the error ramp brakes with the ramp's jerk and keeps Vmax",
          "[kernel][errors]") {
  // Fuzz finding K24: the error ramp of the case above (at J 1e6, K5) is still running when a
  // reset clears the error (it finishes first), and an MC_Halt with D = 0 and J = 0 then takes
  // the running motion's D and J. The ramp is that running motion; before the fix the halt took
  // the axis's defaults (J 50000) instead: 20000² / (2·50000) = 4000 mm/s more.
  kt::Harness h;
  const double v0 = reset_during_error_ramp(h);
  const uint16_t halt = h.post(kt::simple(plc::CommandType::kHalt));
  const double peak = peak_set_speed(h, 5000);
  CHECK(h.state_of(halt) == plc::CommandState::kDone);
  CHECK(peak <= 2200.0);
  CHECK(peak == Approx(v0 + 200.0).margin(25.0));  // a ramped out at J 1e6, as the ramp would
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
}

TEST_CASE("a move after a reset during the error ramp keeps Vmax", "[kernel][errors]") {
  // K24's situation with a new positioning (J = 0: the axis's 50000) instead of a halt: K4's rule
  // applies with the error ramp as the running job, whose jerk (1e6, K5) the move takes where its
  // own would pass the max velocity (20000² / (2·50000) = 4000 mm/s more).
  kt::Harness h;
  reset_during_error_ramp(h);
  const uint16_t move = h.post(kt::move_absolute(0.0, 1000.0));
  const double peak = peak_set_speed(h, 10000);
  CHECK(h.state_of(move) == plc::CommandState::kDone);
  CHECK(peak <= 2200.0);
  CHECK(h.x->NcToPlc.SetPos == Approx(0.0).margin(1e-9));
}
