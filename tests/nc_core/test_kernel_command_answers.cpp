// The kernel's side of the command contract (plc_interface/command.hpp, team brief): accepted →
// kActive with CmdNo; the replaced command → kAborted; positioning → kDone after the target
// window; MoveVelocity → kReached; Halt/Stop → kDone at standstill; Stop locks until
// StopRelease; Reset and StopRelease answered at once without taking CmdNo.
#include <catch2/catch.hpp>

#include "kernel_harness.hpp"

using plc::AxisState;
using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

TEST_CASE("an accepted move is answered kActive in the same cycle and becomes CmdNo",
          "[kernel][answers]") {
  kt::Harness h;
  const uint16_t n = h.post(kt::move_absolute(100.0, 1000.0));
  CHECK(h.state_of(n) == CommandState::kPosted);
  h.cycles(1);
  CHECK(h.state_of(n) == CommandState::kActive);
  CHECK(h.x->NcToPlc.CmdNo == n);
  CHECK(h.x->NcToPlc.CmdState == static_cast<uint16_t>(CommandState::kActive));
  CHECK(kt::axis_state(*h.x) == AxisState::kDiscreteMotion);
  CHECK(kt::bit(*h.x, plc::kStateHasJob));
  CHECK(kt::bit(*h.x, plc::kStatePtpMode));
  CHECK(h.x->NcToPlc.TargetPos == 100.0);
  CHECK(h.x->NcToPlc.SetVelo > 0.0);
  CHECK(kt::bit(*h.x, plc::kStatePositiveDirection));
}

TEST_CASE("a move that replaces a running move aborts it; both in one cycle, in order",
          "[kernel][answers]") {
  kt::Harness h;
  const uint16_t first = h.post(kt::move_absolute(1000.0, 1000.0));
  h.cycles(200);
  const uint16_t second = h.post(kt::move_absolute(-200.0, 500.0));
  h.cycles(1);
  CHECK(h.state_of(first) == CommandState::kAborted);
  CHECK(h.state_of(second) == CommandState::kActive);
  CHECK(h.x->NcToPlc.CmdNo == second);

  // Two commands taken in the same cycle: the later one wins, the earlier is aborted.
  const uint16_t third = h.post(kt::move_absolute(300.0, 500.0));
  const uint16_t fourth = h.post(kt::move_relative(10.0, 500.0));
  h.cycles(1);
  CHECK(h.state_of(second) == CommandState::kAborted);
  CHECK(h.state_of(third) == CommandState::kAborted);
  CHECK(h.state_of(fourth) == CommandState::kActive);
  const int n = h.cycles_until([&] { return h.state_of(fourth) == CommandState::kDone; });
  REQUIRE(n > 0);
  CHECK(kt::axis_state(*h.x) == AxisState::kStandstill);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHasJob));
  CHECK(kt::bit(*h.x, plc::kStateInTargetPosition));
  CHECK(h.x->NcToPlc.CmdState == static_cast<uint16_t>(CommandState::kDone));
}

TEST_CASE("MoveRelative goes the distance from the current set position", "[kernel][answers]") {
  kt::Harness h;
  const uint16_t a = h.post(kt::move_absolute(250.0, 1000.0));
  h.cycles_until([&] { return h.state_of(a) == CommandState::kDone; });
  const uint16_t b = h.post(kt::move_relative(-75.5, 1000.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(b) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == 174.5);
  CHECK(h.x->NcToPlc.TargetPos == 174.5);
}

TEST_CASE("MoveVelocity is kReached at its velocity and stays so until another command",
          "[kernel][answers]") {
  kt::Harness h;
  const uint16_t n = h.post(kt::move_velocity(1000.0, 1));
  h.cycles(1);
  CHECK(h.state_of(n) == CommandState::kActive);
  CHECK(kt::axis_state(*h.x) == AxisState::kContinuousMotion);
  CHECK(kt::bit(*h.x, plc::kStateContinuousMotion));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateConstantVelocity));
  // 0 → 1000 mm/s with A = 5000, J = 50000: V/A + A/J = 0.2 + 0.1 s = 300 cycles.
  h.cycles(298);
  CHECK(h.state_of(n) == CommandState::kActive);
  h.cycles(1);
  CHECK(h.state_of(n) == CommandState::kReached);
  CHECK(h.x->NcToPlc.SetVelo == Approx(1000.0).epsilon(1e-12));
  CHECK(kt::bit(*h.x, plc::kStateConstantVelocity));
  h.cycles(500);
  CHECK(h.state_of(n) == CommandState::kReached);
  CHECK(h.x->NcToPlc.CmdState == static_cast<uint16_t>(CommandState::kReached));

  // Halt (0 = the running motion's deceleration and jerk): aborts it, done at standstill
  // after the same 0.3 s.
  const uint16_t halt = h.post(kt::simple(CommandType::kHalt));
  h.cycles(1);
  CHECK(h.state_of(n) == CommandState::kAborted);
  CHECK(h.state_of(halt) == CommandState::kActive);
  CHECK(kt::axis_state(*h.x) == AxisState::kDiscreteMotion);
  CHECK(kt::bit(*h.x, plc::kStateHasBeenStopped));
  h.cycles(298);
  CHECK(h.state_of(halt) == CommandState::kActive);
  h.cycles(1);
  CHECK(h.state_of(halt) == CommandState::kDone);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  CHECK(kt::axis_state(*h.x) == AxisState::kStandstill);
}

