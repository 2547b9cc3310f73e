// MC_NewPosAndVelo beyond the six cases (SPEC B6, seed 000 §2.4): iterative velocity reduction
// when VNew is not reachable (halving the difference to the current speed, 8 attempts, the table
// kept when none fits), suspension in the brake phase, the Event 1 … 4 replacement rules, and
// the override on top. Seed axis, VOld = 1000 mm/s, the request at Pos = 1150 mm (cruise).
#include <catch2/catch.hpp>

#include <algorithm>

#include "kernel_harness.hpp"

using plc::CommandState;

namespace {

// 0 → 5000 mm at 1000 mm/s, run to 1150 mm; the move's number.
uint16_t cruise_at_1150(kt::Harness& h, kt::LimitChecker& c) {
  const uint16_t move = h.post(kt::move_absolute(5000.0, 1000.0));
  kt::checked_cycles(h, c, 1300);
  REQUIRE(h.x->NcToPlc.SetPos == Approx(1150.0).margin(1e-9));
  return move;
}

// Runs to the end of the job (kDone of `move`); the highest set velocity on the way.
double peak_until_done(kt::Harness& h, kt::LimitChecker& c, uint16_t move) {
  double peak = 0.0;
  const int n = kt::checked_cycles_until(h, c, [&] {
    peak = std::max(peak, h.x->NcToPlc.SetVelo);
    return h.state_of(move) == CommandState::kDone;
  });
  REQUIRE(n > 0);
  return peak;
}

}  // namespace

