// Seed 002 §3, examples 1–3: target Y2 = logical axis 8 coupled to logical axis 1 (SPEC D3).
#include <catch2/catch.hpp>

#include "hli_stage_rig.hpp"

using namespace hlitest;

namespace {
constexpr std::size_t kX = 0;   // logical axis 1
constexpr std::size_t kY2 = 1;  // logical axis 8
}  // namespace

TEST_CASE("example 1: Y2 follows axis 1 and its own program motion does not move its drive",
          "[hli]") {
  Rig rig({1, 8});
  rig.command(kY2, {direct(1), inactive()});
  rig.cycle();
  REQUIRE(rig.unit(kY2).state_r.error_r == 0);
  REQUIRE(rig.unit(kY2).state_r.active_r);

  rig.move(kX, 900.0, 1000.0);
  CHECK(rig.d[kY2] == Approx(900.0).margin(1e-9));
  CHECK(rig.d[kX] == Approx(900.0).margin(1e-9));

  // A move commanded on Y2 runs its program position, not its drive.
  rig.move(kY2, 250.0, 500.0);
  CHECK(rig.q[kY2] == 250.0);
  CHECK(rig.d[kY2] == Approx(900.0).margin(1e-9));
}

TEST_CASE("example 2: with the self entry axis 1's and Y2's own movements add", "[hli]") {
  Rig rig({1, 8});
  rig.command(kY2, {direct(1), direct(8), inactive()});
  rig.cycle();
  REQUIRE(rig.unit(kY2).state_r.error_r == 0);

  rig.move(kX, 900.0, 1000.0);
  rig.move(kY2, 100.0, 200.0);
  CHECK(rig.d[kY2] == Approx(1000.0).margin(1e-9));
  CHECK(rig.d[kX] == Approx(900.0).margin(1e-9));
}

TEST_CASE("example 3: FRACT -5/9 turns axis 1's 900 mm into -500 mm, plus Y2's own motion",
          "[hli]") {
  Rig rig({1, 8});
  rig.command(kY2, {direct(8), fract(1, -5, 9), inactive()});
  rig.cycle();
  REQUIRE(rig.unit(kY2).state_r.error_r == 0);
  CHECK(rig.stage.factor(kY2, kX) == -5.0 / 9.0);

  rig.move(kX, 900.0, 1000.0);
  CHECK(rig.d[kY2] == Approx(-500.0).margin(1e-9));
  rig.move(kY2, 40.0, 100.0);
  CHECK(rig.d[kY2] == Approx(-460.0).margin(1e-9));

  // While axis 1 moves at 900 mm/s, Y2's drive runs at -500 mm/s.
  rig.q[kX] += 0.9;
  rig.qv[kX] = 900.0;
  rig.cycle();
  CHECK(rig.dv[kY2] == Approx(-500.0).margin(1e-9));
  CHECK(rig.active_rev_r(kY2) == -500000);
}