TEST_CASE("the MC_Direction encoding 3 (negative) runs backward like -1", "[kernel][answers]") {
  kt::Harness a;
  kt::Harness b;
  a.post(kt::move_velocity(500.0, 3));
  b.post(kt::move_velocity(500.0, -1));
  a.cycles(400);
  b.cycles(400);
  CHECK(a.x->NcToPlc.SetVelo == -500.0);
  CHECK(kt::bit(*a.x, plc::kStateNegativeDirection));
  CHECK(a.x->NcToPlc.SetPos == b.x->NcToPlc.SetPos);
}

TEST_CASE("Stop locks motion commands until StopRelease; Halt is locked out too",
          "[kernel][answers][stop]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_velocity(1000.0, 1));
  h.cycles(400);
  const uint16_t stop = h.post(kt::simple(CommandType::kStop));
  h.cycles(1);
  CHECK(h.state_of(move) == CommandState::kAborted);
  CHECK(h.state_of(stop) == CommandState::kActive);
  CHECK(kt::bit(*h.x, plc::kStateMotionCommandsLocked));
  CHECK(kt::axis_state(*h.x) == AxisState::kStopping);

  const uint16_t refused = h.post(kt::move_absolute(0.0, 100.0));
  const uint16_t refused_halt = h.post(kt::simple(CommandType::kHalt));
  h.cycles(1);
  CHECK(h.answer(refused).state == CommandState::kError);
  CHECK(h.answer(refused).error_code == kt::id(ErrorCode::kMotionCommandsLocked));
  CHECK(h.answer(refused_halt).error_code == kt::id(ErrorCode::kMotionCommandsLocked));
  CHECK(h.x->NcToPlc.CmdNo == stop);
  CHECK(h.x->NcToPlc.ErrorCode == 0);  // a refusal never puts the axis into error

  // 1000 mm/s down with the running motion's A- 5000, J 50000: 300 cycles in all.
  h.cycles(297);
  CHECK(h.state_of(stop) == CommandState::kActive);
  h.cycles(1);
  CHECK(h.state_of(stop) == CommandState::kDone);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  // Done, but still locked and Stopping until the release (PLCopen MC_Stop).
  h.cycles(10);
  CHECK(kt::axis_state(*h.x) == AxisState::kStopping);
  CHECK(kt::bit(*h.x, plc::kStateMotionCommandsLocked));

  const uint16_t release = h.post(kt::simple(CommandType::kStopRelease));
  h.cycles(1);
  CHECK(h.state_of(release) == CommandState::kDone);
  CHECK(h.x->NcToPlc.CmdNo == stop);  // the release is not a job
  CHECK_FALSE(kt::bit(*h.x, plc::kStateMotionCommandsLocked));
  CHECK(kt::axis_state(*h.x) == AxisState::kStandstill);

  const uint16_t again = h.post(kt::move_absolute(0.0, 100.0));
  h.cycles(1);
  CHECK(h.state_of(again) == CommandState::kActive);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHasBeenStopped));
}

