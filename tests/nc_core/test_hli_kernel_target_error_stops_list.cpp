// A coupled target that gets an axis error of its own (following error, feed enable) or loses
// its controller enable loses its list: from the next phase (c) on its drive brakes at the
// emergency deceleration (stopping distance v²/2a from the drive velocity it had) instead of
// following its sources; its sources are not disturbed; MC_Reset and a new list couple it again.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "hli_kernel_rig.hpp"

using namespace hlik;

namespace {

const h::HLI_AX_COUPLING_STATE& state_of(Rig& rig, std::size_t i) {
  return rig.kernel.gpAx()[i]->lr_mc_control.axis_coupling.state_r;
}

// Ticks until axis i shows an error; the tick count, or -1 after `limit`.
int ticks_until_error(Rig& rig, std::size_t i, int limit) {
  for (int n = 0; n < limit; ++n) {
    rig.tick();
    if (rig.error(i) != 0) return n;
  }
  return -1;
}

}  // namespace

TEST_CASE("A following error on a DIRECT target switches its list off and brakes its drive",
          "[hli][kernel]") {
  nc::AxisConfig y2 = axis(8, "Y2");
  y2.drive_max_velocity = 500.0;  // its drive cannot follow axis 1 at 2200 mm/s: it lags
  Rig rig({axis(1, "X"), y2});
  const double a = y2.emergency_deceleration;
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  rig.start_move(0, 900.0);
  REQUIRE(ticks_until_error(rig, 1, 2000) >= 0);
  CHECK(rig.error(1) == 0x4550);
  // The error was raised in phase (e): the list is still in force for this cycle's d.
  CHECK(state_of(rig, 1).active_r);
  const double p_error = rig.set_pos(1);
  const double v_error = rig.axes[1]->NcToPlc.SetVelo;
  REQUIRE(v_error > 500.0);
  rig.tick();  // phase (c) of the next cycle: the list goes off
  CHECK_FALSE(state_of(rig, 1).active_r);
  CHECK(state_of(rig, 1).desc[0] == h::HLI_AX_COUPLING_STATE_DESC{});
  CHECK(state_of(rig, 1).error_r == 0);  // error_r keeps the evaluation's ID
  CHECK(rig.axes[1]->NcToPlc.SetVelo == Approx(v_error - a * 0.001).margin(1e-9));

  REQUIRE(rig.finish_move(0));  // axis 1 is not disturbed
  CHECK(rig.error(0) == 0);
  CHECK(rig.set_pos(0) == Approx(900.0).margin(1e-9));
  // Y2's drive came to rest v²/2a after the error, far from the 900 mm its source reached.
  CHECK(rig.axes[1]->NcToPlc.SetVelo == 0.0);
  const double rest = rig.set_pos(1);
  CHECK(rest - p_error == Approx(v_error * v_error / (2.0 * a)).margin(1e-6));
  CHECK(rest < 900.0 - 100.0);
  CHECK(rig.axes[0]->NcToPlc.CoupleState == 0);
  CHECK(rig.axes[1]->NcToPlc.CoupleState == 0);
  REQUIRE(rig.move_to(0, 0.0));  // the source moving back does not move Y2 either
  CHECK(rig.set_pos(1) == rest);

  // MC_Reset at rest takes the set position from the actual one (the slow drive still lags a
  // little); coupled again, Y2 follows axis 1 from where it stands.
  rig.ticks(3000);
  REQUIRE(rig.reset_axis(1));
  CHECK(rig.error(1) == 0);
  const double held = rig.set_pos(1);
  CHECK(held == Approx(rest).margin(0.5));
  CHECK(held == Approx(rig.axes[1]->NcToPlc.ActPos).margin(1e-3));
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  REQUIRE(rig.move_to(0, 100.0, 200.0));
  CHECK(rig.error(1) == 0);
  CHECK(rig.set_pos(1) == Approx(held + 100.0).margin(1e-9));
}

TEST_CASE("An error reset by the PLC in the very next tick still switches the list off",
          "[hli][kernel]") {
  nc::AxisConfig y2 = axis(8, "Y2");
  y2.drive_max_velocity = 500.0;
  Rig rig({axis(1, "X"), y2});
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  rig.start_move(0, 900.0);
  REQUIRE(ticks_until_error(rig, 1, 2000) >= 0);
  REQUIRE(rig.error(1) == 0x4550);
  // MC_Reset's edge: phase (a) clears the error before phase (c) runs; the list goes off all the
  // same in that phase (c). (Phase (e) raises the following error again: the drive still lags.)
  rig.reset[1].Execute = true;
  rig.tick();
  CHECK_FALSE(state_of(rig, 1).active_r);
  rig.reset[1].Execute = false;
  REQUIRE(rig.finish_move(0));
  rig.ticks(1000);
  CHECK(rig.set_pos(1) < 900.0 - 100.0);  // it did not follow axis 1 to 900 mm
  CHECK(rig.axes[1]->NcToPlc.SetVelo == 0.0);
}

