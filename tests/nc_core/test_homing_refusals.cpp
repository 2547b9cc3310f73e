// MC_Home's refusals (SPEC F, issue 13, NC_ERROR_CODES.md): each is answered kError with its
// code, and the NC→PLC image stays bit-identical to a twin kernel that never got the command.
#include <catch2/catch.hpp>

#include "homing_rig.hpp"
#include "refusal_check.hpp"

using plc::CommandState;
using plc::ErrorCode;

TEST_CASE("modes ncsdk does not provide, and mode values outside MC_HomingMode, are refused",
          "[homing][refusals]") {
  kt::TwinKernels t(kt::homing_axis());
  const kt::Bad cases[] = {
      {"MC_AbsSwitch", kt::home(plc::MC_AbsSwitch, 0.0), ErrorCode::kHomingModeNotSupported},
      {"MC_LimitSwitch", kt::home(plc::MC_LimitSwitch, 0.0), ErrorCode::kHomingModeNotSupported},
      {"MC_RefPulse", kt::home(plc::MC_RefPulse, 0.0), ErrorCode::kHomingModeNotSupported},
      {"mode 7", kt::home(7, 0.0), ErrorCode::kBlockInputOutOfRange},
      {"mode -1", kt::home(-1, 0.0), ErrorCode::kBlockInputOutOfRange},
  };
  for (const kt::Bad& bad : cases)
    kt::expect_refused_without_effect(t, bad, 5);
  CHECK(t.probe.x->NcToPlc.ErrorCode == 0);
}

TEST_CASE("bad positions and buffer modes are refused", "[homing][refusals]") {
  kt::TwinKernels t(kt::homing_axis());
  plc::Command buffered = kt::home(plc::MC_DefaultHoming, 0.0);
  buffered.buffer_mode = plc::MC_Buffered;
  const kt::Bad cases[] = {
      {"Direct NaN", kt::home(plc::MC_Direct, kt::kNaN), ErrorCode::kPositionNotFinite},
      {"Direct inf", kt::home(plc::MC_Direct, kt::kInf), ErrorCode::kPositionNotFinite},
      {"Default NaN", kt::home(plc::MC_DefaultHoming, kt::kNaN), ErrorCode::kPositionNotFinite},
      {"Direct 1e300", kt::home(plc::MC_Direct, 1e300), ErrorCode::kTargetPositionNotAllowed},
      {"buffered", buffered, ErrorCode::kBufferModeNotSupported},
  };
  for (const kt::Bad& bad : cases)
    kt::expect_refused_without_effect(t, bad, 5);
}

TEST_CASE("every mode is refused without controller enable", "[homing][refusals]") {
  kt::TwinKernels t(kt::homing_axis());
  t.enables(false, true, true);
  t.cycles(2);
  for (int32_t mode : {plc::MC_DefaultHoming, plc::MC_Direct, plc::MC_ForceCalibration,
                       plc::MC_ResetCalibration}) {
    kt::expect_refused_without_effect(
        t,
        {"mode " + std::to_string(mode), kt::home(mode, 5.0), ErrorCode::kNoControllerOrFeedEnable},
        5);
  }
}

TEST_CASE("default homing is refused without the feed enable of a search direction",
          "[homing][refusals]") {
  kt::TwinKernels t(kt::homing_axis());
  t.enables(true, true, false);  // the sync search runs negative by default
  t.cycles(2);
  kt::expect_refused_without_effect(t, {"no feed minus", kt::home(plc::MC_DefaultHoming, 0.0),
                                        ErrorCode::kNoControllerOrFeedEnable});
}

TEST_CASE("every mode is refused while the axis is in error, and Homed is not changed",
          "[homing][refusals]") {
  nc::AxisConfig c = kt::homing_axis();
  c.homed_at_start = true;
  c.sw_limit_max_enabled = true;
  c.sw_limit_max = 50.0;
  kt::TwinKernels t(c);
  // Run both out through the limit with MoveVelocity: 0x4463.
  t.both(kt::move_velocity(500.0, +1));
  t.cycles(400);
  REQUIRE(t.probe.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kSoftLimitMaxDuringMotion));
  REQUIRE(t.same());
  for (int32_t mode : {plc::MC_DefaultHoming, plc::MC_Direct, plc::MC_ForceCalibration,
                       plc::MC_ResetCalibration}) {
    kt::expect_refused_without_effect(
        t, {"mode " + std::to_string(mode), kt::home(mode, 5.0), ErrorCode::kAxisInErrorState}, 5);
  }
  CHECK(kt::bit(*t.probe.x, plc::kStateHomed));
}

TEST_CASE("a coupled slave refuses MC_Home with 0x424E", "[homing][refusals]") {
  kt::Harness h(kt::homing_axis("M"));
  plc::AXIS_REF& slave = h.kernel.add_axis(kt::homing_axis("S"));
  kt::set_enables(slave, true);
  h.cycles(2);
  plc::Command gear;
  gear.type = plc::CommandType::kGearIn;
  gear.ratio = 1.0;
  gear.other_axis = h.x->NcToPlc.AxisIndex;
  const uint16_t g = slave.Mailbox.post(gear);
  h.cycles(2);
  REQUIRE(slave.Mailbox.answer(g).state != CommandState::kError);
  REQUIRE(slave.NcToPlc.CoupleState == static_cast<uint32_t>(plc::CoupleState::kSlave));
  for (int32_t mode : {plc::MC_DefaultHoming, plc::MC_Direct, plc::MC_ForceCalibration}) {
    const plc::NCTOPLC_AXIS_REF before = slave.NcToPlc;
    const uint16_t n = slave.Mailbox.post(kt::home(mode, 5.0));
    h.cycles(1);
    CHECK(slave.Mailbox.answer(n).error_code == kt::id(ErrorCode::kFunctionNotAllowed));
    CHECK(slave.NcToPlc.SetPos == before.SetPos);
    CHECK_FALSE(kt::bit(slave, plc::kStateHomed));
  }
}

TEST_CASE("default homing with a homing velocity above Vmax or Vref is refused with 0x4221",
          "[homing][refusals]") {
  nc::AxisConfig c = kt::homing_axis();
  c.max_velocity = 50.0;  // below the 100 mm/s towards the cam
  kt::TwinKernels t(c);
  kt::expect_refused_without_effect(
      t, {"to cam > Vmax", kt::home(plc::MC_DefaultHoming, 0.0), ErrorCode::kVelocityNotAllowed});
  nc::AxisConfig r = kt::homing_axis();
  r.ref_velocity = 5.0;  // below the 10 mm/s off the cam
  kt::TwinKernels u(r);
  kt::expect_refused_without_effect(
      u, {"off cam > Vref", kt::home(plc::MC_DefaultHoming, 0.0), ErrorCode::kVelocityNotAllowed});
}

TEST_CASE("MC_Direct is refused while the axis moves; the move goes on", "[homing][refusals]") {
  kt::TwinKernels t(kt::homing_axis());
  t.both(kt::move_absolute(300.0, 1000.0));
  t.cycles(30);
  kt::expect_refused_without_effect(
      t, {"moving", kt::home(plc::MC_Direct, 0.0), ErrorCode::kHomingAxisMoving}, 20);
}

TEST_CASE("MC_Home is refused while MC_Stop holds the axis locked", "[homing][refusals]") {
  kt::TwinKernels t(kt::homing_axis());
  t.both(kt::simple(plc::CommandType::kStop));
  t.cycles(5);
  kt::expect_refused_without_effect(
      t, {"locked", kt::home(plc::MC_DefaultHoming, 0.0), ErrorCode::kMotionCommandsLocked});
}
