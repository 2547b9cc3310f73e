// Slave compensation (SPEC C5, seed 000 §3.2.4) with the seed's figures: master 0 → 10000 mm at
// V 2000, slave factor 1.0, compensation D 500, L 5000, VK 300, VP 2000, AK+ 500, AK- 1000
// requested once the master cruises at VP: the slave from -500 makes up fully and ends at 10000;
// from 5000 with D -500 it slows down and ends at 14500. Down a cascade the next slave sees the
// compensated set position (its own compensation adds on top), independent of the factor; the
// compensation runs with the master's path (override 0 holds it, and the time at rest is lost as
// for masters: less than D, warning 0x4243); decoupling during it keeps
// the basic dynamics and the compensation velocity (continuous), and it never completes.
// Refusals: master at rest (0x424E), master stopping (0x4242), one already running (0x4245).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>

#include "gear_rig.hpp"

namespace {

using plc::CommandState;

plc::Command seed_compensation(double distance, double process_velocity = 2000.0,
                               double length = 5000.0) {
  return kt::move_superimposed(distance, 300.0, 500.0, 1000.0, process_velocity, length);
}

// Axis 1 (and 2, when `cascade`) placed at their start positions and coupled with factor 1
// (axis 2 to axis 1 with `factor2`); the master started 0 → 10000 at V 2000 and run to VP.
void start(gr::Rig& rig, double slave_start, bool cascade = false, double factor2 = 1.0) {
  rig.move_to(1, slave_start);
  REQUIRE(rig.couple(1, 0, 1.0).state == CommandState::kReached);
  if (cascade) REQUIRE(rig.couple(2, 1, factor2).state == CommandState::kReached);
  rig.post(0, kt::move_absolute(10000.0, 2000.0));
  rig.cycles(600);
  REQUIRE(rig.at(0).NcToPlc.SetVelo == 2000.0);
}

// Runs until the master's move is done and the axes settle.
void run_to_end(gr::Rig& rig) {
  rig.cycles(10);
  for (int i = 0; i < 20000 && rig.at(0).NcToPlc.SetVelo != 0.0; ++i)
    rig.kernel.cycle();
  rig.cycles(10);
}

// After a decoupling during a compensation the former slave runs the head's plan times `scale`:
// runs it until it stands, checking every cycle against the seed axis's limits times `scale`
// (V `velocity`).
void run_scaled_plan_to_rest(gr::Rig& rig, double velocity, double scale) {
  kt::LimitChecker checker = kt::LimitChecker::seed(velocity * (1.0 + 1e-9));
  checker.acceleration = 5000.0 * scale;
  checker.deceleration = checker.acceleration;
  checker.jerk = 50000.0 * scale;
  for (int i = 0; i < 20000 && !(rig.at(1).NcToPlc.SetVelo == 0.0 && i > 10); ++i) {
    rig.kernel.cycle();
    checker.check(rig.at(1));
  }
  INFO(checker.first);
  CHECK(checker.ok());
}

}  // namespace

TEST_CASE("slave compensation, seed figure 'making up fully'': from -500 with D 500 ends at 10000",
          "[gear][compensation]") {
  gr::Rig rig(2);
  start(rig, -500.0);
  const uint16_t n = rig.post(1, seed_compensation(500.0));
  rig.kernel.cycle();
  REQUIRE(rig.answer(1, n).state == CommandState::kActive);
  CHECK(kt::bit(rig.at(1), plc::kStateCompensating));
  CHECK(rig.at(1).NcToPlc.CoupleState == 3U);
  CHECK(rig.at(1).NcToPlc.TargetPos == 10000.0);  // the compensated end
  // The slave runs ahead of the master, at most VK = 300 mm/s faster (D over L needs less).
  double peak = 0.0;
  for (int i = 0; i < 4000; ++i) {
    rig.kernel.cycle();
    peak = std::fmax(peak, rig.at(1).NcToPlc.SetVelo - rig.at(0).NcToPlc.SetVelo);
  }
  CHECK(peak > 200.0);
  CHECK(peak <= 300.0);
  run_to_end(rig);
  CHECK(rig.answer(1, n).state == CommandState::kDone);
  CHECK(rig.at(0).NcToPlc.SetPos == 10000.0);
  CHECK(rig.at(1).NcToPlc.SetPos == Approx(10000.0).margin(1e-6));
  CHECK(rig.at(1).NcToPlc.CompensationDistance == Approx(500.0).margin(1e-6));
  CHECK(rig.at(1).NcToPlc.Warning == 0U);
}

