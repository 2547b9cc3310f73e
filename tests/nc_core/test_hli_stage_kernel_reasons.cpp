// What the stage offers the kernel for its own reasons: a new list refused with the kernel's
// code (axis in error, no controller enable, external setpoints) changes nothing else;
// source_of_other() for CoupleState (a self entry does not count); release() switches a list off
// without braking (a target whose drive is off), stop() with braking (a target in error).
#include <catch2/catch.hpp>

#include "hli_stage_rig.hpp"

using namespace hlitest;

TEST_CASE("a list refused for the kernel's reason is not taken; the list in force stays", "[hli]") {
  Rig rig({1, 8});
  rig.command(1, {direct(1)});
  rig.cycle();
  REQUIRE(rig.stage.coupled(1));
  rig.move(0, 100.0, 500.0);
  REQUIRE(rig.d[1] == Approx(100.0).margin(1e-12));

  rig.refusal.assign(2, plc::ErrorCode::kNone);
  rig.refusal[1] = plc::ErrorCode::kAxisInErrorState;
  rig.command(1, {mirror(1), direct(8)});
  rig.cycle();
  CHECK_FALSE(rig.unit(1).command_w.semaphor_rw);  // evaluated and reset all the same
  CHECK(rig.unit(1).state_r.error_r == 0x4F06);
  CHECK(rig.unit(1).state_r.active_r);
  CHECK(rig.unit(1).state_r.desc[0] ==
        h::HLI_AX_COUPLING_STATE_DESC{1, h::HLI_AXIS_COUPLING_DIRECT});
  CHECK(rig.unit(1).state_r.desc[1] == h::HLI_AX_COUPLING_STATE_DESC{});
  CHECK(rig.stop[1] == plc::ErrorCode::kNone);
  rig.move(0, 50.0, 500.0);  // still DIRECT
  CHECK(rig.d[1] == Approx(150.0).margin(1e-12));

  // The reason gone, the same list is taken.
  rig.refusal[1] = plc::ErrorCode::kNone;
  rig.command(1, {mirror(1), direct(8)});
  rig.cycle();
  CHECK(rig.unit(1).state_r.error_r == 0);
  rig.move(0, 50.0, 500.0);
  CHECK(rig.d[1] == Approx(100.0).margin(1e-12));
}

TEST_CASE("source_of_other: sources of other axes' lists in force, not self entries", "[hli]") {
  Rig rig({1, 2, 3});
  rig.command(1, {direct(1), direct(2)});  // B ← A, B
  rig.cycle();
  CHECK(rig.stage.source_of_other(0));
  CHECK_FALSE(rig.stage.source_of_other(1));
  CHECK_FALSE(rig.stage.source_of_other(2));
  rig.command(2, {fract(2, 1, 2), direct(2)});  // C ← B, B (a source named twice)
  rig.cycle();
  CHECK(rig.stage.source_of_other(1));
  rig.command(1, {inactive()});  // B off: A is no source any more, B still is (C's list)
  rig.cycle();
  CHECK_FALSE(rig.stage.source_of_other(0));
  CHECK(rig.stage.source_of_other(1));
  rig.stage.stop(2);  // C stopped: nothing is a source
  CHECK_FALSE(rig.stage.source_of_other(1));
  rig.stage.release(2);  // no list in force: nothing happens
  CHECK_FALSE(rig.stage.coupled(2));
}

TEST_CASE("release: the list goes off in place, no braking; stop: braking v²/2a", "[hli]") {
  nc::hli::AxisSetup setup;
  setup.emergency_deceleration = 1000.0;
  Rig rig({1, 8}, setup);
  rig.command(1, {direct(1)});
  rig.cycle();
  rig.q[0] = 0.0;
  for (int k = 0; k < 100; ++k) {  // axis 1 at 500 mm/s
    rig.q[0] += 0.5;
    rig.qv[0] = 500.0;
    rig.cycle();
  }
  const double held = rig.d[1];
  REQUIRE(held == Approx(50.0).margin(1e-12));
  REQUIRE(rig.dv[1] == 500.0);
  rig.stage.release(1);
  CHECK_FALSE(rig.stage.coupled(1));
  CHECK_FALSE(rig.stage.braking(1));
  CHECK_FALSE(rig.unit(1).state_r.active_r);
  for (int k = 0; k < 10; ++k) {
    rig.q[0] += 0.5;
    rig.cycle();
  }
  CHECK(rig.d[1] == held);  // at once: it does not follow, nor coast on
  CHECK(rig.dv[1] == 0.0);

  // stop() on a target moving at 500 mm/s: it comes to rest 500²/(2·1000) = 125 mm further on.
  rig.command(1, {direct(1)});
  rig.qv[0] = 0.0;
  rig.cycle();
  REQUIRE(rig.stage.coupled(1));
  for (int k = 0; k < 100; ++k) {
    rig.q[0] += 0.5;
    rig.qv[0] = 500.0;
    rig.cycle();
  }
  const double at_stop = rig.d[1];
  rig.stage.stop(1);
  CHECK(rig.stage.braking(1));
  for (int k = 0; k < 1000; ++k) {
    rig.q[0] += 0.5;
    rig.cycle();
  }
  CHECK(rig.dv[1] == 0.0);
  CHECK(rig.d[1] - at_stop == Approx(125.0).margin(1e-9));
}
