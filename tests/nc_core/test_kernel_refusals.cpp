// Every bad input of every command is refused with kError and its specific code, and changes
// nothing: two identical kernels run side by side, one of them gets the bad command while a move
// runs, and their NC→PLC images stay bit-identical afterwards (SPEC B2, NC_ERROR_CODES.md).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "refusal_check.hpp"

using kt::Bad;
using kt::kInf;
using kt::kNaN;
using kt::with;
using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

namespace {

// The images are compared for 100 cycles after each refusal.
void expect_refused(kt::TwinKernels& t, const Bad& bad) {
  kt::expect_refused_without_effect(t, bad, 100);
}

std::vector<Bad> bad_dynamics(const plc::Command& good, const std::string& name) {
  using C = plc::Command;
  std::vector<Bad> out;
  for (double v : {kNaN, kInf, -kInf}) {
    const std::string s = std::to_string(v);
    out.push_back(
        {name + " velocity " + s, with(good, &C::velocity, v), ErrorCode::kParameterNotFinite});
    out.push_back({name + " acceleration " + s, with(good, &C::acceleration, v),
                   ErrorCode::kParameterNotFinite});
    out.push_back({name + " deceleration " + s, with(good, &C::deceleration, v),
                   ErrorCode::kParameterNotFinite});
    out.push_back({name + " jerk " + s, with(good, &C::jerk, v), ErrorCode::kParameterNotFinite});
  }
  out.push_back(
      {name + " velocity 0", with(good, &C::velocity, 0.0), ErrorCode::kVelocityNotPositive});
  out.push_back(
      {name + " velocity -0", with(good, &C::velocity, -0.0), ErrorCode::kVelocityNotPositive});
  out.push_back(
      {name + " velocity -100", with(good, &C::velocity, -100.0), ErrorCode::kVelocityNotPositive});
  out.push_back({name + " velocity above Vmax", with(good, &C::velocity, 2300.0),
                 ErrorCode::kVelocityNotAllowed});
  out.push_back({name + " velocity above Vref", with(good, &C::velocity, 2150.0),
                 ErrorCode::kVelocityNotAllowed});
  out.push_back({name + " acceleration -1", with(good, &C::acceleration, -1.0),
                 ErrorCode::kAccelerationNotAllowed});
  out.push_back({name + " deceleration -1", with(good, &C::deceleration, -1.0),
                 ErrorCode::kDecelerationNotAllowed});
  out.push_back({name + " jerk -1", with(good, &C::jerk, -1.0), ErrorCode::kJerkNotAllowed});
  plc::Command buffered = good;
  buffered.buffer_mode = 6;  // not an MC_BufferMode value (MC_BlendingHigh is 5)
  out.push_back({name + " buffer mode 6", buffered, ErrorCode::kBufferModeNotSupported});
  return out;
}

std::vector<Bad> bad_stops(CommandType type, const std::string& name) {
  const plc::Command good = kt::simple(type, 3000.0, 30000.0);
  using C = plc::Command;
  std::vector<Bad> out;
  for (double v : {kNaN, kInf, -kInf}) {
    out.push_back({name + " deceleration " + std::to_string(v), with(good, &C::deceleration, v),
                   ErrorCode::kParameterNotFinite});
    out.push_back({name + " jerk " + std::to_string(v), with(good, &C::jerk, v),
                   ErrorCode::kParameterNotFinite});
  }
  out.push_back({name + " deceleration -1", with(good, &C::deceleration, -1.0),
                 ErrorCode::kDecelerationNotAllowed});
  out.push_back({name + " jerk -1", with(good, &C::jerk, -1.0), ErrorCode::kJerkNotAllowed});
  return out;
}

}  // namespace

TEST_CASE(
    "bad MoveAbsolute, MoveRelative, MoveVelocity, Halt and Stop inputs are refused with "
    "their code and disturb nothing",
    "[kernel][refusals]") {
  kt::TwinKernels t(kt::refusal_axis());
  t.both(kt::move_velocity(1000.0, 1));
  t.cycles(300);  // moving at 1000 mm/s

  std::vector<Bad> bads;
  const plc::Command abs = kt::move_absolute(100.0, 1000.0);
  for (double p : {kNaN, kInf, -kInf}) {
    bads.push_back({"MoveAbsolute position " + std::to_string(p),
                    with(abs, &plc::Command::position, p), ErrorCode::kPositionNotFinite});
  }
  bads.push_back({"MoveAbsolute above sw_limit_max", kt::move_absolute(100000.5, 1000.0),
                  ErrorCode::kTargetPositionNotAllowed});
  bads.push_back({"MoveAbsolute below sw_limit_min", kt::move_absolute(-100001.0, 1000.0),
                  ErrorCode::kTargetPositionNotAllowed});
  for (const Bad& b : bad_dynamics(abs, "MoveAbsolute"))
    bads.push_back(b);

  const plc::Command rel = kt::move_relative(100.0, 1000.0);
  for (double p : {kNaN, kInf, -kInf}) {
    bads.push_back({"MoveRelative distance " + std::to_string(p),
                    with(rel, &plc::Command::position, p), ErrorCode::kPositionNotFinite});
  }
  bads.push_back({"MoveRelative beyond sw_limit_max", kt::move_relative(100000.0, 1000.0),
                  ErrorCode::kTargetPositionNotAllowed});
  for (const Bad& b : bad_dynamics(rel, "MoveRelative"))
    bads.push_back(b);

  const plc::Command vel = kt::move_velocity(1000.0, 1);
  for (const Bad& b : bad_dynamics(vel, "MoveVelocity"))
    bads.push_back(b);
  // 4 (MC_Current_Direction) is valid while moving; refused at standstill (test_move_velocity).
  for (int32_t d : {0, 2, 5, -3, 128}) {
    plc::Command c = vel;
    c.direction = d;
    bads.push_back(
        {"MoveVelocity direction " + std::to_string(d), c, ErrorCode::kDirectionInvalid});
  }
  for (const Bad& b : bad_stops(CommandType::kHalt, "Halt"))
    bads.push_back(b);
  plc::Command buffered_halt = kt::simple(CommandType::kHalt);
  buffered_halt.buffer_mode = -1;  // not an MC_BufferMode value
  bads.push_back({"Halt buffer mode -1", buffered_halt, ErrorCode::kBufferModeNotSupported});
  for (const Bad& b : bad_stops(CommandType::kStop, "Stop"))
    bads.push_back(b);

  for (const Bad& b : bads)
    expect_refused(t, b);
  // The axis was moving the whole time and still is.
  CHECK(t.probe.x->NcToPlc.SetVelo == 1000.0);
}

