// Continuous motion (SPEC B1; MC_MoveVelocity): InVelocity (kReached) once the velocity is
// reached, ended by Halt or Stop; MC_Current_Direction (4) keeps the direction of travel and is
// refused at standstill; the override acts on velocity moves too (SPEC B3).
#include <catch2/catch.hpp>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

TEST_CASE("MC_Current_Direction continues in the direction the axis moves", "[move_velocity]") {
  for (int sign : {1, -1}) {
    INFO("moving " << (sign > 0 ? "positive" : "negative"));
    kt::Harness h;
    kt::LimitChecker c = kt::LimitChecker::seed(1500.0);
    const uint16_t first = h.post(kt::move_velocity(1000.0, sign));
    kt::checked_cycles(h, c, 400);
    const uint16_t second = h.post(kt::move_velocity(1500.0, 4));
    kt::checked_cycles(h, c, 1);
    CHECK(h.state_of(first) == CommandState::kAborted);
    CHECK(h.state_of(second) == CommandState::kActive);
    // 1000 → 1500 mm/s: 500 = A²/J, 0.2 s.
    kt::checked_cycles(h, c, 199);
    CHECK(h.state_of(second) == CommandState::kReached);
    CHECK(h.x->NcToPlc.SetVelo == Approx(sign * 1500.0).margin(1e-9));
    CHECK(h.x->NcToPlc.TargetVelo == sign * 1500.0);
    CHECK(kt::axis_state(*h.x) == plc::AxisState::kContinuousMotion);
    INFO(c.first);
    CHECK(c.ok());
  }
}

TEST_CASE("MC_Current_Direction at standstill is refused with kDirectionInvalid, nothing changes",
          "[move_velocity][refusals]") {
  kt::TwinKernels t;
  t.cycles(5);
  const uint16_t n = t.probe.post(kt::move_velocity(1000.0, 4));
  t.cycles(1);
  CHECK(t.probe.answer(n).state == CommandState::kError);
  CHECK(t.probe.answer(n).error_code == kt::id(ErrorCode::kDirectionInvalid));
  for (int i = 0; i < 50; ++i) {
    REQUIRE(t.same());
    t.cycles(1);
  }
}

TEST_CASE("InVelocity when the velocity is reached; Halt and Stop end the motion",
          "[move_velocity]") {
  for (CommandType end : {CommandType::kHalt, CommandType::kStop}) {
    kt::Harness h;
    kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
    const uint16_t move = h.post(kt::move_velocity(2000.0, 1));
    // 0 → 2000 mm/s: 0.5 s.
    kt::checked_cycles(h, c, 499);
    CHECK(h.state_of(move) == CommandState::kActive);
    kt::checked_cycles(h, c, 1);
    CHECK(h.state_of(move) == CommandState::kReached);
    CHECK(kt::bit(*h.x, plc::kStateConstantVelocity));
    kt::checked_cycles(h, c, 1000);
    CHECK(h.state_of(move) == CommandState::kReached);  // it goes on
    const uint16_t stop = h.post(kt::simple(end));
    kt::checked_cycles(h, c, 1);
    CHECK(h.state_of(move) == CommandState::kAborted);
    kt::checked_cycles(h, c, 498);
    CHECK(h.state_of(stop) == CommandState::kActive);
    kt::checked_cycles(h, c, 1);
    CHECK(h.state_of(stop) == CommandState::kDone);
    CHECK(h.x->NcToPlc.SetVelo == 0.0);
    INFO(c.first);
    CHECK(c.ok());
  }
}

TEST_CASE(
    "the override scales a velocity move: 50 % gives 1000 mm/s, 0 % rests with the job active, "
    "100 % gives 2000 mm/s",
    "[move_velocity][override]") {
  kt::Harness h;
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
  kt::set_override(*h.x, 50.0);
  const uint16_t move = h.post(kt::move_velocity(2000.0, 1));
  kt::checked_cycles(h, c, 400);  // 0 → 1000 mm/s: 0.3 s
  CHECK(h.x->NcToPlc.SetVelo == Approx(1000.0).margin(1e-9));
  CHECK(h.x->NcToPlc.TargetVelo == 1000.0);
  CHECK(h.state_of(move) == CommandState::kReached);

  kt::set_override(*h.x, 0.0);
  kt::checked_cycles(h, c, 400);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateConstantVelocity));
  CHECK(kt::bit(*h.x, plc::kStateHasJob));
  CHECK(h.x->NcToPlc.CmdNo == move);
  CHECK(kt::axis_state(*h.x) == plc::AxisState::kContinuousMotion);

  kt::set_override(*h.x, 100.0);
  kt::checked_cycles(h, c, 600);  // 0 → 2000 mm/s: 0.5 s
  CHECK(h.x->NcToPlc.SetVelo == Approx(2000.0).margin(1e-9));
  CHECK(kt::bit(*h.x, plc::kStateConstantVelocity));
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE("a velocity move started at override 0 is not InVelocity until it moves",
          "[move_velocity][override]") {
  kt::Harness h;
  kt::set_override(*h.x, 0.0);
  const uint16_t move = h.post(kt::move_velocity(1000.0, 1));
  h.cycles(100);
  CHECK(h.state_of(move) == CommandState::kActive);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  kt::set_override(*h.x, 100.0);
  h.cycles(300);  // 0 → 1000 mm/s: 0.3 s
  CHECK(h.state_of(move) == CommandState::kReached);
  CHECK(h.x->NcToPlc.SetVelo == Approx(1000.0).margin(1e-9));
}
