// SPEC D5, seed 002 P-AXIS-00460: X = 40, X1 = 50, X1 coupled 1:1 to X and to itself. The
// command-position request gives 50 (default and P-AXIS-00436) and 10 with P-AXIS-00460; after X
// moves +20: 70 by default, 50 with 00436, 10 with 00436 + 00460.
#include <catch2/catch.hpp>

#include <vector>

#include "hli_stage_rig.hpp"

using namespace hlitest;

namespace {

// X (1), then three copies of X1: default (2), 00436 (3), 00436 + 00460 (4).
Rig seed_rig() {
  std::vector<nc::hli::AxisSetup> s(4);
  for (int i = 0; i < 4; ++i)
    s[static_cast<std::size_t>(i)].ax_nr = i + 1;
  s[2].forward_mapping = true;
  s[3].forward_mapping = true;
  s[3].forward_mapping_absolute = true;
  Rig rig(s);
  rig.q = {40.0, 50.0, 50.0, 50.0};
  rig.cycle();
  for (std::size_t x1 = 1; x1 <= 3; ++x1)
    rig.command(x1, {direct(1), direct(static_cast<int>(x1) + 1), inactive()});
  rig.cycle();
  return rig;
}

}  // namespace

TEST_CASE("seed example: 50 without P-AXIS-00460, 10 with it", "[hli]") {
  Rig rig = seed_rig();
  CHECK(rig.stage.command_position_request(1) == 50.0);
  CHECK(rig.stage.command_position_request(2) == 50.0);
  CHECK(rig.stage.command_position_request(3) == 10.0);
  CHECK(rig.stage.command_position_request(0) == 40.0);
}

TEST_CASE("after X moves +20: 70 by default, 50 with 00436, 10 with 00436 + 00460", "[hli]") {
  Rig rig = seed_rig();
  rig.move(0, 20.0, 100.0);
  CHECK(rig.stage.command_position_request(1) == Approx(70.0).margin(1e-9));
  CHECK(rig.stage.command_position_request(2) == Approx(50.0).margin(1e-9));
  CHECK(rig.stage.command_position_request(3) == Approx(10.0).margin(1e-9));
  CHECK(rig.d[1] == Approx(70.0).margin(1e-9));
}

TEST_CASE("with P-AXIS-00436 the request returns the program coordinate the list maps to d",
          "[hli]") {
  nc::hli::AxisSetup s;
  s.forward_mapping = true;
  Rig rig({1, 2}, s);
  rig.q = {12.0, -3.0};
  rig.cycle();
  rig.command(1, {fract(1, 1, 2), fract(2, 2, 1), inactive()});
  rig.cycle();
  rig.move(0, 7.0, 100.0);
  rig.move(1, 4.5, 100.0);
  rig.move(0, -2.0, 100.0);
  CHECK(rig.d[1] == Approx(-3.0 + 0.5 * 5.0 + 2.0 * 4.5).margin(1e-9));
  CHECK(rig.stage.command_position_request(1) == Approx(rig.q[1]).margin(1e-9));

  // Without a self entry the drive does not depend on the program coordinate: it is returned.
  rig.command(1, {direct(1), inactive()});
  rig.cycle();
  rig.move(1, 2.0, 100.0);
  CHECK(rig.stage.command_position_request(1) == rig.q[1]);
  // Unknown index: NaN.
  CHECK(rig.stage.command_position_request(5) != rig.stage.command_position_request(5));
}
