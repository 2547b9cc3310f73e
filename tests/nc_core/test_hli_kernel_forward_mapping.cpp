// D5 through the kernel: Kernel::command_position_request(ax_nr). Seed 002's example: X = 40,
// X1 = 50, X1 coupled 1:1 to X and to itself: 50 without P-AXIS-00460, 10 with it; after X moves
// +20: 70 by default, 50 with P-AXIS-00436, 10 with 00436 + 00460. NaN for an unknown axis.
#include <catch2/catch.hpp>

#include <cmath>

#include "hli_kernel_rig.hpp"

using namespace hlik;

namespace {

Rig example(bool p436, bool p460) {
  nc::AxisConfig x1 = axis(2, "X1");
  x1.recalc_link_main_input_position = p436;
  x1.recalc_input_position_absolute = p460;
  Rig rig({axis(1, "X"), x1});
  REQUIRE(rig.move_to(0, 40.0));
  REQUIRE(rig.move_to(1, 50.0));
  REQUIRE(rig.couple(
      1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}, {2, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  return rig;
}

}  // namespace

TEST_CASE("Forward mapping through the kernel: 50 / 10, then 70 / 50 / 10", "[hli][kernel]") {
  Rig plain = example(false, false);
  Rig relative = example(true, false);
  Rig absolute = example(true, true);
  CHECK(relative.kernel.command_position_request(2) == Approx(50.0).margin(1e-9));
  CHECK(absolute.kernel.command_position_request(2) == Approx(10.0).margin(1e-9));
  for (Rig* rig : {&plain, &relative, &absolute})
    REQUIRE(rig->move_to(0, 60.0));
  CHECK(plain.kernel.command_position_request(2) == Approx(70.0).margin(1e-9));
  CHECK(plain.set_pos(1) == Approx(70.0).margin(1e-9));
  CHECK(relative.kernel.command_position_request(2) == Approx(50.0).margin(1e-9));
  CHECK(absolute.kernel.command_position_request(2) == Approx(10.0).margin(1e-9));
  // An uncoupled axis: its drive position.
  CHECK(plain.kernel.command_position_request(1) == Approx(60.0).margin(1e-9));
  CHECK(std::isnan(plain.kernel.command_position_request(7)));
  CHECK(std::isnan(plain.kernel.command_position_request(0)));
}

TEST_CASE("The request gives the drive position while the stage is idle too", "[hli][kernel]") {
  nc::AxisConfig x1 = axis(2, "X1");
  x1.recalc_link_main_input_position = true;
  Rig rig({axis(1, "X"), x1});
  // Nothing ever coupled: phase (c) has not run, the request is each axis's drive position.
  REQUIRE(rig.move_to(0, 40.0));
  REQUIRE(rig.move_to(1, 50.0));
  CHECK(rig.kernel.command_position_request(1) == Approx(40.0).margin(1e-9));
  CHECK(rig.kernel.command_position_request(2) == Approx(50.0).margin(1e-9));
  // Coupled to itself only and switched off again: d = q, the stage goes idle; later moves show.
  REQUIRE(rig.couple(1, {{2, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  REQUIRE(rig.couple(1, {}));
  REQUIRE(rig.move_to(0, 15.0));
  REQUIRE(rig.move_to(1, -25.0));
  CHECK(rig.kernel.command_position_request(1) == Approx(15.0).margin(1e-9));
  CHECK(rig.kernel.command_position_request(2) == Approx(-25.0).margin(1e-9));
}
