// The enable's Position is the target of the target-window monitoring while external setpoints
// drive the axis (seed 000 §2.6 "Activation"): absolute as given, relative added to the internal
// generator's target (or, at standstill, to the position at the enable). InTargetPosition follows
// the axis's window (2 mm held for 20 ms here).
#include <catch2/catch.hpp>

#include "kernel_harness.hpp"

TEST_CASE("absolute: InTargetPosition once the fed motion rests within the window of Position",
          "[ext_setpoint][target_window]") {
  for (double target : {100.0, 200.0}) {
    INFO("target " << target);
    kt::Harness h;
    h.post(kt::ext_enable(target, 1));
    h.cycles(1);
    CHECK(h.x->NcToPlc.TargetPos == target);
    for (int i = 1; i <= 200; ++i) {
      kt::feed(*h.x, 0.5 * i, 500.0, 0.0, 1);
      h.cycles(1);
      REQUIRE_FALSE(kt::bit(*h.x, plc::kStateInTargetPosition));
    }
    kt::feed(*h.x, 100.0, 0.0, 0.0, 0);
    const int cycles =
        h.cycles_until([&] { return kt::bit(*h.x, plc::kStateInTargetPosition); }, 500);
    if (target == 100.0) {
      // The window counts only once the fed motion rests (direction 0 from cycle 201 on):
      // 20 samples (20 ms) make it InTargetPosition 20 cycles after the last ramp packet.
      CHECK(cycles == 20);
    } else {
      CHECK(cycles == -1);
    }
  }
}

TEST_CASE("relative at standstill: the target is the position at the enable plus Position",
          "[ext_setpoint][target_window]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(50.0, 500.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == plc::CommandState::kDone; }) > 0);
  h.post(kt::ext_enable(30.0, 2));
  h.cycles(1);
  CHECK(h.x->NcToPlc.TargetPos == 80.0);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateInTargetPosition));
  for (int i = 1; i <= 60; ++i) {
    kt::feed(*h.x, 0.5 * i, 500.0, 0.0, 1);
    h.cycles(1);
  }
  kt::feed(*h.x, 30.0, 0.0, 0.0, 0);
  CHECK(h.cycles_until([&] { return kt::bit(*h.x, plc::kStateInTargetPosition); }, 500) > 0);
  CHECK(h.x->NcToPlc.SetPos == 80.0);
}

TEST_CASE("absolute: a fed motion crawling through the target window is not InTargetPosition",
          "[ext_setpoint][target_window]") {
  kt::Harness h;
  h.post(kt::ext_enable(100.0, 1));
  h.cycles(1);
  // 0 → 101 mm at 100 mm/s: the last 30 cycles lie inside the 2 mm window around 100 while the
  // generator still feeds a motion (direction +1) — more than the 20 ms window time.
  for (int i = 1; i <= 1010; ++i) {
    kt::feed(*h.x, 0.1 * i, 100.0, 0.0, 1);
    h.cycles(1);
    REQUIRE_FALSE(kt::bit(*h.x, plc::kStateInTargetPosition));
  }
  // The motion rests at 101 mm (direction 0): now the window counts, 20 samples.
  kt::feed(*h.x, 101.0, 0.0, 0.0, 0);
  CHECK(h.cycles_until([&] { return kt::bit(*h.x, plc::kStateInTargetPosition); }, 500) == 20);
}