TEST_CASE("A feed-enable error of a target's own move stops its coupled drive too",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  const double a = rig.kernel.config("Y2").emergency_deceleration;
  REQUIRE(rig.run_example_2(100.0, 200.0, 400));  // DIRECT + self, both axes move
  REQUIRE(rig.axes[1]->NcToPlc.SetVelo > 1000.0);
  rig.power[1].Enable_Positive = false;  // raised in phase (a), seen by phase (c) at once
  rig.tick();
  CHECK(rig.error(1) == 0x4358);
  CHECK_FALSE(state_of(rig, 1).active_r);
  rig.tick();
  CHECK(rig.move[1].Error);
  CHECK(rig.move[1].ErrorID == 0x4358);
  double last = rig.set_pos(1);
  double v_prev = rig.axes[1]->NcToPlc.SetVelo;
  // From here on the drive only slows down at the emergency deceleration, to rest.
  for (int n = 0; n < 1000; ++n) {
    rig.tick();
    const double v = rig.axes[1]->NcToPlc.SetVelo;
    CHECK(v <= v_prev);
    CHECK(v >= 0.0);
    CHECK(v_prev - v <= a * 0.001 + 1e-9);
    v_prev = v;
  }
  CHECK(v_prev == 0.0);
  CHECK(rig.set_pos(1) > last);
  last = rig.set_pos(1);
  REQUIRE(rig.finish_move(0));
  CHECK(rig.error(0) == 0);
  CHECK(rig.set_pos(1) == last);
}

TEST_CASE("A target losing its controller enable while its drive moves: list off, 0x4356",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_MIRROR, 0, 0}}));
  rig.start_move(0, 900.0);
  rig.ticks(400);
  REQUIRE(rig.axes[1]->NcToPlc.SetVelo < -1000.0);
  rig.power[1].Enable = false;
  rig.tick();
  CHECK(rig.error(1) == 0x4356);
  CHECK_FALSE(state_of(rig, 1).active_r);
  REQUIRE(rig.finish_move(0));
  CHECK(rig.error(0) == 0);
  rig.ticks(2000);
  // Without its drive the set position follows the actual one; when the enable returns and the
  // error is reset, nothing jumps: no following error, the drive stays where it coasted to.
  const double coasted = rig.axes[1]->NcToPlc.ActPos;
  CHECK(coasted > -900.0 + 100.0);
  rig.power[1].Enable = true;
  rig.ticks(5);
  REQUIRE(rig.reset_axis(1));
  rig.ticks(100);
  CHECK(rig.error(1) == 0);
  CHECK(rig.set_pos(1) == Approx(coasted).margin(1e-6));
  CHECK(rig.axes[1]->NcToPlc.ActPos == Approx(coasted).margin(1e-3));
}

TEST_CASE("A target losing its controller enable at rest: list off without an error",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  rig.power[1].Enable = false;
  rig.tick();
  CHECK(rig.error(1) == 0);
  CHECK_FALSE(state_of(rig, 1).active_r);
  rig.power[1].Enable = true;
  rig.ticks(5);
  REQUIRE(rig.move_to(0, 300.0));
  CHECK(rig.set_pos(1) == Approx(0.0).margin(1e-9));  // no longer coupled: it stays
}

TEST_CASE(
    "A target with a move of its own losing its controller enable: no brake of a drive "
    "that is off, no jump when the enable returns",
    "[hli][kernel]") {
  // Fuzz finding K22: the lost enable raised 0x4260 for the target's own move in phase (a), so
  // phase (c) took the error path and braked the drive (84 m/s in the fuzz program) while the
  // drive was off; with the enable back and MC_Reset while that brake still ran, the image showed
  // the brake's velocity and position.
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  REQUIRE(rig.run_example_2(100.0, 200.0, 400));  // DIRECT + self, both axes move
  REQUIRE(rig.axes[1]->NcToPlc.SetVelo > 1000.0);
  rig.power[1].Enable = false;
  rig.tick();
  CHECK(rig.error(1) == 0x4260);  // its own move fails (section "Axis state and enables")
  CHECK_FALSE(state_of(rig, 1).active_r);
  rig.tick();
  rig.power[1].Enable = true;  // back at once: a brake from > 1000 mm/s would still run
  rig.ticks(2);
  REQUIRE(rig.reset_axis(1));
  double fastest = 0.0;
  for (int n = 0; n < 50; ++n) {
    rig.tick();
    fastest = std::max(fastest, std::abs(rig.axes[1]->NcToPlc.SetVelo));
  }
  CHECK(rig.error(1) == 0);
  CHECK(fastest == 0.0);  // the drive was off: nothing to brake, the axis holds
  REQUIRE(rig.finish_move(0));
  rig.ticks(2000);
  CHECK(rig.set_pos(1) == Approx(rig.axes[1]->NcToPlc.ActPos).margin(1e-3));
}