TEST_CASE(
    "VNew not reachable: the level is reduced iteratively, 2000 -> 1500 -> 1250 mm/s, and held",
    "[new_pos_and_velo][reduction]") {
  // 500 mm left: 2000 needs 450 mm up and 500 mm down, 1500 needs 250 + 300 mm; 1250 needs
  // 159 + 219 mm and fits with a plateau.
  kt::Harness h;
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
  cruise_at_1150(h, c);
  h.post(kt::new_pos_and_velo(1650.0, 2000.0, 0.0));  // case 2: at once
  kt::checked_cycles(h, c, 1);
  CHECK(h.x->NcToPlc.TargetVelo == Approx(1250.0).margin(1e-9));
  int at_level = 0;
  double peak = 0.0;
  REQUIRE(kt::checked_cycles_until(h, c, [&] {
            const double v = h.x->NcToPlc.SetVelo;
            peak = std::max(peak, v);
            if (v == Approx(1250.0).margin(1e-9)) ++at_level;
            return h.x->NcToPlc.SetVelo == 0.0;
          }) > 0);
  CHECK(peak == Approx(1250.0).margin(1e-9));
  CHECK(at_level > 50);  // a plateau, not a touch
  CHECK(h.x->NcToPlc.SetPos == 1650.0);
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE("VNew not reachable at any of the 8 levels: the table with VOld is kept",
          "[new_pos_and_velo][reduction]") {
  // 165 mm left: even the last level, 1007.8 mm/s, needs 25 + 152 mm. The motion is the one a
  // plain new end position gives.
  kt::TwinKernels t;
  kt::LimitChecker c = kt::LimitChecker::seed(1000.0);
  t.both(kt::move_absolute(5000.0, 1000.0));
  t.cycles(1300);
  const uint16_t request = t.probe.post(kt::new_pos_and_velo(1315.0, 2000.0, 0.0));
  t.reference.post(kt::new_pos(1315.0));
  for (int i = 0; i < 600; ++i) {
    t.cycles(1);
    c.check(*t.probe.x);
    REQUIRE(t.probe.x->NcToPlc.SetPos == t.reference.x->NcToPlc.SetPos);
    REQUIRE(t.probe.x->NcToPlc.SetVelo == t.reference.x->NcToPlc.SetVelo);
  }
  CHECK(t.probe.state_of(request) == CommandState::kDone);
  CHECK(t.probe.x->NcToPlc.SetPos == 1315.0);
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE("a request in the brake phase: the braking goes on and the new velocity is suspended",
          "[new_pos_and_velo][brake]") {
  // 0 → 3000 mm at 2000 mm/s, braking from 1.5 s on. Same end, VNew 1000 at once (case 2):
  // nothing to change in a brake; the job ends at 3000 mm like its undisturbed twin.
  kt::TwinKernels t;
  const uint16_t move = t.both(kt::move_absolute(3000.0, 2000.0));
  t.cycles(1600);
  REQUIRE(t.probe.x->NcToPlc.SetAcc < 0.0);
  t.probe.post(kt::new_pos_and_velo(3000.0, 1000.0, 0.0));
  for (int i = 0; i < 450; ++i) {
    t.cycles(1);
    REQUIRE(t.probe.x->NcToPlc.SetPos == Approx(t.reference.x->NcToPlc.SetPos).margin(1e-9));
    REQUIRE(t.probe.x->NcToPlc.SetVelo == Approx(t.reference.x->NcToPlc.SetVelo).margin(1e-9));
  }
  CHECK(t.probe.state_of(move) == CommandState::kDone);
  CHECK(t.probe.x->NcToPlc.SetPos == 3000.0);
}

TEST_CASE(
    "a request in the brake phase whose new end position ends the braking: the suspended "
    "velocity acts at once",
    "[new_pos_and_velo][brake]") {
  kt::Harness h;
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
  const uint16_t move = h.post(kt::move_absolute(3000.0, 2000.0));
  kt::checked_cycles(h, c, 1600);
  const double v_then = h.x->NcToPlc.SetVelo;
  REQUIRE(v_then > 1000.0);
  h.post(kt::new_pos_and_velo(6000.0, 1000.0, 0.0));
  kt::checked_cycles(h, c, 1);
  CHECK(h.x->NcToPlc.TargetVelo == 1000.0);
  kt::checked_cycles(h, c, 500);
  CHECK(h.x->NcToPlc.SetVelo == Approx(1000.0).margin(1e-9));  // down to VNew, held
  const double peak = peak_until_done(h, c, move);
  CHECK(peak == Approx(1000.0).margin(1e-9));
  CHECK(h.x->NcToPlc.SetPos == 6000.0);
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE(
    "Event rules: an instantaneous-only request deletes a pending activation; one with a "
    "later activation replaces it",
    "[new_pos_and_velo][events]") {
  SECTION("Event 1/2 (APos 2000, VNew 2000) interrupted by Event 3 only (case 4): deleted") {
    kt::Harness h;
    kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
    const uint16_t move = cruise_at_1150(h, c);
    h.post(kt::new_pos_and_velo(4000.0, 2000.0, 2000.0));  // case 1
    kt::checked_cycles(h, c, 100);
    h.post(kt::new_pos_and_velo(4500.0, 1500.0, 4800.0));  // case 4: instantaneous only
    const double peak = peak_until_done(h, c, move);
    CHECK(peak == Approx(1000.0).margin(1e-9));  // VNew never acts, also not past 2000 mm
    CHECK(h.x->NcToPlc.SetPos == 4500.0);
    INFO(c.first);
    CHECK(c.ok());
  }
  SECTION("interrupted by MC_NewPos (instantaneous only): deleted") {
    kt::Harness h;
    kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
    const uint16_t move = cruise_at_1150(h, c);
    h.post(kt::new_pos_and_velo(4000.0, 2000.0, 2000.0));
    kt::checked_cycles(h, c, 100);
    h.post(kt::new_pos(4500.0));
    const double peak = peak_until_done(h, c, move);
    CHECK(peak == Approx(1000.0).margin(1e-9));
    CHECK(h.x->NcToPlc.SetPos == 4500.0);
  }
  SECTION("interrupted by Event 3/4 (APos 3000, VNew 1500): Event 4 replaces Event 2") {
    kt::Harness h;
    kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
    const uint16_t move = cruise_at_1150(h, c);
    h.post(kt::new_pos_and_velo(4000.0, 2000.0, 2000.0));
    kt::checked_cycles(h, c, 100);
    h.post(kt::new_pos_and_velo(4500.0, 1500.0, 3000.0));  // case 1 again
    double peak_before = 0.0;
    REQUIRE(kt::checked_cycles_until(h, c, [&] {
              peak_before = std::max(peak_before, h.x->NcToPlc.SetVelo);
              return h.x->NcToPlc.SetPos >= 3000.0;
            }) > 0);
    CHECK(peak_before == Approx(1000.0).margin(1e-9));  // nothing at 2000 mm
    const double peak = peak_until_done(h, c, move);
    CHECK(peak == Approx(1500.0).margin(1e-9));  // VNew of Event 4 from 3000 mm on
    CHECK(h.x->NcToPlc.SetPos == 4500.0);
    INFO(c.first);
    CHECK(c.ok());
  }
}

TEST_CASE("the new velocity works with the override: VNew 2000 at 50 % gives 1000 mm/s",
          "[new_pos_and_velo][override]") {
  kt::Harness h;
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
  kt::set_override(*h.x, 50.0);
  const uint16_t move = h.post(kt::move_absolute(5000.0, 1000.0));  // 500 mm/s
  kt::checked_cycles(h, c, 1000);
  CHECK(h.x->NcToPlc.SetVelo == Approx(500.0).margin(1e-9));
  h.post(kt::new_pos_and_velo(5000.0, 2000.0, 0.0));
  kt::checked_cycles(h, c, 500);
  CHECK(h.x->NcToPlc.SetVelo == Approx(1000.0).margin(1e-9));
  kt::set_override(*h.x, 100.0);
  const double peak = peak_until_done(h, c, move);
  CHECK(peak == Approx(2000.0).margin(1e-9));
  CHECK(h.x->NcToPlc.SetPos == 5000.0);
  INFO(c.first);
  CHECK(c.ok());
}
