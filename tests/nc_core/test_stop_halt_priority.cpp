// Stop priority (SPEC B4, seed 000 §2.2): outside the brake phase a Stop (or Halt) takes the axis
// at once; while a stop is active the new-position functions are refused (0x4242); the override
// does not act on a stop; in the brake phase a Stop is accepted and the braking that runs goes
// on (no emergency stop inside the brake phase).
#include <catch2/catch.hpp>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

TEST_CASE(
    "a Stop takes a positioning at once; new positions after it are refused with 0x4242 until "
    "the lock is released",
    "[stop][priority]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(5000.0, 2000.0));
  h.cycles(1000);  // cruising at 2000 mm/s
  const uint16_t stop = h.post(kt::simple(CommandType::kStop));
  const uint16_t same_cycle = h.post(kt::new_pos(6000.0));
  h.cycles(1);
  CHECK(h.state_of(move) == CommandState::kAborted);
  CHECK(h.state_of(stop) == CommandState::kActive);
  CHECK(h.answer(same_cycle).state == CommandState::kError);
  CHECK(h.answer(same_cycle).error_code == kt::id(ErrorCode::kStopAlreadyActive));
  CHECK(h.x->NcToPlc.SetAcc < 0.0);

  h.cycles(100);  // stopping
  const uint16_t during = h.post(kt::new_pos_and_velo(6000.0, 1000.0, 5500.0));
  h.cycles(1);
  CHECK(h.answer(during).error_code == kt::id(ErrorCode::kStopAlreadyActive));
  REQUIRE(h.cycles_until([&] { return h.state_of(stop) == CommandState::kDone; }) > 0);
  const uint16_t locked = h.post(kt::new_pos(6000.0));
  h.cycles(1);
  CHECK(h.answer(locked).error_code == kt::id(ErrorCode::kStopAlreadyActive));

  h.post(kt::simple(CommandType::kStopRelease));
  const uint16_t no_job = h.post(kt::new_pos(6000.0));
  h.cycles(1);
  CHECK(h.answer(no_job).error_code == kt::id(ErrorCode::kFunctionNotAllowed));
  CHECK(h.x->NcToPlc.ErrorCode == 0);
}

TEST_CASE("while a Halt runs new positions are refused with 0x4242", "[halt][priority]") {
  kt::Harness h;
  h.post(kt::move_absolute(5000.0, 2000.0));
  h.cycles(1000);
  const uint16_t halt = h.post(kt::simple(CommandType::kHalt));
  h.cycles(10);
  const uint16_t a = h.post(kt::new_pos(6000.0));
  const uint16_t b = h.post(kt::new_pos_and_velo(6000.0, 1000.0, 5500.0));
  h.cycles(1);
  CHECK(h.answer(a).error_code == kt::id(ErrorCode::kStopAlreadyActive));
  CHECK(h.answer(b).error_code == kt::id(ErrorCode::kStopAlreadyActive));
  CHECK(h.state_of(halt) == CommandState::kActive);
}

TEST_CASE("a new end position posted before a Stop in the same cycle is overruled by the stop",
          "[stop][priority]") {
  kt::TwinKernels t;
  t.both(kt::move_absolute(5000.0, 2000.0));
  t.cycles(1000);
  const uint16_t first = t.probe.post(kt::new_pos(8000.0));
  t.both(kt::simple(CommandType::kStop));
  t.cycles(1);
  CHECK(t.probe.state_of(first) == CommandState::kDone);  // accepted, then the stop took over
  t.cycles(600);
  CHECK(t.probe.x->NcToPlc.SetVelo == 0.0);
  CHECK(t.probe.x->NcToPlc.SetPos == Approx(t.reference.x->NcToPlc.SetPos).margin(1e-9));
}

TEST_CASE(
    "a Stop in the brake phase is accepted and the braking that runs goes on, even with larger "
    "values",
    "[stop][brake]") {
  // 0 → 3000 mm at 2000 mm/s: the final deceleration runs from 1.5 s to 2.0 s.
  kt::TwinKernels t;
  const uint16_t move = t.probe.post(kt::move_absolute(3000.0, 2000.0));
  t.reference.post(kt::move_absolute(3000.0, 2000.0));
  t.cycles(1600);
  REQUIRE(t.probe.x->NcToPlc.SetAcc < 0.0);
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);  // A- 5000, J 50000: nothing sharper
  const uint16_t stop = t.probe.post(kt::simple(CommandType::kStop, 20000.0, 500000.0));
  for (int i = 0; i < 400; ++i) {
    if (i == 50) t.probe.post(kt::simple(CommandType::kStop, 40000.0, 900000.0));
    t.cycles(1);
    c.check(*t.probe.x);
    REQUIRE(t.probe.x->NcToPlc.SetPos == Approx(t.reference.x->NcToPlc.SetPos).margin(1e-9));
    REQUIRE(t.probe.x->NcToPlc.SetVelo == Approx(t.reference.x->NcToPlc.SetVelo).margin(1e-9));
  }
  CHECK(t.probe.state_of(move) == CommandState::kAborted);
  CHECK(t.probe.state_of(stop) == CommandState::kAborted);  // by the second stop
  CHECK(t.probe.x->NcToPlc.SetVelo == 0.0);
  CHECK(t.probe.x->NcToPlc.SetPos == Approx(3000.0).margin(1e-9));
  CHECK(kt::bit(*t.probe.x, plc::kStateMotionCommandsLocked));
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE("the override does not act on a running Stop or Halt", "[stop][halt][override]") {
  for (CommandType type : {CommandType::kStop, CommandType::kHalt}) {
    kt::TwinKernels t;
    t.both(kt::move_velocity(2000.0, 1));
    t.cycles(600);
    t.both(kt::simple(type));
    t.cycles(1);
    kt::set_override(*t.probe.x, 30.0);
    for (int i = 0; i < 100; ++i) {
      t.cycles(1);
      REQUIRE(t.same());
    }
    kt::set_override(*t.probe.x, 0.0);
    for (int i = 0; i < 500; ++i) {
      t.cycles(1);
      REQUIRE(t.same());
    }
  }
}
