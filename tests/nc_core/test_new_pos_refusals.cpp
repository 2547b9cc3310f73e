// Every bad input of MC_NewPos (kNewPos) and MC_NewPosAndVelo (kNewPosAndVelo) is refused with
// its specific code and disturbs nothing: twin kernels, one gets the bad command, their NC→PLC
// images stay bit-identical (SPEC B5, B6, NC_ERROR_CODES.md).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "refusal_check.hpp"

using kt::Bad;
using kt::expect_refused_without_effect;
using kt::kInf;
using kt::kNaN;
using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

namespace {

std::vector<Bad> bad_inputs() {
  std::vector<Bad> out;
  for (double p : {kNaN, kInf, -kInf}) {
    const std::string s = std::to_string(p);
    out.push_back({"NewPos " + s, kt::new_pos(p), ErrorCode::kPositionNotFinite});
    out.push_back({"NewPosAndVelo EPos " + s, kt::new_pos_and_velo(p, 1000.0, 0.0),
                   ErrorCode::kPositionNotFinite});
    out.push_back({"NewPosAndVelo VNew " + s, kt::new_pos_and_velo(3000.0, p, 0.0),
                   ErrorCode::kParameterNotFinite});
    out.push_back({"NewPosAndVelo APos " + s, kt::new_pos_and_velo(3000.0, 1000.0, p),
                   ErrorCode::kParameterNotFinite});
  }
  out.push_back(
      {"NewPos above sw_limit_max", kt::new_pos(100000.5), ErrorCode::kTargetPositionNotAllowed});
  out.push_back(
      {"NewPos below sw_limit_min", kt::new_pos(-100001.0), ErrorCode::kTargetPositionNotAllowed});
  out.push_back({"NewPosAndVelo EPos above sw_limit_max",
                 kt::new_pos_and_velo(100000.5, 1000.0, 0.0),
                 ErrorCode::kTargetPositionNotAllowed});
  for (double v : {0.0, -0.0, -100.0}) {
    out.push_back({"NewPosAndVelo VNew " + std::to_string(v), kt::new_pos_and_velo(3000.0, v, 0.0),
                   ErrorCode::kVelocityNotPositive});
  }
  out.push_back({"NewPosAndVelo VNew above Vmax", kt::new_pos_and_velo(3000.0, 2300.0, 0.0),
                 ErrorCode::kVelocityNotAllowed});
  out.push_back({"NewPosAndVelo VNew above Vref", kt::new_pos_and_velo(3000.0, 2150.0, 0.0),
                 ErrorCode::kVelocityNotAllowed});
  return out;
}

}  // namespace

TEST_CASE("bad NewPos and NewPosAndVelo inputs during a positioning are refused with their code",
          "[new_pos][new_pos_and_velo][refusals]") {
  kt::TwinKernels t(kt::refusal_axis());
  t.both(kt::move_absolute(50000.0, 1000.0));
  t.cycles(300);
  for (const Bad& b : bad_inputs())
    expect_refused_without_effect(t, b);
  CHECK(t.probe.x->NcToPlc.SetVelo == Approx(1000.0).margin(1e-9));
}

TEST_CASE("without a positioning job NewPos and NewPosAndVelo are refused with 0x424E",
          "[new_pos][new_pos_and_velo][refusals]") {
  SECTION("at standstill") {
    kt::TwinKernels t(kt::refusal_axis());
    t.cycles(5);
    expect_refused_without_effect(t,
                                  {"NewPos", kt::new_pos(100.0), ErrorCode::kFunctionNotAllowed});
    expect_refused_without_effect(t, {"NewPosAndVelo", kt::new_pos_and_velo(100.0, 500.0, 50.0),
                                      ErrorCode::kFunctionNotAllowed});
  }
  SECTION("during a velocity move") {
    kt::TwinKernels t(kt::refusal_axis());
    t.both(kt::move_velocity(1000.0, 1));
    t.cycles(300);
    expect_refused_without_effect(t,
                                  {"NewPos", kt::new_pos(100.0), ErrorCode::kFunctionNotAllowed});
    expect_refused_without_effect(t, {"NewPosAndVelo", kt::new_pos_and_velo(100.0, 500.0, 50.0),
                                      ErrorCode::kFunctionNotAllowed});
  }
}

TEST_CASE("while a stop is active NewPos and NewPosAndVelo are refused with 0x4242",
          "[new_pos][new_pos_and_velo][refusals]") {
  for (CommandType stop : {CommandType::kStop, CommandType::kHalt}) {
    kt::TwinKernels t(kt::refusal_axis());
    t.both(kt::move_absolute(50000.0, 1000.0));
    t.cycles(300);
    t.both(kt::simple(stop));
    t.cycles(20);
    expect_refused_without_effect(t, {"NewPos", kt::new_pos(100.0), ErrorCode::kStopAlreadyActive});
    expect_refused_without_effect(t, {"NewPosAndVelo", kt::new_pos_and_velo(100.0, 500.0, 50.0),
                                      ErrorCode::kStopAlreadyActive});
  }
}

TEST_CASE("on an axis in error NewPos and NewPosAndVelo are refused with kAxisInErrorState",
          "[new_pos][new_pos_and_velo][refusals]") {
  kt::TwinKernels t(kt::refusal_axis());
  t.both(kt::move_absolute(50000.0, 1000.0));
  t.cycles(300);
  t.enables(true, false, true);  // feed enable plus gone: error 0x4358
  t.cycles(2);
  REQUIRE(t.probe.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kFeedEnablePlusMissing));
  expect_refused_without_effect(t, {"NewPos", kt::new_pos(100.0), ErrorCode::kAxisInErrorState});
  expect_refused_without_effect(
      t, {"NewPosAndVelo", kt::new_pos_and_velo(100.0, 500.0, 50.0), ErrorCode::kAxisInErrorState});
}

TEST_CASE("a new end position needing a direction without feed enable is refused with 0x4223",
          "[new_pos][new_pos_and_velo][refusals]") {
  kt::TwinKernels t(kt::refusal_axis());
  t.enables(true, true, false);
  t.both(kt::move_absolute(50000.0, 1000.0));
  t.cycles(300);
  expect_refused_without_effect(
      t, {"NewPos behind", kt::new_pos(-100.0), ErrorCode::kNoControllerOrFeedEnable});
  expect_refused_without_effect(t,
                                {"NewPosAndVelo behind", kt::new_pos_and_velo(-100.0, 500.0, 0.0),
                                 ErrorCode::kNoControllerOrFeedEnable});
}

TEST_CASE("during a position compensation NewPos and NewPosAndVelo are refused with 0x4245",
          "[new_pos][new_pos_and_velo][refusals]") {
  // Seed 000 §2.3 / §2.4: not while a compensation runs (D 250, VK 300, AK± 500 / 1000, VP 2000,
  // L 5000).
  kt::TwinKernels t(kt::refusal_axis());
  t.both(kt::move_absolute(50000.0, 1000.0));
  t.cycles(300);
  const uint16_t compensation =
      t.both(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
  t.cycles(10);
  REQUIRE(t.probe.state_of(compensation) == CommandState::kActive);
  expect_refused_without_effect(t, {"NewPos", kt::new_pos(100.0), ErrorCode::kCompensationActive});
  expect_refused_without_effect(t, {"NewPosAndVelo", kt::new_pos_and_velo(100.0, 500.0, 50.0),
                                    ErrorCode::kCompensationActive});
}