TEST_CASE("slave compensation, seed figure 'slows down': from 5000 with D -500 ends at 14500",
          "[gear][compensation]") {
  gr::Rig rig(2);
  start(rig, 5000.0);
  const uint16_t n = rig.post(1, seed_compensation(-500.0));
  run_to_end(rig);
  CHECK(rig.answer(1, n).state == CommandState::kDone);
  CHECK(rig.at(1).NcToPlc.SetPos == Approx(14500.0).margin(1e-6));
  CHECK(rig.at(0).NcToPlc.SetPos == 10000.0);
}

TEST_CASE("a compensation is passed down a cascade; compensations of a cascade add",
          "[gear][compensation]") {
  for (const double factor2 : {1.0, -0.5}) {
    INFO("factor of the second slave " << factor2);
    gr::Rig rig(3);
    start(rig, -500.0, true, factor2);
    const double offset2 = rig.at(2).NcToPlc.SetPos - factor2 * rig.at(1).NcToPlc.SetPos;
    const uint16_t n1 = rig.post(1, seed_compensation(500.0));
    rig.cycles(200);
    // VP and L in axis 2's own path: |factor| × the master's.
    const double k = std::abs(factor2);
    const uint16_t n2 = rig.post(2, seed_compensation(250.0, k * 2000.0, k * 5000.0));
    for (int i = 0; i < 20000 && rig.at(0).NcToPlc.SetVelo != 0.0; ++i) {
      rig.kernel.cycle();
      // Axis 2's basic position is factor × axis 1's compensated one; its own comes on top.
      REQUIRE(std::abs(rig.at(2).NcToPlc.SetPos - (factor2 * rig.at(1).NcToPlc.SetPos + offset2)) <=
              250.0 + 1e-6);
    }
    rig.cycles(10);
    CHECK(rig.answer(1, n1).state == CommandState::kDone);
    CHECK(rig.answer(2, n2).state == CommandState::kDone);
    CHECK(rig.at(1).NcToPlc.SetPos == Approx(10000.0).margin(1e-6));
    // D is relative to the direction of travel, independent of the factor.
    const double direction = factor2 > 0.0 ? 1.0 : -1.0;
    CHECK(rig.at(2).NcToPlc.SetPos ==
          Approx(factor2 * 10000.0 + offset2 + direction * 250.0).margin(1e-6));
  }
}

TEST_CASE("a slave's compensation pauses with its master's override 0 and goes on after",
          "[gear][compensation]") {
  gr::Rig rig(2);
  start(rig, -500.0);
  const uint16_t n = rig.post(1, seed_compensation(500.0));
  rig.cycles(300);
  kt::set_override(rig.at(0), 0.0);
  rig.cycles(1500);
  REQUIRE(rig.at(0).NcToPlc.SetVelo == 0.0);
  const double held = rig.at(1).NcToPlc.SetPos;
  rig.cycles(500);
  CHECK(rig.at(1).NcToPlc.SetPos == held);  // linear path control: it stands with the master
  CHECK(rig.answer(1, n).state == CommandState::kActive);
  kt::set_override(rig.at(0), 100.0);
  run_to_end(rig);
  // It runs in time over T = L / VP (SPEC B7 decision): the time at rest compensated nothing,
  // so less than D is done (seed 000 §3.2.4 note 3 "for stop or override 0.0") — warning 0x4243.
  CHECK(rig.answer(1, n).state == CommandState::kDone);
  CHECK(rig.at(1).NcToPlc.SetPos < 10000.0 - 1.0);
  CHECK(rig.at(1).NcToPlc.SetPos > 9500.0);
  CHECK(rig.at(1).NcToPlc.Warning == kt::id(plc::ErrorCode::kCompensationIncomplete));
}

