// External setpoint generation is switched off at once (no further cycle taken) by an axis error,
// an axis reset and the loss of the controller enable (seed 000 §2.6 "To be observed"), and by a
// stop (our choice: MC_Stop / MC_Halt have priority and brake from the set state the external
// generator reached). A packet with NaN or inf is never taken: the axis goes into error
// (0x4F02) and brakes on its emergency ramp from where the generator was heading.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

namespace {

// Absolute external generation moving at 500 mm/s: position 0.5 mm per 1 ms cycle, `n` cycles.
void run_ramp(kt::Harness& h, int n) {
  h.post(kt::ext_enable(0.0, 1));
  for (int i = 1; i <= n; ++i) {
    kt::feed(*h.x, 0.5 * i, 500.0, 0.0, 1);
    h.cycles(1);
  }
  REQUIRE(h.x->NcToPlc.SetPos == 0.5 * n);
}

// Runs until standstill; checks that the set velocity only falls, within the emergency ramp.
void check_brakes_smoothly(kt::Harness& h, double from_velocity) {
  double previous = from_velocity;
  for (int i = 0; i < 2000 && h.x->NcToPlc.SetVelo != 0.0; ++i) {
    h.cycles(1);
    REQUIRE(h.x->NcToPlc.SetVelo <= previous);
    REQUIRE(previous - h.x->NcToPlc.SetVelo <= 10000.0 * 0.001 + 1e-9);
    previous = h.x->NcToPlc.SetVelo;
  }
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
}

}  // namespace

TEST_CASE("a packet with NaN is not taken: axis error 0x4F02, generation off, emergency ramp",
          "[ext_setpoint][auto_disable]") {
  for (int which = 0; which < 3; ++which) {
    INFO("NaN in field " << which);
    kt::Harness h;
    run_ramp(h, 100);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    kt::feed(*h.x, which == 0 ? nan : 50.5, which == 1 ? nan : 500.0, which == 2 ? nan : 0.0, 1);
    h.cycles(1);
    CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kParameterNotFinite));
    CHECK_FALSE(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
    // Not taken: the set state went on at 500 mm/s for this cycle.
    CHECK(h.x->NcToPlc.SetPos == 50.5);
    CHECK(h.x->NcToPlc.SetVelo == 500.0);
    check_brakes_smoothly(h, 500.0);
    CHECK(std::isfinite(h.x->NcToPlc.SetPos));
    const double rest = h.x->NcToPlc.SetPos;
    kt::feed(*h.x, 80.0, 500.0, 0.0, 1);
    h.cycles(10);
    CHECK(h.x->NcToPlc.SetPos == rest);  // nothing is taken any more
  }
}

TEST_CASE(
    "a finite packet out of range is not taken: axis error 0x4359, generation off, emergency "
    "ramp",
    "[ext_setpoint][auto_disable][range]") {
  // Fuzz finding K2: ExtSetPos and ExtSetVelo of 2.3e302 were taken and the controller
  // overflowed. Out of range: carried velocity above the max velocity (2200 mm/s), |p| or |a|
  // above 1e12.
  struct Packet {
    double p, v, a;
  };
  for (const Packet& bad :
       {Packet{2.3e302, 2.3e302, 0.0}, Packet{50.5, 2200.5, 0.0}, Packet{50.5, -2300.0, 0.0},
        Packet{1.01e12, 500.0, 0.0}, Packet{50.5, 500.0, 1.01e12}}) {
    INFO("packet " << bad.p << " " << bad.v << " " << bad.a);
    kt::Harness h;
    run_ramp(h, 100);
    kt::feed(*h.x, bad.p, bad.v, bad.a, 1);
    h.cycles(1);
    CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kSetVelocityNotAllowed));
    CHECK_FALSE(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
    // Not taken: the set state went on at 500 mm/s for this cycle.
    CHECK(h.x->NcToPlc.SetPos == 50.5);
    CHECK(h.x->NcToPlc.SetVelo == 500.0);
    check_brakes_smoothly(h, 500.0);
    CHECK(std::isfinite(h.x->NcToPlc.ActPos));
  }
  // At the max velocity itself the packet is taken.
  kt::Harness h;
  run_ramp(h, 100);
  kt::feed(*h.x, 52.7, 2200.0, 0.0, 1);
  h.cycles(1);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK(h.x->NcToPlc.SetVelo == 2200.0);
}

