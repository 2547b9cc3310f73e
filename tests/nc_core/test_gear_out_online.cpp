// SPEC C4 (seed 000 §3.2.3): online decoupling. A slave decoupled while its master moves goes on
// exactly as it would have as a slave — compared bit for bit with a twin kernel in which nothing
// decouples — while its former master is stopped; it then stops on its own MC_Stop with its own
// dynamics, takes a new end position with or against its direction of travel (ends exactly
// there, limits respected every cycle), and its override relates to |last factor| × the former
// master's target velocity. Seed figures: master 0 → 20000 mm at V 2000, factors 1.0, 0.5, 0.8,
// -0.8, 0.75; the cascade case decouples the middle and the last axis of a 3-axis cascade.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>

#include "gear_rig.hpp"
#include "nc_core/profile.hpp"

namespace {

using plc::CommandState;

// The master (axis 0) cruising at 2000 mm/s on its way 0 → 20000, axis 1 coupled at 0 with
// `factor` before the start.
void start_seed_figure(gr::Rig& rig, double factor) {
  REQUIRE(rig.couple(1, 0, factor).state == CommandState::kReached);
  rig.post(0, kt::move_absolute(20000.0, 2000.0));
  rig.cycles(1000);  // the master has reached V after about 0.45 s
  REQUIRE(rig.at(0).NcToPlc.SetVelo == 2000.0);
}

bool same_set_values(const plc::AXIS_REF& a, const plc::AXIS_REF& b) {
  return a.NcToPlc.SetPos == b.NcToPlc.SetPos && a.NcToPlc.SetVelo == b.NcToPlc.SetVelo &&
         a.NcToPlc.SetAcc == b.NcToPlc.SetAcc && a.NcToPlc.SetJerk == b.NcToPlc.SetJerk;
}

// Limits of an axis after decoupling: V = |factor| × 2000, the seed axis's own A± and J.
kt::LimitChecker limits_after(double factor) {
  return kt::LimitChecker::seed(std::abs(factor) * 2000.0);
}

}  // namespace

TEST_CASE(
    "a slave decoupled at master velocity 2000 goes on as the undisturbed slave while the former "
    "master stops (factors 1.0 and 0.5)",
    "[gear][decouple]") {
  for (const double factor : {1.0, 0.5}) {
    INFO("factor " << factor);
    gr::Rig probe(2);
    gr::Rig twin(2);
    start_seed_figure(probe, factor);
    start_seed_figure(twin, factor);

    const uint16_t out = probe.post(1, gr::gear_out());
    probe.kernel.cycle();
    twin.kernel.cycle();
    CHECK(probe.answer(1, out).state == CommandState::kDone);
    CHECK(probe.at(1).NcToPlc.CoupleState == 0);
    CHECK(probe.at(0).NcToPlc.CoupleState == 0);
    CHECK_FALSE(kt::bit(probe.at(1), plc::kStateCoupled));
    CHECK(kt::bit(probe.at(1), plc::kStateHasJob));
    CHECK(kt::axis_state(probe.at(1)) == plc::AxisState::kDiscreteMotion);
    CHECK(same_set_values(probe.at(1), twin.at(1)));

    // The former master stops; no change of it reaches the former slave.
    probe.post(0, kt::simple(plc::CommandType::kStop));
    for (int i = 0; i < 1000; ++i) {
      probe.kernel.cycle();
      twin.kernel.cycle();
      REQUIRE(same_set_values(probe.at(1), twin.at(1)));
    }
    CHECK(probe.at(0).NcToPlc.SetVelo == 0.0);
    CHECK(probe.at(1).NcToPlc.SetVelo == factor * 2000.0);
    CHECK(probe.at(1).NcToPlc.TargetPos == factor * 20000.0);

    // Its own MC_Stop with 0 for deceleration and jerk: the axis's defaults (5000, 50000).
    const nc::KinematicState from{probe.at(1).NcToPlc.SetPos, probe.at(1).NcToPlc.SetVelo,
                                  probe.at(1).NcToPlc.SetAcc};
    const double expected_end = nc::plan_stop(from, 5000.0, 50000.0).final_state().p;
    kt::LimitChecker checker = limits_after(factor);
    const uint16_t stop = probe.post(1, kt::simple(plc::CommandType::kStop));
    int cycles = 0;
    while (probe.answer(1, stop).state != CommandState::kDone && cycles < 5000) {
      probe.kernel.cycle();
      checker.check(probe.at(1));
      ++cycles;
    }
    REQUIRE(probe.answer(1, stop).state == CommandState::kDone);
    CHECK(checker.ok());
    INFO(checker.first);
    CHECK(probe.at(1).NcToPlc.SetPos == expected_end);
    CHECK(probe.at(1).NcToPlc.SetVelo == 0.0);
    // The stop took D 5000 / J 50000: about v/D + D/J.
    CHECK(cycles == Approx(1000.0 * (factor * 2000.0 / 5000.0 + 0.1)).margin(2.0));
  }
}

