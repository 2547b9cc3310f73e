// Finite but extreme dynamics and targets (fuzz finding K1) are refused when the command is
// accepted, with the code of the input, and disturb nothing: a command's A, D, J (0 = default)
// must lie in the planner's range [1e-9, 1e12], a target at most 1e12 mm from 0
// (docs/behaviour.md, "Starts"). Twin kernels, one gets the bad command while a move runs, their
// NC→PLC images stay bit-identical.
#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "refusal_check.hpp"

using kt::Bad;
using kt::with;
using plc::CommandType;
using plc::ErrorCode;

namespace {

// Values just outside the range, the kept fuzz inputs' values, and the extremes of a double.
const double kOutside[] = {0.99e-9, 2.2e-308, 4.9e-324, 1.01e12, 2.2e301, 1.7e308};

// "MoveAbsolute acceleration 1e-09": what a case is, for the failure message.
std::string label(const char* name, const char* field, double value) {
  std::ostringstream out;
  out << name << ' ' << field << ' ' << value;
  return out.str();
}

void add_bad_dynamics(std::vector<Bad>& out, const plc::Command& good, const char* name) {
  using C = plc::Command;
  for (double v : kOutside) {
    out.push_back({label(name, "acceleration", v), with(good, &C::acceleration, v),
                   ErrorCode::kAccelerationNotAllowed});
    out.push_back({label(name, "deceleration", v), with(good, &C::deceleration, v),
                   ErrorCode::kDecelerationNotAllowed});
    out.push_back({label(name, "jerk", v), with(good, &C::jerk, v), ErrorCode::kJerkNotAllowed});
  }
}

}  // namespace

TEST_CASE("dynamics outside [1e-9, 1e12] are refused at the start and disturb nothing",
          "[kernel][refusals][range]") {
  kt::TwinKernels t(kt::seed_axis());
  t.both(kt::move_velocity(1000.0, 1));
  t.cycles(300);  // moving at 1000 mm/s

  std::vector<Bad> bads;
  add_bad_dynamics(bads, kt::move_absolute(100.0, 1000.0), "MoveAbsolute");
  add_bad_dynamics(bads, kt::move_relative(100.0, 1000.0), "MoveRelative");
  add_bad_dynamics(bads, kt::move_velocity(500.0, 1), "MoveVelocity");
  for (double v : kOutside) {
    for (CommandType type : {CommandType::kHalt, CommandType::kStop}) {
      const char* name = type == CommandType::kHalt ? "Halt" : "Stop";
      bads.push_back({label(name, "deceleration", v), kt::simple(type, v, 30000.0),
                      ErrorCode::kDecelerationNotAllowed});
      bads.push_back(
          {label(name, "jerk", v), kt::simple(type, 3000.0, v), ErrorCode::kJerkNotAllowed});
    }
  }
  // The kept input blocks-stop-huge-deceleration-and-jerk-at-rest: both "larger", so they
  // would have been adopted.
  bads.push_back({"Stop D 2e307 J 1.79e308", kt::simple(CommandType::kStop, 2e307, 1.79e308),
                  ErrorCode::kDecelerationNotAllowed});
  for (const Bad& b : bads)
    kt::expect_refused_without_effect(t, b, 20);
  CHECK(t.probe.x->NcToPlc.SetVelo == 1000.0);
}

TEST_CASE("targets beyond 1e12 mm are refused with 0x4222 and disturb nothing",
          "[kernel][refusals][range]") {
  kt::TwinKernels t(kt::seed_axis());  // no software limits: only the range refuses
  t.both(kt::move_absolute(5000.0, 1000.0));
  t.cycles(400);  // a positioning runs at 1000 mm/s

  std::vector<Bad> bads;
  for (double p : {1.01e12, -1.01e12, 2.6e307, -1.7e308}) {
    bads.push_back({label("MoveAbsolute", "target", p), kt::move_absolute(p, 1000.0),
                    ErrorCode::kTargetPositionNotAllowed});
    bads.push_back({label("MoveRelative", "distance", p), kt::move_relative(p, 1000.0),
                    ErrorCode::kTargetPositionNotAllowed});
    bads.push_back(
        {label("NewPos", "target", p), kt::new_pos(p), ErrorCode::kTargetPositionNotAllowed});
  }
  // The kept input blocks-move-tiny-acceleration-huge-target: A+ 2.2e-308, target 2.6e307.
  bads.push_back({"MoveAbsolute A 2.2e-308 to 2.6e307",
                  kt::move_absolute(2.6e307, 1000.0, 2.2e-308),
                  ErrorCode::kAccelerationNotAllowed});
  for (const Bad& b : bads)
    kt::expect_refused_without_effect(t, b, 20);
  CHECK(t.probe.x->NcToPlc.SetVelo == 1000.0);
}

TEST_CASE("dynamics at the edges of the range are accepted", "[kernel][refusals][range]") {
  kt::Harness fast;
  const uint16_t n = fast.post(kt::move_absolute(100.0, 1000.0, 1e12, 1e12, 1e12));
  REQUIRE(fast.cycles_until([&] { return fast.state_of(n) == plc::CommandState::kDone; }, 1000) >
          0);
  CHECK(fast.x->NcToPlc.SetPos == 100.0);

  kt::Harness slow;
  const uint16_t m = slow.post(kt::move_velocity(10.0, 1, 1e-9, 1e-9, 1e-9));
  slow.cycles(10);
  CHECK(slow.state_of(m) == plc::CommandState::kActive);
  CHECK(slow.x->NcToPlc.ErrorCode == 0);
}