TEST_CASE("an axis error switches the generation off", "[ext_setpoint][auto_disable]") {
  kt::Harness h;
  run_ramp(h, 100);
  kt::set_enables(*h.x, true, false, true);  // feed enable plus removed while moving plus
  kt::feed(*h.x, 50.5, 500.0, 0.0, 1);
  h.cycles(1);
  CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kFeedEnablePlusMissing));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
  check_brakes_smoothly(h, 500.0);
  // After the reset the generation stays off until enabled again.
  kt::set_enables(*h.x, true);
  h.post(kt::simple(CommandType::kReset));
  h.cycles(1);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
  const uint16_t again = h.post(kt::ext_enable(0.0, 1));
  h.cycles(1);
  CHECK(h.state_of(again) == CommandState::kDone);
}

TEST_CASE("a reset switches the generation off at once: the reset's cycle takes nothing",
          "[ext_setpoint][auto_disable]") {
  for (int type : {1, 2}) {
    INFO("position type " << type);
    kt::Harness h;
    h.post(kt::ext_enable(0.0, type));
    for (int i = 1; i <= 10; ++i) {
      kt::feed(*h.x, 0.5 * i, 0.0, 0.0, 1);
      h.cycles(1);
    }
    CHECK(h.x->NcToPlc.SetPos == 5.0);
    const uint16_t reset = h.post(kt::simple(CommandType::kReset));
    kt::feed(*h.x, 5.5, 0.0, 0.0, 1);
    h.cycles(1);
    CHECK(h.state_of(reset) == CommandState::kDone);
    CHECK_FALSE(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
    CHECK(h.x->NcToPlc.SetPos == 5.0);
    h.cycles(5);
    CHECK(h.x->NcToPlc.SetPos == 5.0);
  }
}

TEST_CASE("losing the controller enable switches the generation off",
          "[ext_setpoint][auto_disable]") {
  kt::Harness h;
  run_ramp(h, 20);
  kt::set_enables(*h.x, false);
  h.cycles(1);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
  kt::set_enables(*h.x, true);
  kt::feed(*h.x, 50.0, 0.0, 0.0, 1);
  h.cycles(5);
  CHECK(h.x->NcToPlc.SetPos == Approx(10.0).margin(1.0));  // where the drive coasted, not 50
  CHECK_FALSE(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
}

TEST_CASE("MC_Stop and MC_Halt end the generation and brake from its set state",
          "[ext_setpoint][auto_disable]") {
  for (CommandType type : {CommandType::kStop, CommandType::kHalt}) {
    INFO((type == CommandType::kStop ? "MC_Stop" : "MC_Halt"));
    kt::Harness h;
    run_ramp(h, 100);
    const uint16_t stop = h.post(kt::simple(type));
    kt::feed(*h.x, 50.5, 500.0, 0.0, 1);
    h.cycles(1);
    CHECK(h.state_of(stop) == CommandState::kActive);
    CHECK_FALSE(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
    REQUIRE(h.cycles_until([&] { return h.state_of(stop) == CommandState::kDone; }) > 0);
    // From 50 mm at 500 mm/s with A- 5000, J 50000: v = A²/J, so the braking is one jerk
    // triangle of 2·sqrt(v/J) = 0.2 s covering v · 0.2 s / 2 = 50 mm.
    CHECK(h.x->NcToPlc.SetPos == Approx(100.0).margin(1e-9));
    CHECK(h.x->NcToPlc.ErrorCode == 0);
  }
}
