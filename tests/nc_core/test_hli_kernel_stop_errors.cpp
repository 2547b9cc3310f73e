// 70200 and 70195 through the kernel: the target gets the axis error (NcToPlc.ErrorCode), its
// running move fails with it, its list goes off and its drive brakes at the emergency
// deceleration to rest; MC_Reset clears the error and a new list is taken again at rest.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "hli_kernel_rig.hpp"

using namespace hlik;

TEST_CASE("70200: a new list while a source moves stops the target; MC_Reset clears it",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  const double a = rig.kernel.config("Y2").emergency_deceleration;
  REQUIRE(rig.run_example_2(500.0, 500.0, 300));
  REQUIRE(rig.axes[0]->NcToPlc.SetVelo > 0.0);
  const double v_before = rig.axes[1]->NcToPlc.SetVelo;
  const double p_before = rig.set_pos(1);
  REQUIRE(v_before > 1000.0);

  // A new list on Y2 while axis 1 moves.
  fb::HLI_AxisCoupling& c = rig.coupling[1];
  c.desc = {};
  c.desc[0] = {1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0};
  c.Execute = true;
  rig.tick();
  CHECK(rig.error(1) == 70200);
  const double v_error = rig.axes[1]->NcToPlc.SetVelo;  // first braking step done
  const double p_error = rig.set_pos(1);
  CHECK(v_error == Approx(v_before - a * 0.001).epsilon(0.01));
  CHECK(rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.state_r.error_r == 70200);
  CHECK_FALSE(rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.state_r.active_r);
  rig.tick();
  CHECK(c.Error);
  CHECK(c.ErrorID == 70200);
  c.Execute = false;
  CHECK(rig.move[1].Error);  // its program's move fails with the axis error
  CHECK(rig.move[1].ErrorID == 70200);
  CHECK(rig.error(0) == 0);  // axis 1 is not disturbed
  CHECK(rig.move[0].Busy);

  // Y2's drive brakes at the emergency deceleration: from there it rests after exactly v²/2a.
  rig.ticks(1000);
  CHECK(rig.axes[1]->NcToPlc.SetVelo == 0.0);
  CHECK(p_error > p_before);
  CHECK(rig.set_pos(1) - p_error == Approx(v_error * v_error / (2.0 * a)).margin(1e-6));
  CHECK(rig.axes[1]->NcToPlc.ActPos == Approx(rig.set_pos(1)).margin(1e-6));
  const double rest = rig.set_pos(1);
  REQUIRE(rig.finish_move(0));  // axis 1 ends its move; Y2's list is off, its drive stays
  CHECK(rig.set_pos(1) == rest);
  CHECK(rig.error(1) == 70200);

  REQUIRE(rig.reset_axis(1));
  CHECK(rig.error(1) == 0);
  CHECK(rig.set_pos(1) == Approx(rest).margin(1e-9));  // the reset does not move the drive
  // At rest a list is taken again, and Y2 moves on its own program from where it stands.
  REQUIRE(rig.couple(1, {{8, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  REQUIRE(rig.move_to(0, 0.0));
  CHECK(rig.set_pos(1) == Approx(rest).margin(1e-9));
  const double q = rig.axes[1]->NcToPlc.TargetPos;  // Y2's program position (its last target)
  REQUIRE(rig.move_to(1, q + 25.0, 500.0));
  CHECK(rig.set_pos(1) == Approx(rest + 25.0).margin(1e-9));
}

TEST_CASE("70195: a FRACT coupling driving a homed axis toward its limit stops it before it",
          "[hli][kernel]") {
  nc::AxisConfig y2 = axis(8, "Y2");
  y2.sw_limit_max_enabled = true;
  y2.sw_limit_max = 300.0;
  y2.emergency_deceleration = 8000.0;
  Rig rig({axis(1, "X"), y2});
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_FRACT, 3, 2}}));
  rig.start_move(0, 900.0);
  double highest = 0.0;
  int raised_at = -1;
  for (int n = 0; n < 3000; ++n) {
    rig.tick();
    highest = std::max(highest, rig.set_pos(1));
    if (raised_at < 0 && rig.error(1) != 0) raised_at = n;
  }
  REQUIRE(raised_at >= 0);
  CHECK(rig.error(1) == 70195);
  CHECK(rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.state_r.error_r == 70195);
  CHECK_FALSE(rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.state_r.active_r);
  CHECK(highest <= 300.0);
  CHECK(highest > 150.0);  // it did run toward the limit first
  CHECK(rig.axes[1]->NcToPlc.SetVelo == 0.0);
  CHECK(rig.axes[1]->NcToPlc.ActPos <= 300.0);
  REQUIRE(rig.finish_move(0));  // axis 1 is not disturbed
  CHECK(rig.set_pos(0) == Approx(900.0).margin(1e-9));
  REQUIRE(rig.reset_axis(1));
  CHECK(rig.error(1) == 0);
  CHECK(rig.set_pos(1) == Approx(highest).margin(1e-9));
}