TEST_CASE("decoupling during a slave's compensation keeps its velocity; it never completes",
          "[gear][compensation][decouple]") {
  gr::Rig rig(2);
  start(rig, -500.0);
  const uint16_t n = rig.post(1, seed_compensation(500.0));
  rig.cycles(1500);  // the compensation is in its constant phase (about 232 over the basic 2000)
  const double v_before = rig.at(1).NcToPlc.SetVelo;
  REQUIRE(v_before > 2200.0);
  REQUIRE(rig.at(1).NcToPlc.SetAcc == 0.0);
  const double scale = v_before / 2000.0;  // 1 + c
  REQUIRE(rig.decouple(1).state == CommandState::kDone);
  CHECK(rig.at(1).NcToPlc.SetVelo == Approx(v_before).epsilon(1e-12));
  CHECK(rig.answer(1, n).state == CommandState::kAborted);
  CHECK_FALSE(kt::bit(rig.at(1), plc::kStateCompensating));
  const double p0 = rig.at(1).NcToPlc.SetPos;
  const double m0 = rig.at(0).NcToPlc.SetPos;
  rig.post(0, kt::simple(plc::CommandType::kStop));  // the former master's stop does not reach it
  run_scaled_plan_to_rest(rig, v_before, scale);     // the head's plan times 1 + c
  // The head's remaining way 10000 - m0, scaled by 1 + c: D is never "completed".
  CHECK(rig.at(1).NcToPlc.SetPos == Approx(p0 + (10000.0 - m0) * scale).epsilon(1e-9));
  CHECK(std::abs(rig.at(1).NcToPlc.SetPos - 10000.0) > 1.0);
  CHECK(rig.at(1).NcToPlc.SetVelo == 0.0);
}

TEST_CASE("slave compensation refusals: master at rest, master stopping, one already running",
          "[gear][compensation][refusal]") {
  gr::Rig rig(2);
  REQUIRE(rig.couple(1, 0, 1.0).state == CommandState::kReached);
  uint16_t n = rig.post(1, seed_compensation(500.0));
  rig.kernel.cycle();
  CHECK(rig.answer(1, n).error_code == kt::id(plc::ErrorCode::kFunctionNotAllowed));
  rig.post(0, kt::move_absolute(10000.0, 2000.0));
  rig.cycles(600);
  n = rig.post(1, seed_compensation(500.0));
  rig.kernel.cycle();
  REQUIRE(rig.answer(1, n).state == CommandState::kActive);
  const uint16_t again = rig.post(1, seed_compensation(100.0));
  rig.kernel.cycle();
  CHECK(rig.answer(1, again).error_code == kt::id(plc::ErrorCode::kCompensationActive));
  rig.cycles(3000);
  rig.post(0, kt::simple(plc::CommandType::kHalt));
  rig.cycles(2);
  const uint16_t stopping = rig.post(1, seed_compensation(100.0));
  rig.kernel.cycle();
  CHECK(rig.answer(1, stopping).error_code == kt::id(plc::ErrorCode::kStopAlreadyActive));
}

TEST_CASE("decoupling during the master's compensation keeps the slave's velocity",
          "[gear][compensation][decouple]") {
  gr::Rig rig(2);
  REQUIRE(rig.couple(1, 0, 0.5).state == CommandState::kReached);
  rig.post(0, kt::move_absolute(10000.0, 2000.0));
  rig.cycles(600);
  const uint16_t n = rig.post(0, seed_compensation(500.0));
  rig.cycles(1500);
  const double v_before = rig.at(1).NcToPlc.SetVelo;
  REQUIRE(v_before > 0.5 * 2200.0);  // the master's compensation reaches the slave
  REQUIRE(rig.decouple(1).state == CommandState::kDone);
  CHECK(rig.at(1).NcToPlc.SetVelo == Approx(v_before).epsilon(1e-12));
  const double scale = v_before / 1000.0;  // 0.5 × (1 + c)
  run_scaled_plan_to_rest(rig, v_before, scale);
  CHECK(rig.at(1).NcToPlc.SetVelo == 0.0);
  // The master's own compensation goes on and completes there.
  rig.cycles(100);
  CHECK(rig.answer(0, n).state == CommandState::kDone);
  CHECK(rig.at(0).NcToPlc.SetPos == Approx(10500.0).margin(1e-6));
}
