// New end position (SPEC B5, seed 000 §2.3; MC_NewPos) with the seed's figures, V = 2000 mm/s,
// A+ = A- = 5000 mm/s², J = 50000 mm/s³: the running positioning is replanned the quickest way;
// where the axis cannot stop before the new target it reverses and returns on its own; a V not
// reachable at the start is reached when the new distance allows it. The NewPos command is
// answered kDone when accepted; the positioning keeps CmdNo and ends kDone at the new target.
#include <catch2/catch.hpp>

#include <algorithm>

#include "kernel_harness.hpp"

using plc::CommandState;

TEST_CASE(
    "new end position during the stop phase: 0 -> 3000 mm, then 5000 mm during the final "
    "deceleration",
    "[new_pos]") {
  kt::Harness h;
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
  const uint16_t move = h.post(kt::move_absolute(3000.0, 2000.0));
  kt::checked_cycles(h, c, 1600);  // the final deceleration began at 1.5 s
  REQUIRE(h.x->NcToPlc.SetAcc < 0.0);
  REQUIRE(h.x->NcToPlc.SetVelo < 2000.0);
  const uint16_t new_pos = h.post(kt::new_pos(5000.0));
  kt::checked_cycles(h, c, 1);
  CHECK(h.state_of(new_pos) == CommandState::kDone);
  CHECK(h.state_of(move) == CommandState::kActive);
  CHECK(h.x->NcToPlc.CmdNo == move);
  CHECK(h.x->NcToPlc.TargetPos == 5000.0);
  double peak = 0.0;
  REQUIRE(kt::checked_cycles_until(h, c, [&] {
            peak = std::max(peak, h.x->NcToPlc.SetVelo);
            return h.state_of(move) == CommandState::kDone;
          }) > 0);
  CHECK(peak == Approx(2000.0).margin(1e-9));  // back up to V before the new end
  CHECK(h.x->NcToPlc.SetPos == 5000.0);
  CHECK(h.x->NcToPlc.ActPos == Approx(5000.0).margin(1e-4));
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE(
    "new end position with reversal: 0 -> 3000 mm, then 2000 mm when the axis can no longer "
    "stop before it",
    "[new_pos]") {
  kt::Harness h;
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
  const uint16_t move = h.post(kt::move_absolute(3000.0, 2000.0));
  kt::checked_cycles(h, c, 1150);  // 1800 mm at 2000 mm/s: the shortest stop ends at 2300 mm
  REQUIRE(h.x->NcToPlc.SetPos == Approx(1800.0).margin(1e-9));
  const uint16_t new_pos = h.post(kt::new_pos(2000.0));
  kt::checked_cycles(h, c, 1);
  CHECK(h.state_of(new_pos) == CommandState::kDone);
  double furthest = 0.0;
  double most_negative = 0.0;
  REQUIRE(kt::checked_cycles_until(h, c, [&] {
            furthest = std::max(furthest, h.x->NcToPlc.SetPos);
            most_negative = std::min(most_negative, h.x->NcToPlc.SetVelo);
            return h.state_of(move) == CommandState::kDone;
          }) > 0);
  // Brakes as hard as allowed and passes v = 0 at full deceleration (one continuous profile,
  // no stop at the turning point): 0.1 s of jerk (2000·0.1 - J·0.1³/6 = 191.667 mm) then A- from
  // 1750 mm/s down (1750²/(2·5000) = 306.25 mm); returns on its own, ends exactly at 2000 mm.
  CHECK(furthest == Approx(1800.0 + 200.0 - 50000.0 * 0.001 / 6.0 + 306.25).margin(1e-6));
  CHECK(most_negative < -100.0);
  CHECK(h.x->NcToPlc.SetPos == 2000.0);
  CHECK(h.x->NcToPlc.CmdNo == move);
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE("a V not reachable at the start is reached after a new end position allows it",
          "[new_pos]") {
  // 0 → 600 mm at V 2000: the start level is reduced to 1500 mm/s (600 = v²/A + v·A/J).
  kt::Harness h;
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
  const uint16_t move = h.post(kt::move_absolute(600.0, 2000.0));
  kt::checked_cycles(h, c, 1);
  CHECK(h.x->NcToPlc.TargetVelo == Approx(1500.0).margin(1e-9));
  kt::checked_cycles(h, c, 199);
  h.post(kt::new_pos(5000.0));
  double peak = 0.0;
  REQUIRE(kt::checked_cycles_until(h, c, [&] {
            peak = std::max(peak, h.x->NcToPlc.SetVelo);
            return h.state_of(move) == CommandState::kDone;
          }) > 0);
  CHECK(peak == Approx(2000.0).margin(1e-9));
  CHECK(h.x->NcToPlc.SetPos == 5000.0);
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE(
    "a re-triggered aborting MoveAbsolute gives the same motion as MC_NewPos; only the command "
    "numbers differ",
    "[new_pos]") {
  kt::TwinKernels t;
  const uint16_t move = t.both(kt::move_absolute(3000.0, 2000.0));
  t.cycles(1600);
  const uint16_t np = t.probe.post(kt::new_pos(5000.0));
  const uint16_t again = t.reference.post(kt::move_absolute(5000.0, 2000.0));
  for (int i = 0; i < 3000; ++i) {
    t.cycles(1);
    REQUIRE(t.probe.x->NcToPlc.SetPos == t.reference.x->NcToPlc.SetPos);
    REQUIRE(t.probe.x->NcToPlc.SetVelo == t.reference.x->NcToPlc.SetVelo);
  }
  CHECK(t.probe.state_of(np) == CommandState::kDone);
  CHECK(t.probe.state_of(move) == CommandState::kDone);
  CHECK(t.reference.state_of(move) == CommandState::kAborted);
  CHECK(t.reference.state_of(again) == CommandState::kDone);
}