TEST_CASE("Reset cancels the MC_Stop lock (Tc2_MC2 MC_Reset)", "[kernel][answers][stop]") {
  kt::Harness h;
  h.post(kt::move_velocity(1000.0, 1));
  h.cycles(400);
  const uint16_t stop = h.post(kt::simple(CommandType::kStop));
  REQUIRE(h.cycles_until([&] { return h.state_of(stop) == CommandState::kDone; }) > 0);
  REQUIRE(kt::bit(*h.x, plc::kStateMotionCommandsLocked));

  const uint16_t reset = h.post(kt::simple(CommandType::kReset));
  h.cycles(1);
  CHECK(h.state_of(reset) == CommandState::kDone);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateMotionCommandsLocked));
  CHECK(kt::axis_state(*h.x) == AxisState::kStandstill);

  const uint16_t again = h.post(kt::move_absolute(0.0, 100.0));
  h.cycles(1);
  CHECK(h.state_of(again) == CommandState::kActive);
}

TEST_CASE("a second Stop replaces the first, which is aborted", "[kernel][answers][stop]") {
  kt::Harness h;
  h.post(kt::move_velocity(1000.0, 1));
  h.cycles(400);
  const uint16_t s1 = h.post(kt::simple(CommandType::kStop, 2000.0));
  h.cycles(10);
  const uint16_t s2 = h.post(kt::simple(CommandType::kStop, 20000.0, 500000.0));
  h.cycles(1);
  CHECK(h.state_of(s1) == CommandState::kAborted);
  CHECK(h.state_of(s2) == CommandState::kActive);
  REQUIRE(h.cycles_until([&] { return h.state_of(s2) == CommandState::kDone; }) > 0);
}

TEST_CASE("Reset and StopRelease are answered kDone at once and leave CmdNo alone",
          "[kernel][answers]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(10.0, 100.0));
  h.cycles(5);
  const uint16_t reset = h.post(kt::simple(CommandType::kReset));
  const uint16_t release = h.post(kt::simple(CommandType::kStopRelease));
  h.cycles(1);
  CHECK(h.state_of(reset) == CommandState::kDone);
  CHECK(h.state_of(release) == CommandState::kDone);
  CHECK(h.x->NcToPlc.CmdNo == move);
  CHECK(h.state_of(move) == CommandState::kActive);  // a reset without error stops nothing
}

TEST_CASE("command types the kernel does not know are refused with kUnknownCommand",
          "[kernel][answers]") {
  kt::Harness h;
  for (CommandType t : {CommandType::kNone, static_cast<CommandType>(99)}) {
    const uint16_t n = h.post(kt::simple(t));
    h.cycles(1);
    CHECK(h.answer(n).state == CommandState::kError);
    CHECK(h.answer(n).error_code == kt::id(ErrorCode::kUnknownCommand));
  }
}

TEST_CASE("a start shorter than one encoder increment does not start: kDone with warning 0x4224",
          "[kernel][answers]") {
  kt::Harness h;  // encoder increment 1e-4 mm
  const uint16_t a = h.post(kt::move_absolute(50.0, 1000.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(a) == CommandState::kDone; }) > 0);
  const plc::NCTOPLC_AXIS_REF before = h.x->NcToPlc;

  const uint16_t tiny = h.post(kt::move_relative(0.5e-4, 1000.0));
  h.cycles(1);
  CHECK(h.state_of(tiny) == CommandState::kDone);
  CHECK(h.x->NcToPlc.Warning == 0x4224);
  CHECK(h.x->NcToPlc.CmdNo == a);  // no job was started
  CHECK(h.x->NcToPlc.SetPos == before.SetPos);
  CHECK(h.x->NcToPlc.TargetPos == before.TargetPos);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHasJob));

  const uint16_t zero = h.post(kt::move_absolute(50.0, 1000.0));
  h.cycles(1);
  CHECK(h.state_of(zero) == CommandState::kDone);
  CHECK(h.x->NcToPlc.CmdNo == a);

  // One increment or more starts.
  const uint16_t real = h.post(kt::move_relative(1e-4, 1000.0));
  h.cycles(1);
  CHECK(h.state_of(real) == CommandState::kActive);
  CHECK(h.x->NcToPlc.Warning == 0);
}