TEST_CASE(
    "a start without controller enable or without feed enable for its direction is "
    "refused with 0x4223",
    "[kernel][refusals]") {
  SECTION("feed enable plus missing while a negative move runs") {
    kt::TwinKernels t(kt::refusal_axis());
    t.enables(true, false, true);
    t.both(kt::move_absolute(-3000.0, 1000.0));
    t.cycles(300);
    expect_refused(t, {"positive MoveAbsolute", kt::move_absolute(100.0, 500.0),
                       ErrorCode::kNoControllerOrFeedEnable});
    expect_refused(t, {"positive MoveVelocity", kt::move_velocity(500.0, 1),
                       ErrorCode::kNoControllerOrFeedEnable});
    CHECK(t.probe.x->NcToPlc.SetVelo < -900.0);
  }
  SECTION("feed enable minus missing while a positive move runs") {
    kt::TwinKernels t(kt::refusal_axis());
    t.enables(true, true, false);
    t.both(kt::move_absolute(3000.0, 1000.0));
    t.cycles(300);
    expect_refused(t, {"negative MoveRelative", kt::move_relative(-2000.0, 500.0),
                       ErrorCode::kNoControllerOrFeedEnable});
    expect_refused(t, {"negative MoveVelocity", kt::move_velocity(500.0, 3),
                       ErrorCode::kNoControllerOrFeedEnable});
  }
  SECTION("controller enable missing") {
    kt::TwinKernels t(kt::refusal_axis());
    t.enables(false, true, true);
    t.cycles(5);
    for (const plc::Command& c : {kt::move_absolute(100.0, 500.0), kt::move_relative(-100.0, 500.0),
                                  kt::move_velocity(500.0, 1), kt::simple(CommandType::kHalt),
                                  kt::simple(CommandType::kStop)}) {
      expect_refused(t, {"disabled", c, ErrorCode::kNoControllerOrFeedEnable});
    }
    CHECK(kt::axis_state(*t.probe.x) == plc::AxisState::kDisabled);
    CHECK_FALSE(kt::bit(*t.probe.x, plc::kStateOperational));
  }
}

TEST_CASE("motion commands on a locked axis are refused with 0x42EF", "[kernel][refusals]") {
  kt::TwinKernels t(kt::refusal_axis());
  t.both(kt::move_velocity(1000.0, 1));
  t.cycles(300);
  t.both(kt::simple(CommandType::kStop));
  t.cycles(20);  // still stopping
  for (const plc::Command& c : {kt::move_absolute(100.0, 500.0), kt::move_relative(-100.0, 500.0),
                                kt::move_velocity(500.0, 1), kt::simple(CommandType::kHalt)}) {
    expect_refused(t, {"locked", c, ErrorCode::kMotionCommandsLocked});
  }
}

TEST_CASE("motion commands on an axis in error are refused with kAxisInErrorState",
          "[kernel][refusals]") {
  kt::TwinKernels t(kt::refusal_axis());
  t.both(kt::move_velocity(1000.0, 1));
  t.cycles(300);
  // Feed enable plus removed while moving forward: axis error 0x4358, emergency ramp.
  t.enables(true, false, true);
  t.cycles(1);
  REQUIRE(t.probe.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kFeedEnablePlusMissing));
  t.cycles(10);  // the error ramp is running
  for (const plc::Command& c : {kt::move_absolute(100.0, 500.0), kt::move_relative(-100.0, 500.0),
                                kt::move_velocity(500.0, 3), kt::simple(CommandType::kHalt),
                                kt::simple(CommandType::kStop)}) {
    expect_refused(t, {"in error", c, ErrorCode::kAxisInErrorState});
  }
}

TEST_CASE("MoveVelocity outward from a software limit it stands on is refused with 0x4460/0x4461",
          "[kernel][refusals]") {
  nc::AxisConfig at_max = kt::refusal_axis();
  at_max.sw_limit_max = 0.0;
  kt::Harness h(at_max);
  const uint16_t up = h.post(kt::move_velocity(100.0, 1));
  h.cycles(1);
  CHECK(h.answer(up).error_code == kt::id(ErrorCode::kSoftLimitMaxAtStart));
  CHECK(h.x->NcToPlc.SetPos == 0.0);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  const uint16_t back = h.post(kt::move_velocity(100.0, -1));  // back into the range: allowed
  h.cycles(1);
  CHECK(h.state_of(back) == CommandState::kActive);

  nc::AxisConfig at_min = kt::refusal_axis();
  at_min.sw_limit_min = 0.0;
  kt::Harness g(at_min);
  const uint16_t down = g.post(kt::move_velocity(100.0, 3));
  g.cycles(1);
  CHECK(g.answer(down).error_code == kt::id(ErrorCode::kSoftLimitMinAtStart));
  CHECK(g.x->NcToPlc.ErrorCode == 0);
}
