// Software limit switches (SPEC A4, seed 000 §2.1 notes 4 and 5): a target outside is refused
// (0x4222), a start from outside back into the range is allowed, and a motion whose set position
// runs out through a limit is an axis error (0x4462 / 0x4463) that stops on the emergency ramp.
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

using plc::AxisState;
using plc::CommandState;
using plc::ErrorCode;

namespace {

nc::AxisConfig limited_axis(double min, double max) {
  nc::AxisConfig c = kt::seed_axis();
  c.sw_limit_min_enabled = true;
  c.sw_limit_max_enabled = true;
  c.sw_limit_min = min;
  c.sw_limit_max = max;
  return c;
}

}  // namespace

TEST_CASE("a target outside the limits is refused with 0x4222, on the limit is allowed",
          "[monitor][software_limits]") {
  kt::Harness h(limited_axis(-100.0, 100.0));
  const uint16_t out = h.post(kt::move_absolute(100.001, 500.0));
  const uint16_t under = h.post(kt::move_relative(-100.5, 500.0));
  h.cycles(1);
  CHECK(h.answer(out).error_code == kt::id(ErrorCode::kTargetPositionNotAllowed));
  CHECK(h.answer(under).error_code == kt::id(ErrorCode::kTargetPositionNotAllowed));
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  const uint16_t edge = h.post(kt::move_absolute(100.0, 500.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(edge) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == 100.0);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateSoftLimitMaxExceeded));
}

TEST_CASE("a start from outside the limits back into the range is allowed (seed note 5)",
          "[monitor][software_limits]") {
  // The axis stands at 0, below the minimum 10.
  kt::Harness h(limited_axis(10.0, 1000.0));
  CHECK(kt::bit(*h.x, plc::kStateSoftLimitMinExceeded));
  const uint16_t further_out = h.post(kt::move_absolute(5.0, 100.0));
  h.cycles(1);
  CHECK(h.answer(further_out).error_code == kt::id(ErrorCode::kTargetPositionNotAllowed));

  const uint16_t back_in = h.post(kt::move_absolute(100.0, 100.0));
  h.cycles(1);
  CHECK(h.state_of(back_in) == CommandState::kActive);
  const int crossed = h.cycles_until([&] { return h.x->NcToPlc.ActPos >= 10.0; });
  REQUIRE(crossed > 0);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateSoftLimitMinExceeded));
  REQUIRE(h.cycles_until([&] { return h.state_of(back_in) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK(h.x->NcToPlc.SetPos == 100.0);
}

TEST_CASE(
    "continuous motion through the maximum limit raises 0x4463 in the cycle the set "
    "position passes it and stops on the emergency ramp",
    "[monitor][software_limits]") {
  kt::Harness h(limited_axis(-500.0, 500.0));
  const uint16_t job = h.post(kt::move_velocity(1000.0, 1));
  int passed = -1;
  for (int cycle = 1; cycle <= 2000 && passed < 0; ++cycle) {
    const double before = h.x->NcToPlc.SetPos;
    h.cycles(1);
    if (h.x->NcToPlc.SetPos > 500.0) {
      passed = cycle;
      CHECK(before <= 500.0);
    } else {
      REQUIRE(h.x->NcToPlc.ErrorCode == 0);
    }
  }
  REQUIRE(passed > 0);
  CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kSoftLimitMaxDuringMotion));
  CHECK(h.answer(job).error_code == kt::id(ErrorCode::kSoftLimitMaxDuringMotion));
  CHECK(kt::axis_state(*h.x) == AxisState::kErrorStop);
  // From 1000 mm/s at a = 0 with D = 10000, J = 100000: 0.2 s and v²/2D + vD/2J = 100 mm.
  REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetVelo == 0.0; }) == 200);
  CHECK(h.x->NcToPlc.SetPos == Approx(500.0 + 100.0).margin(1.0));
  CHECK(kt::bit(*h.x, plc::kStateSoftLimitMaxExceeded));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateSoftLimitMinExceeded));
}

TEST_CASE("continuous motion through the minimum limit raises 0x4462",
          "[monitor][software_limits]") {
  kt::Harness h(limited_axis(-50.0, 500.0));
  h.post(kt::move_velocity(200.0, 3));
  const int n = h.cycles_until([&] { return h.x->NcToPlc.ErrorCode != 0; });
  REQUIRE(n > 0);
  CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kSoftLimitMinDuringMotion));
  CHECK(h.x->NcToPlc.SetPos < -50.0);
  REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetVelo == 0.0; }) > 0);
  CHECK(kt::bit(*h.x, plc::kStateSoftLimitMinExceeded));
}

TEST_CASE("disabled software limits neither refuse nor raise", "[monitor][software_limits]") {
  nc::AxisConfig c = limited_axis(-50.0, 50.0);
  c.sw_limit_min_enabled = false;
  c.sw_limit_max_enabled = false;
  kt::Harness h(c);
  const uint16_t job = h.post(kt::move_absolute(200.0, 500.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(job) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateSoftLimitMaxExceeded));
}

TEST_CASE(
    "a positioning whose reversal runs out through the maximum limit raises 0x4463 in the cycle "
    "the set position passes it",
    "[monitor][software_limits]") {
  // The steady lane (nc_core/src/axis/steady_lane.hpp) takes a segment only when every position
  // it can reach lies within the limits: here the brake segment before the reversal passes 500.
  kt::Harness h(limited_axis(-500.0, 500.0));
  h.post(kt::move_velocity(1000.0, 1));
  REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetPos >= 420.0; }) > 0);
  REQUIRE(h.x->NcToPlc.ErrorCode == 0);
  const uint16_t back = h.post(kt::move_absolute(0.0, 1000.0));
  h.cycles(1);
  REQUIRE(h.state_of(back) == CommandState::kActive);
  int passed = -1;
  for (int cycle = 1; cycle <= 1000 && passed < 0; ++cycle) {
    h.cycles(1);
    if (h.x->NcToPlc.SetPos > 500.0) {
      passed = cycle;
    } else {
      REQUIRE(h.x->NcToPlc.ErrorCode == 0);
    }
  }
  REQUIRE(passed > 0);
  CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kSoftLimitMaxDuringMotion));
  CHECK(h.answer(back).error_code == kt::id(ErrorCode::kSoftLimitMaxDuringMotion));
}
