// Controller and feed enables (PlcToNc.ControlDWord, written by MC_Power): Operational, Disabled
// state with the set position following the actual one, and the axis errors when an enable is
// taken away during a job (0x4260 controller, 0x4358 / 0x4357 feed plus / minus).
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

using plc::AxisState;
using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

TEST_CASE(
    "a new axis is Disabled until the controller enable comes, then Standstill and "
    "Operational",
    "[kernel][enables]") {
  kt::Harness h(kt::seed_axis(), 0.001, false);
  CHECK(kt::axis_state(*h.x) == AxisState::kDisabled);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateOperational));
  CHECK(kt::bit(*h.x, plc::kStateHomed));  // homed_at_start (the default): homed from the start
  CHECK(kt::bit(*h.x, plc::kStateNotMoving));
  kt::set_enables(*h.x, true);
  h.cycles(1);
  CHECK(kt::axis_state(*h.x) == AxisState::kStandstill);
  CHECK(kt::bit(*h.x, plc::kStateOperational));
}

TEST_CASE(
    "controller enable removed during a move: error 0x4260, the job fails, the set "
    "position follows the actual one",
    "[kernel][enables]") {
  nc::AxisConfig c = kt::seed_axis();
  c.drive_model = nc::DriveModel::kFirstOrderLag;  // the drive runs down on its own
  c.drive_time_constant = 0.05;
  c.following_error_limit = 100.0;  // v·tau = 50 mm behind while moving
  kt::Harness h(c);
  const uint16_t job = h.post(kt::move_velocity(1000.0, 1));
  h.cycles(500);
  kt::set_enables(*h.x, false);
  h.cycles(1);
  CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kControllerEnableLost));
  CHECK(h.x->NcToPlc.ErrorCode == 0x4260U);
  CHECK(h.answer(job).state == CommandState::kError);
  CHECK(h.answer(job).error_code == kt::id(ErrorCode::kControllerEnableLost));
  CHECK(kt::axis_state(*h.x) == AxisState::kErrorStop);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHasJob));
  for (int i = 0; i < 300; ++i) {
    h.cycles(1);
    REQUIRE(h.x->NcToPlc.SetPos == h.x->NcToPlc.ActPos);
    REQUIRE(h.x->NcToPlc.SetVelo == 0.0);
  }
  // 300 ms = 6 time constants: the drive has run down below e^-5 of its speed.
  CHECK(std::abs(h.x->NcToPlc.ActVelo) < 1000.0 * std::exp(-5.0));

  const uint16_t reset = h.post(kt::simple(CommandType::kReset));
  h.cycles(1);
  CHECK(h.state_of(reset) == CommandState::kDone);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK(kt::axis_state(*h.x) == AxisState::kDisabled);
  kt::set_enables(*h.x, true);
  h.cycles(1);
  CHECK(kt::axis_state(*h.x) == AxisState::kStandstill);
}

TEST_CASE("controller enable removed at standstill is no error", "[kernel][enables]") {
  kt::Harness h;
  const uint16_t job = h.post(kt::move_absolute(20.0, 200.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(job) == CommandState::kDone; }) > 0);
  kt::set_enables(*h.x, false);
  h.cycles(10);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK(kt::axis_state(*h.x) == AxisState::kDisabled);
  CHECK(h.x->NcToPlc.SetPos == h.x->NcToPlc.ActPos);
}

TEST_CASE(
    "feed enable removed in the direction of travel: error 0x4358 / 0x4357 and the "
    "emergency ramp",
    "[kernel][enables]") {
  SECTION("plus") {
    kt::Harness h;
    const uint16_t job = h.post(kt::move_velocity(1000.0, 1));
    h.cycles(400);
    kt::set_enables(*h.x, true, false, true);
    h.cycles(1);
    CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kFeedEnablePlusMissing));
    CHECK(h.answer(job).error_code == kt::id(ErrorCode::kFeedEnablePlusMissing));
    // 1000 mm/s at a = 0, D = 10000, J = 100000: 0.2 s.
    CHECK(h.cycles_until([&] { return h.x->NcToPlc.SetVelo == 0.0; }) == 199);
    CHECK(kt::bit(*h.x, plc::kStateHasBeenStopped));
  }
  SECTION("minus") {
    kt::Harness h;
    h.post(kt::move_velocity(1000.0, -1));
    h.cycles(400);
    kt::set_enables(*h.x, true, true, false);
    h.cycles(1);
    CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kFeedEnableMinusMissing));
  }
  SECTION("the other direction's feed enable does not matter") {
    kt::Harness h;
    h.post(kt::move_velocity(1000.0, 1));
    h.cycles(400);
    kt::set_enables(*h.x, true, true, false);
    h.cycles(100);
    CHECK(h.x->NcToPlc.ErrorCode == 0);
  }
}
