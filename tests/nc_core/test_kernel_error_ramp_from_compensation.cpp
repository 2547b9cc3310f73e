// An axis error during a compensation (docs/behaviour.md "Position compensation", fuzz finding
// K23): the compensation fails with the axis and the error ramp starts from the compensated set
// state, the compensation's acceleration included; the ramp brings it back to 0 at the emergency
// jerk first, so the velocity rises by a² / 2J before the axis brakes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandState;

TEST_CASE("the error ramp starts from the compensation's acceleration and passes v + a^2/2J",
          "[kernel][errors][compensation]") {
  // Seed axis: max velocity 2200 mm/s, emergency deceleration 10000 mm/s², emergency jerk 1e5
  // mm/s³ (the positioning's own J, 50000, is smaller: K5 keeps the emergency jerk). Base 0 →
  // 100000 at 1500 mm/s; then D 2000 over L 5000 with VK 3000, AK± 20000 and VP 1500: the opening
  // ramp adds 20000 mm/s² for about 40 ms. Ten cycles into it the plus feed enable goes (0x4358).
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(100000.0, 1500.0));
  REQUIRE(h.cycles_until(
              [&] { return h.x->NcToPlc.SetVelo == 1500.0 && h.x->NcToPlc.SetAcc == 0.0; }) > 0);
  const uint16_t comp =
      h.post(kt::move_superimposed(2000.0, 3000.0, 20000.0, 20000.0, 1500.0, 5000.0));
  h.cycles(10);
  REQUIRE(h.state_of(comp) == CommandState::kActive);
  const double a0 = h.x->NcToPlc.SetAcc;
  const double v0 = h.x->NcToPlc.SetVelo;
  REQUIRE(a0 == Approx(20000.0));
  REQUIRE(v0 > 1600.0);

  kt::set_enables(*h.x, true, false, true);
  h.cycles(1);
  CHECK(h.x->NcToPlc.ErrorCode == 0x4358U);
  CHECK(h.state_of(comp) == CommandState::kError);
  CHECK(h.state_of(move) == CommandState::kError);
  // The ramp's first cycle: the compensated acceleration less one cycle of the emergency jerk.
  CHECK(h.x->NcToPlc.SetAcc == Approx(a0 - 1e5 * 0.001).margin(1.0));
  double peak = v0;
  for (int i = 0; i < 3000; ++i) {
    h.cycles(1);
    peak = std::max(peak, h.x->NcToPlc.SetVelo);
  }
  // 20000² / (2·1e5) = 2000 mm/s on top of v0, to within one cycle's velocity step (20 mm/s):
  // above the max velocity (the watch of the fuzz targets allows it, K23), then to rest.
  CHECK(peak == Approx(v0 + a0 * a0 / (2.0 * 1e5)).margin(20.0));
  CHECK(peak > 2200.0);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  CHECK(h.x->NcToPlc.SetAcc == 0.0);
}
