// SPEC D3: sources contribute their program movement since activation; several sources sum, a
// ZERO target still serves as a source, drive movement never feeds another axis, and switching
// a list off never moves the drive.
#include <catch2/catch.hpp>

#include "hli_stage_rig.hpp"

using namespace hlitest;

TEST_CASE("three sources (DIRECT, MIRROR, FRACT 3/2) sum their program movements", "[hli]") {
  Rig rig({1, 2, 3, 4});
  rig.command(3, {direct(1), mirror(2), fract(3, 3, 2), inactive()});
  rig.cycle();
  REQUIRE(rig.unit(3).state_r.error_r == 0);

  rig.move(0, 100.0, 500.0);
  rig.move(1, 30.0, 500.0);
  rig.move(2, 20.0, 500.0);
  // 100 - 30 + 1.5 · 20
  CHECK(rig.d[3] == Approx(100.0).margin(1e-9));
  rig.move(1, 50.0, 500.0);
  CHECK(rig.d[3] == Approx(50.0).margin(1e-9));
}

TEST_CASE("a ZERO target stands still, yet its program motion drives its own target", "[hli]") {
  Rig rig({1, 2});
  rig.command(0, {zero(1), inactive()});  // axis 1 shut down
  rig.command(1, {direct(1), inactive()});
  rig.cycle();
  REQUIRE(rig.unit(0).state_r.error_r == 0);
  REQUIRE(rig.unit(1).state_r.error_r == 0);
  CHECK(rig.unit(0).state_r.active_r);

  rig.move(0, 75.0, 300.0);
  CHECK(rig.d[0] == 0.0);
  CHECK(rig.d[1] == Approx(75.0).margin(1e-9));
}

TEST_CASE("a target used as a source passes on its program movement, not its drive's", "[hli]") {
  Rig rig({1, 2, 3});  // A = 1, B = 2 follows A, C = 3 follows B
  rig.command(1, {direct(1), inactive()});
  rig.command(2, {direct(2), inactive()});
  rig.cycle();

  rig.move(0, 200.0, 1000.0);  // A moves: B's drive follows, B's program does not move
  CHECK(rig.d[1] == Approx(200.0).margin(1e-9));
  CHECK(rig.d[2] == 0.0);
  rig.move(1, 30.0, 100.0);  // B's program moves: its drive (no self entry) does not, C's does
  CHECK(rig.d[1] == Approx(200.0).margin(1e-9));
  CHECK(rig.d[2] == Approx(30.0).margin(1e-9));
}

TEST_CASE("switching a list off leaves the drive where it stands; it follows its program on",
          "[hli]") {
  Rig rig({1, 8});
  rig.command(1, {fract(1, -5, 9), inactive()});
  rig.cycle();
  rig.move(0, 900.0, 1000.0);
  rig.move(1, 10.0, 100.0);  // program only: no self entry
  REQUIRE(rig.d[1] == Approx(-500.0).margin(1e-9));

  rig.command(1, {inactive(), direct(1)});  // first entry INACTIVE: all off
  rig.cycle();
  CHECK(rig.unit(1).state_r.error_r == 0);
  CHECK_FALSE(rig.unit(1).state_r.active_r);
  CHECK(rig.d[1] == Approx(-500.0).margin(1e-9));
  CHECK(rig.dv[1] == 0.0);

  rig.move(0, 100.0, 1000.0);  // no longer a source
  CHECK(rig.d[1] == Approx(-500.0).margin(1e-9));
  rig.move(1, 25.0, 100.0);  // its own program moves its drive again, from where it stood
  CHECK(rig.d[1] == Approx(-475.0).margin(1e-9));
}

TEST_CASE("switching targets off and stopping one leaves the other targets' couplings intact",
          "[hli]") {
  Rig rig({1, 2, 3, 4, 5});
  rig.command(1, {direct(1), inactive()});
  rig.command(2, {mirror(1), inactive()});
  rig.command(3, {fract(1, 1, 4), inactive()});
  rig.command(4, {fract(1, 3, 1), inactive()});
  rig.cycle();
  rig.command(1, {inactive()});  // the first target off: another one's row takes its place
  rig.cycle();
  rig.move(0, 8.0, 100.0);
  CHECK(rig.d[1] == 0.0);
  CHECK(rig.d[2] == Approx(-8.0).margin(1e-9));
  CHECK(rig.d[3] == Approx(2.0).margin(1e-9));
  CHECK(rig.d[4] == Approx(24.0).margin(1e-9));
  CHECK(rig.stage.factor(4, 0) == 3.0);
  CHECK(rig.stage.factor(1, 1) == 1.0);  // free: the unit row
  CHECK(rig.stage.factor(1, 0) == 0.0);

  rig.stage.stop(2);  // the kernel stops a target for its own reasons
  CHECK_FALSE(rig.unit(2).state_r.active_r);
  rig.move(0, 4.0, 100.0);
  CHECK(rig.d[2] == Approx(-8.0).margin(1e-9));
  CHECK(rig.d[3] == Approx(3.0).margin(1e-9));
  CHECK(rig.d[4] == Approx(36.0).margin(1e-9));
  rig.command(1, {direct(1), inactive()});  // and a new row again
  rig.cycle();
  rig.move(0, 1.0, 100.0);
  CHECK(rig.d[1] == Approx(1.0).margin(1e-9));
  CHECK(rig.d[4] == Approx(39.0).margin(1e-9));
}
