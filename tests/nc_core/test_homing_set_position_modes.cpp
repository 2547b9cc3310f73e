// MC_Home's modes without motion (SPEC F, issue 13): MC_Direct sets the position (set and actual
// move together, the following error stays), MC_ForceCalibration sets Homed,
// MC_ResetCalibration clears it; all are answered Done in the cycle they are taken.
#include <catch2/catch.hpp>

#include "homing_rig.hpp"

using plc::CommandState;
using plc::ErrorCode;

TEST_CASE("MC_Direct to 250 at rest: set and actual 250, following error unchanged, Homed",
          "[homing][direct]") {
  kt::Harness h(kt::homing_axis());
  const uint16_t move = h.post(kt::move_absolute(37.5, 500.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  h.cycles(50);
  const plc::NCTOPLC_AXIS_REF before = h.x->NcToPlc;
  REQUIRE_FALSE(kt::bit(*h.x, plc::kStateHomed));

  const uint16_t direct = h.post(kt::home(plc::MC_Direct, 250.0));
  h.cycles(1);
  CHECK(h.state_of(direct) == CommandState::kDone);
  CHECK(h.x->NcToPlc.ActPos == Approx(250.0).margin(1e-9));
  CHECK(h.x->NcToPlc.SetPos == Approx(250.0).margin(1e-9));
  CHECK(h.x->NcToPlc.PosDiff == Approx(before.PosDiff).margin(1e-9));
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  CHECK(h.x->NcToPlc.TargetPos == Approx(250.0).margin(1e-9));
  CHECK(kt::bit(*h.x, plc::kStateHomed));
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK(h.x->NcToPlc.CmdNo == before.CmdNo);  // no job was taken
  h.cycles(100);                              // nothing moves afterwards
  CHECK(h.x->NcToPlc.ActPos == Approx(250.0).margin(1e-9));
  CHECK(h.x->NcToPlc.ErrorCode == 0);

  // A move after it goes from 250: 10 mm further is 260.
  const uint16_t after = h.post(kt::move_relative(10.0, 500.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(after) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == Approx(260.0).margin(1e-9));
}

TEST_CASE("MC_Direct with a standing following error keeps it", "[homing][direct]") {
  nc::AxisConfig c = kt::homing_axis();
  c.velocity_feed_forward = 0.9;  // the axis lags during the move and creeps in after it
  c.position_kv = 10.0;
  c.following_error_limit = 50.0;
  kt::Harness h(c);
  const uint16_t move = h.post(kt::move_absolute(100.0, 1000.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  const double lag = h.x->NcToPlc.PosDiff;
  REQUIRE(lag != 0.0);  // the drive still creeps in: a following error to keep

  const uint16_t direct = h.post(kt::home(plc::MC_Direct, 250.0));
  h.cycles(1);
  REQUIRE(h.state_of(direct) == CommandState::kDone);
  // One cycle of creeping changes the lag a little; the setting itself adds nothing.
  CHECK(h.x->NcToPlc.PosDiff == Approx(lag).epsilon(0.02));
  CHECK(h.x->NcToPlc.SetPos - h.x->NcToPlc.ActPos == Approx(h.x->NcToPlc.PosDiff).margin(1e-9));
  // The actual position was set to 250 and crept one cycle on; the set position kept its lead.
  CHECK(h.x->NcToPlc.SetPos == Approx(250.0 + lag).margin(1e-9));
  CHECK(h.x->NcToPlc.ActPos == Approx(250.0).margin(0.02 * lag));
}

TEST_CASE("MC_Home with the default Position takes homing_reference_position", "[homing][direct]") {
  nc::AxisConfig c = kt::homing_axis();
  c.homing_reference_position = -12.5;
  kt::Harness h(c);
  const uint16_t direct = h.post(kt::home(plc::MC_Direct));
  h.cycles(1);
  CHECK(h.state_of(direct) == CommandState::kDone);
  CHECK(h.x->NcToPlc.ActPos == Approx(-12.5).margin(1e-9));
  CHECK(h.x->NcToPlc.SetPos == Approx(-12.5).margin(1e-9));
}

TEST_CASE("MC_ForceCalibration sets Homed, MC_ResetCalibration clears it, nothing moves",
          "[homing][calibration]") {
  kt::Harness h(kt::homing_axis());
  h.cycles(5);
  const plc::NCTOPLC_AXIS_REF before = h.x->NcToPlc;
  const uint16_t force = h.post(kt::home(plc::MC_ForceCalibration));
  h.cycles(1);
  CHECK(h.state_of(force) == CommandState::kDone);
  CHECK(kt::bit(*h.x, plc::kStateHomed));
  CHECK(h.x->NcToPlc.SetPos == before.SetPos);
  CHECK(h.x->NcToPlc.ActPos == before.ActPos);

  const uint16_t reset = h.post(kt::home(plc::MC_ResetCalibration));
  h.cycles(1);
  CHECK(h.state_of(reset) == CommandState::kDone);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHomed));
  CHECK(h.x->NcToPlc.SetPos == before.SetPos);
}

TEST_CASE("MC_ResetCalibration during a move: Homed clear, the move goes on",
          "[homing][calibration]") {
  kt::Harness h;  // homed at start
  const uint16_t move = h.post(kt::move_absolute(500.0, 1000.0));
  h.cycles(20);
  const uint16_t reset = h.post(kt::home(plc::MC_ResetCalibration));
  h.cycles(1);
  CHECK(h.state_of(reset) == CommandState::kDone);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHomed));
  CHECK(h.state_of(move) == CommandState::kActive);
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == 500.0);
}