TEST_CASE(
    "decoupling and a new end position: ends exactly there with the limits respected (0.8 "
    "forward, -0.8 backward, 0.75 against the direction)",
    "[gear][decouple]") {
  struct Case {
    double factor;
    double distance;  // from the slave's position at decoupling to its new end
  };
  for (const Case c : {Case{0.8, 3000.0}, Case{-0.8, -3000.0}, Case{0.75, -1000.0}}) {
    INFO("factor " << c.factor << ", distance " << c.distance);
    gr::Rig rig(2);
    start_seed_figure(rig, c.factor);
    kt::LimitChecker checker = limits_after(c.factor);
    checker.check(rig.at(1));
    REQUIRE(rig.decouple(1).state == CommandState::kDone);
    checker.check(rig.at(1));
    const double target = rig.at(1).NcToPlc.SetPos + c.distance;
    const uint16_t n = rig.post(1, kt::new_pos(target));
    rig.kernel.cycle();
    checker.check(rig.at(1));
    REQUIRE(rig.answer(1, n).state == CommandState::kDone);
    CHECK(rig.at(1).NcToPlc.TargetPos == target);
    int cycles = 0;
    while (!(rig.at(1).NcToPlc.SetVelo == 0.0 && !kt::bit(rig.at(1), plc::kStateHasJob)) &&
           cycles < 20000) {
      rig.kernel.cycle();
      checker.check(rig.at(1));
      ++cycles;
    }
    INFO(checker.first);
    CHECK(checker.ok());
    CHECK(rig.at(1).NcToPlc.SetPos == target);
    CHECK(rig.at(1).NcToPlc.ActPos == Approx(target).margin(1e-6));
    CHECK(kt::bit(rig.at(1), plc::kStateInTargetPosition));
    // The former master went on: its plan is its own.
    CHECK(rig.at(0).NcToPlc.SetVelo != 0.0);
  }
}

TEST_CASE("after online decoupling the override relates to |last factor| x the master's V",
          "[gear][decouple]") {
  gr::Rig rig(2);
  start_seed_figure(rig, -0.5);
  REQUIRE(rig.decouple(1).state == CommandState::kDone);
  kt::set_override(rig.at(1), 30.0);
  rig.cycles(1000);
  CHECK(rig.at(1).NcToPlc.SetVelo == Approx(-0.3 * 0.5 * 2000.0).epsilon(1e-12));
  kt::set_override(rig.at(1), 100.0);
  rig.cycles(1000);
  CHECK(rig.at(1).NcToPlc.SetVelo == Approx(-0.5 * 2000.0).epsilon(1e-12));
  // The master's own override no longer reaches it.
  kt::set_override(rig.at(0), 10.0);
  rig.cycles(1000);
  CHECK(rig.at(0).NcToPlc.SetVelo == Approx(200.0).epsilon(1e-12));
  CHECK(rig.at(1).NcToPlc.SetVelo == Approx(-1000.0).epsilon(1e-12));
}

TEST_CASE("decoupling in a moving cascade: each part goes on as before, in any order",
          "[gear][decouple]") {
  for (const bool middle_first : {true, false}) {
    INFO((middle_first ? "middle first" : "last first"));
    gr::Rig probe(3);
    gr::Rig twin(3);
    for (gr::Rig* rig : {&probe, &twin}) {
      REQUIRE(rig->couple(1, 0, 2.0 / 3.0).state == CommandState::kReached);
      REQUIRE(rig->couple(2, 1, -0.75).state == CommandState::kReached);
      rig->post(0, kt::move_absolute(20000.0, 1500.0));
      rig->cycles(1000);
    }
    const std::size_t first = middle_first ? 1 : 2;
    const std::size_t second = middle_first ? 2 : 1;
    REQUIRE(probe.decouple(first).state == CommandState::kDone);
    twin.kernel.cycle();
    for (std::size_t i : {1U, 2U})
      REQUIRE(same_set_values(probe.at(i), twin.at(i)));
    probe.cycles(100);
    twin.cycles(100);
    REQUIRE(probe.decouple(second).state == CommandState::kDone);
    twin.kernel.cycle();
    probe.post(0, kt::simple(plc::CommandType::kStop));
    for (int i = 0; i < 1000; ++i) {
      probe.kernel.cycle();
      twin.kernel.cycle();
      for (std::size_t a : {1U, 2U})
        REQUIRE(same_set_values(probe.at(a), twin.at(a)));
    }
    for (std::size_t a : {0U, 1U, 2U})
      CHECK(probe.at(a).NcToPlc.CoupleState == 0);
    CHECK(probe.at(2).NcToPlc.SetVelo == -0.75 * (2.0 / 3.0) * 1500.0);
  }
}

