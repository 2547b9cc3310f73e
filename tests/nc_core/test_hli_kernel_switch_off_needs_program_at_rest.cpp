// Fuzz finding K25: switching an HLI target's list off hands its drive to its own program, so the
// program is an axis involved in the change (seed 002 "Changing the axis coupling": the target
// and all coupled source axes at standstill, else 70200). Switched off while the program moves,
// the drive took the program's velocity in one cycle: a step from rest to 1000 mm/s. Now that is
// 70200: the drive stays where it rests, the program comes to rest on its emergency ramp, and the
// drive follows it from there without a step.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "hli_kernel_rig.hpp"

using namespace hlik;

namespace {

constexpr double kCycle = 0.001;  // s, the rig's kernel cycle

// The largest change of Y2's (index 1) drive velocity from one tick to the next over `n` ticks.
double largest_velocity_step(Rig& rig, int n) {
  double largest = 0.0;
  double last = rig.axes[1]->NcToPlc.SetVelo;
  for (int k = 0; k < n; ++k) {
    rig.tick();
    const double v = rig.axes[1]->NcToPlc.SetVelo;
    largest = std::max(largest, std::abs(v - last));
    last = v;
  }
  return largest;
}

// Y2's list switched off (first entry INACTIVE) with an Execute edge, and one tick.
void switch_off(Rig& rig) {
  fb::HLI_AxisCoupling& c = rig.coupling[1];
  c.Execute = false;
  rig.tick();
  c.desc = {};
  c.Execute = true;
  rig.tick();
}

}  // namespace

TEST_CASE("an HLI list switched off while the target's own program moves is 70200; no step",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  const double a = rig.kernel.config("Y2").emergency_deceleration;
  // Y2 follows X (at rest) without a self entry: its own move runs its program only.
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  rig.start_move(1, 500.0, 1000.0);
  rig.ticks(300);
  const double rest = rig.set_pos(1);
  REQUIRE(rig.axes[1]->NcToPlc.SetVelo == 0.0);  // the drive does not move
  REQUIRE(rig.move[1].Busy);

  switch_off(rig);
  // Before K25's fix the drive velocity stepped from 0 to the program's 1000 mm/s here.
  CHECK(rig.axes[1]->NcToPlc.SetVelo == 0.0);
  CHECK(rig.error(1) == 70200);
  CHECK(rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.state_r.error_r == 70200);
  CHECK_FALSE(rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.state_r.active_r);
  rig.tick();
  CHECK(rig.coupling[1].Error);
  CHECK(rig.coupling[1].ErrorID == 70200);
  CHECK(rig.move[1].Error);  // the program's move fails with the axis error
  CHECK(rig.move[1].ErrorID == 70200);
  rig.coupling[1].Execute = false;

  // The program ramps down from 1000 mm/s; the drive holds, then follows the resting program.
  CHECK(largest_velocity_step(rig, 1000) == 0.0);
  CHECK(rig.set_pos(1) == Approx(rest).margin(1e-9));
  REQUIRE(rig.reset_axis(1));
  const double q = rig.axes[1]->NcToPlc.TargetPos;  // Y2's program position
  rig.start_move(1, q + 20.0, 500.0);
  CHECK(largest_velocity_step(rig, 500) <= a * kCycle * 1.01);  // now it moves, within its ramps
  CHECK(rig.set_pos(1) == Approx(rest + 20.0).margin(1e-9));
}

TEST_CASE("a list switched off after MC_Reset while the program's error ramp runs is 70200",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  // Y2 follows X at 100 mm/s while its own program runs at 2000 mm/s.
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  rig.start_move(0, 900.0, 100.0);
  rig.start_move(1, 1500.0, 2000.0);
  rig.ticks(600);
  REQUIRE(rig.axes[1]->NcToPlc.SetVelo == Approx(100.0));
  // A new list while X moves: 70200. The drive brakes from 100 mm/s in 10 ms; the program's
  // error ramp from 2000 mm/s takes about 0.2 s.
  fb::HLI_AxisCoupling& c = rig.coupling[1];
  c.desc = {};
  c.desc[0] = {1, h::HLI_AXIS_COUPLING_MIRROR, 0, 0};
  c.Execute = true;
  rig.ticks(20);
  REQUIRE(rig.error(1) == 70200);
  REQUIRE(rig.axes[1]->NcToPlc.SetVelo == 0.0);
  const double rest = rig.set_pos(1);
  // MC_Reset lets the error ramp finish (docs/behaviour.md "Stop and halt"); the PLC switches the
  // list off while it runs.
  REQUIRE(rig.reset_axis(1));
  REQUIRE(rig.error(1) == 0);
  switch_off(rig);
  // Before K25's fix the drive took the ramp's velocity (about 1800 mm/s) in this cycle.
  CHECK(rig.axes[1]->NcToPlc.SetVelo == 0.0);
  CHECK(rig.error(1) == 70200);
  CHECK(largest_velocity_step(rig, 1000) == 0.0);
  CHECK(rig.set_pos(1) == Approx(rest).margin(1e-9));
  CHECK(rig.error(0) == 0);  // X is not disturbed
}
