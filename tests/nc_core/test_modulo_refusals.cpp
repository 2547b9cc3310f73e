// Every bad input of a modulo start (kMoveModulo, MC_MoveModulo) is refused with its specific
// code and disturbs nothing: twin kernels, one gets the bad command, their NC→PLC images stay
// bit-identical (SPEC B1, NC_ERROR_CODES.md).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "refusal_check.hpp"

using kt::Bad;
using kt::expect_refused_without_effect;
using kt::kInf;
using kt::kNaN;
using kt::with;
using plc::CommandType;
using plc::ErrorCode;

TEST_CASE("bad MoveModulo inputs are refused with their code and disturb nothing",
          "[modulo][refusals]") {
  kt::TwinKernels t(kt::refusal_axis());
  t.both(kt::move_velocity(1000.0, 1));
  t.cycles(300);
  using C = plc::Command;
  const plc::Command good = kt::move_modulo(90.0, 1000.0, 1);
  std::vector<Bad> bads;
  for (double v : {kNaN, kInf, -kInf}) {
    const std::string s = std::to_string(v);
    bads.push_back({"position " + s, with(good, &C::position, v), ErrorCode::kPositionNotFinite});
    bads.push_back({"velocity " + s, with(good, &C::velocity, v), ErrorCode::kParameterNotFinite});
    bads.push_back(
        {"acceleration " + s, with(good, &C::acceleration, v), ErrorCode::kParameterNotFinite});
    bads.push_back(
        {"deceleration " + s, with(good, &C::deceleration, v), ErrorCode::kParameterNotFinite});
    bads.push_back({"jerk " + s, with(good, &C::jerk, v), ErrorCode::kParameterNotFinite});
  }
  // More than 1 000 000 extra turns.
  bads.push_back(
      {"position 1e12", with(good, &C::position, 1e12), ErrorCode::kModuloTargetInvalid});
  bads.push_back(
      {"position -1e12", with(good, &C::position, -1e12), ErrorCode::kModuloTargetInvalid});
  // 500 turns end beyond the software limit.
  bads.push_back({"position 180000 (end beyond sw_limit_max)", with(good, &C::position, 180000.0),
                  ErrorCode::kTargetPositionNotAllowed});
  for (int32_t d : {0, 5, -1, -3, 128}) {
    plc::Command c = good;
    c.direction = d;
    bads.push_back({"direction " + std::to_string(d), c, ErrorCode::kDirectionInvalid});
  }
  for (double v : {0.0, -0.0, -100.0}) {
    bads.push_back({"velocity " + std::to_string(v), with(good, &C::velocity, v),
                    ErrorCode::kVelocityNotPositive});
  }
  bads.push_back(
      {"velocity above Vmax", with(good, &C::velocity, 2300.0), ErrorCode::kVelocityNotAllowed});
  bads.push_back(
      {"velocity above Vref", with(good, &C::velocity, 2150.0), ErrorCode::kVelocityNotAllowed});
  bads.push_back(
      {"acceleration -1", with(good, &C::acceleration, -1.0), ErrorCode::kAccelerationNotAllowed});
  bads.push_back(
      {"deceleration -1", with(good, &C::deceleration, -1.0), ErrorCode::kDecelerationNotAllowed});
  bads.push_back({"jerk -1", with(good, &C::jerk, -1.0), ErrorCode::kJerkNotAllowed});
  plc::Command buffered = good;
  buffered.buffer_mode = 6;  // not an MC_BufferMode value (MC_BlendingHigh is 5)
  bads.push_back({"buffer mode 6", buffered, ErrorCode::kBufferModeNotSupported});
  for (const Bad& b : bads)
    expect_refused_without_effect(t, b);
  CHECK(t.probe.x->NcToPlc.SetVelo == 1000.0);
}

TEST_CASE("MoveModulo with MC_Current_Direction at standstill is refused with kDirectionInvalid",
          "[modulo][refusals]") {
  kt::TwinKernels t(kt::refusal_axis());
  t.cycles(5);
  expect_refused_without_effect(t, {"current direction at rest", kt::move_modulo(90.0, 1000.0, 4),
                                    ErrorCode::kDirectionInvalid});
}

TEST_CASE("MoveModulo on a locked axis or an axis in error is refused", "[modulo][refusals]") {
  SECTION("locked by MC_Stop") {
    kt::TwinKernels t(kt::refusal_axis());
    t.both(kt::move_velocity(1000.0, 1));
    t.cycles(300);
    t.both(kt::simple(CommandType::kStop));
    t.cycles(20);
    expect_refused_without_effect(
        t, {"locked", kt::move_modulo(90.0, 1000.0, 1), ErrorCode::kMotionCommandsLocked});
  }
  SECTION("in error") {
    kt::TwinKernels t(kt::refusal_axis());
    t.both(kt::move_velocity(1000.0, 1));
    t.cycles(300);
    t.enables(true, false, true);
    t.cycles(2);
    expect_refused_without_effect(
        t, {"in error", kt::move_modulo(90.0, 1000.0, 3), ErrorCode::kAxisInErrorState});
  }
}
