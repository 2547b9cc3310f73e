// Seed 002 examples 1-3 on the real kernel with blocks (MC_Power, MC_MoveAbsolute,
// fb::HLI_AxisCoupling): Y2 = logical axis 8 coupled to axis 1; NcToPlc.SetPos is the drive
// position d (checked to 1e-9); a PTP move commanded on a coupled target runs its program
// position and ends Done. Also gpAx indexed by add order and active_rev_r in 1e-3 mm/s.
#include <catch2/catch.hpp>

#include "hli_kernel_rig.hpp"

using namespace hlik;

TEST_CASE("Example 1: Y2 DIRECT to axis 1 follows 900 mm; its own PTP move leaves its drive",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  REQUIRE(rig.move_to(0, 900.0));
  CHECK(rig.set_pos(0) == Approx(900.0).margin(1e-9));
  CHECK(rig.set_pos(1) == Approx(900.0).margin(1e-9));
  CHECK(rig.axes[1]->NcToPlc.ActPos == Approx(900.0).margin(1e-6));

  // The move on Y2 is accepted and ends Done (its program position runs); the drive stays.
  REQUIRE(rig.move_to(1, 100.0));
  CHECK(rig.set_pos(1) == Approx(900.0).margin(1e-9));
  CHECK(rig.error(1) == 0);
  // Axis 1 back by 300: Y2's drive follows to 600.
  REQUIRE(rig.move_to(0, 600.0));
  CHECK(rig.set_pos(1) == Approx(600.0).margin(1e-9));
}

TEST_CASE("Example 2: DIRECT + self: axis 1 by 900 and Y2's program by 100 move Y2's drive 1000",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  REQUIRE(rig.couple(
      1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}, {8, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  rig.start_move(0, 900.0);
  rig.start_move(1, 100.0, 500.0);
  // Both edges go out in the same tick; follow until both are Done.
  bool velocity_seen = false;
  for (int n = 0; n < 5000 && !(rig.move[0].Done && rig.move[1].Done); ++n) {
    rig.tick();
    const double v = rig.axes[1]->NcToPlc.SetVelo;
    const int32_t rev = rig.kernel.gpAx()[1]->lr_state.active_rev_r;
    if (v > 100.0) {
      velocity_seen = true;
      CHECK(std::abs(static_cast<double>(rev) - 1000.0 * v) <= 0.5);
    }
  }
  CHECK(velocity_seen);
  REQUIRE(rig.move[0].Done);
  REQUIRE(rig.move[1].Done);
  CHECK(rig.set_pos(1) == Approx(1000.0).margin(1e-9));
}

TEST_CASE("Example 3: self + FRACT -5/9: axis 1 by 900 gives Y2's drive -500, plus its program",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  REQUIRE(rig.couple(
      1, {{8, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}, {1, h::HLI_AXIS_COUPLING_FRACT, -5, 9}}));
  REQUIRE(rig.move_to(0, 900.0));
  CHECK(rig.set_pos(1) == Approx(-500.0).margin(1e-9));
  REQUIRE(rig.move_to(1, 100.0));  // a PTP move on the coupled target: its self entry adds it
  CHECK(rig.set_pos(1) == Approx(-400.0).margin(1e-9));
  CHECK(rig.axes[1]->NcToPlc.ActPos == Approx(-400.0).margin(1e-6));
  const auto& state = rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.state_r;
  CHECK(state.active_r);
  CHECK(state.desc[0] == h::HLI_AX_COUPLING_STATE_DESC{8, h::HLI_AXIS_COUPLING_DIRECT});
  CHECK(state.desc[1] == h::HLI_AX_COUPLING_STATE_DESC{1, h::HLI_AXIS_COUPLING_FRACT});
  CHECK(state.error_r == 0);
}

TEST_CASE("gpAx is indexed by add order; ax_nr names the logical number", "[hli][kernel]") {
  Rig rig({axis(5, "A"), axis(3, "B"), axis(9, "C")});
  REQUIRE(rig.kernel.gpAx().size() == 3);
  // gpAx[1] is axis B (ax_nr 3): its list names ax_nr 5, the axis added first.
  REQUIRE(rig.couple(1, {{5, h::HLI_AXIS_COUPLING_MIRROR, 0, 0}}));
  CHECK(rig.kernel.gpAx()[0]->lr_mc_control.axis_coupling.state_r.active_r == false);
  CHECK(rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.state_r.active_r);
  REQUIRE(rig.move_to(0, 250.0));
  CHECK(rig.set_pos(1) == Approx(-250.0).margin(1e-9));
  CHECK(rig.set_pos(2) == 0.0);
  // Switched off (first entry INACTIVE): the drive stays, then follows B's own program.
  REQUIRE(rig.couple(1, {}));
  CHECK(rig.set_pos(1) == Approx(-250.0).margin(1e-9));
  REQUIRE(rig.move_to(1, 10.0));  // program 0 → 10: the drive moves +10 from where it stands
  CHECK(rig.set_pos(1) == Approx(-240.0).margin(1e-9));
  CHECK(rig.axes[1]->NcToPlc.ActPos == Approx(-240.0).margin(1e-6));
}

TEST_CASE("Without any list the image is that of a kernel without HLI; a refused list keeps it",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  // 70396 (denominator 0): refused, nothing changes; the stage stays without a list.
  CHECK_FALSE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_FRACT, 1, 0}}));
  CHECK(rig.last_coupling_error == 70396);
  REQUIRE(rig.move_to(0, 900.0));
  CHECK(rig.set_pos(1) == 0.0);
  CHECK(rig.error(1) == 0);
}