TEST_CASE("decoupling at override 0 is offline: the slave holds as a PTP master",
          "[gear][decouple]") {
  gr::Rig rig(2);
  REQUIRE(rig.couple(1, 0, 0.75).state == CommandState::kReached);
  rig.post(0, kt::move_absolute(20000.0, 2000.0));
  rig.cycles(500);
  kt::set_override(rig.at(0), 0.0);
  rig.cycles(1500);
  REQUIRE(rig.at(1).NcToPlc.SetVelo == 0.0);
  const double p = rig.at(1).NcToPlc.SetPos;
  REQUIRE(rig.decouple(1).state == CommandState::kDone);
  CHECK_FALSE(kt::bit(rig.at(1), plc::kStateHasJob));
  kt::set_override(rig.at(0), 100.0);
  rig.cycles(500);
  CHECK(rig.at(1).NcToPlc.SetPos == p);
  CHECK(rig.at(0).NcToPlc.SetVelo > 0.0);
}

TEST_CASE(
    "online decoupling is refused (0x424D) when the head runs no PTP job; nothing changes on any "
    "axis",
    "[gear][decouple][refusal]") {
  // The master moves by absolute external setpoints (seed 000 §2.6): there is no plan to go on
  // with. The slave follows it; MC_GearOut goes to the probe only.
  gr::TwinRigs t(3, {});
  t.both(1, gr::gear_in(0, 0.5));
  t.cycles(1);
  t.both(0, kt::ext_enable(1000.0, 1));  // after the coupling: a master at rest couples
  t.cycles(1);
  for (int i = 1; i <= 200; ++i) {
    const double p = 1.0 * i;  // 1000 mm/s
    kt::feed(t.probe.at(0), p, 1000.0, 0.0, 1);
    kt::feed(t.reference.at(0), p, 1000.0, 0.0, 1);
    t.cycles(1);
  }
  REQUIRE(t.probe.at(1).NcToPlc.SetVelo == 500.0);
  REQUIRE(t.same());
  const uint16_t n = t.probe.post(1, gr::gear_out());
  kt::feed(t.probe.at(0), 201.0, 1000.0, 0.0, 1);
  kt::feed(t.reference.at(0), 201.0, 1000.0, 0.0, 1);
  t.cycles(1);
  const plc::CommandAnswer a = t.probe.answer(1, n);
  CHECK(a.state == CommandState::kError);
  CHECK(a.error_code == kt::id(plc::ErrorCode::kDecouplingNotAllowed));
  CHECK(t.probe.at(1).NcToPlc.CoupleState == 3U);
  CHECK(t.same());
}

TEST_CASE("after online decoupling MC_Halt brakes with its own dynamics when both are larger",
          "[gear][decouple]") {
  gr::Rig rig(2);
  start_seed_figure(rig, 1.0);
  REQUIRE(rig.decouple(1).state == CommandState::kDone);
  const nc::KinematicState from{rig.at(1).NcToPlc.SetPos, rig.at(1).NcToPlc.SetVelo,
                                rig.at(1).NcToPlc.SetAcc};
  // D 10000, J 100000: both above the axis's 5000 / 50000, so adopted (seed 000 §2.2).
  const double expected_end = nc::plan_stop(from, 10000.0, 100000.0).final_state().p;
  const uint16_t halt = rig.post(1, kt::simple(plc::CommandType::kHalt, 10000.0, 100000.0));
  int cycles = 0;
  while (rig.answer(1, halt).state != CommandState::kDone && cycles < 5000) {
    rig.kernel.cycle();
    ++cycles;
  }
  REQUIRE(rig.answer(1, halt).state == CommandState::kDone);
  CHECK(rig.at(1).NcToPlc.SetPos == expected_end);
  CHECK(cycles == Approx(1000.0 * (2000.0 / 10000.0 + 0.1)).margin(2.0));
  CHECK(rig.at(0).NcToPlc.SetVelo == 2000.0);  // the former master runs on
  CHECK_FALSE(kt::bit(rig.at(1), plc::kStateMotionCommandsLocked));
}
