// Refusals around external setpoint generation (seed 000 §2.6 "Activation", SPEC B8): enabling
// needs an axis without error, controller and feed enables, a known start type and a finite
// target within the planner's range; a second enable must repeat the start type; beside a PTP
// motion only the relative type; no PTP start while the generation is enabled. A refused command
// disturbs nothing: the NC→PLC image stays bit-identical to a twin that never saw it.
#include <catch2/catch.hpp>

#include <functional>
#include <limits>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

namespace {

void check_refused(const plc::Command& bad, ErrorCode expected,
                   const std::function<void(kt::Harness&)>& prepare, bool enabled = true) {
  kt::Harness h(kt::seed_axis(), 0.001, enabled);
  kt::Harness twin(kt::seed_axis(), 0.001, enabled);
  prepare(h);
  prepare(twin);
  const uint16_t n = h.post(bad);
  h.cycles(1);
  twin.cycles(1);
  CHECK(h.answer(n).state == CommandState::kError);
  CHECK(h.answer(n).error_code == kt::id(expected));
  for (int i = 0; i < 200; ++i) {
    REQUIRE(kt::same_image(h.x->NcToPlc, twin.x->NcToPlc));
    h.cycles(1);
    twin.cycles(1);
  }
}

void nothing(kt::Harness& h) {
  h.cycles(2);
}

void moving(kt::Harness& h) {
  h.post(kt::move_absolute(1000.0, 500.0));
  h.cycles(100);
}

// External generation running, fed with a slow ramp.
std::function<void(kt::Harness&)> external(int type) {
  return [type](kt::Harness& h) {
    h.post(kt::ext_enable(0.0, type));
    kt::feed(*h.x, 0.0, 0.0, 0.0, 0);
    h.cycles(5);
  };
}

}  // namespace

TEST_CASE("enabling is refused on an axis in error, without enables, with a bad type or target",
          "[ext_setpoint][refusals]") {
  check_refused(kt::ext_enable(0.0, 1), ErrorCode::kAxisInErrorState, [](kt::Harness& h) {
    h.post(kt::move_velocity(100.0, 1));
    h.cycles(50);
    kt::set_enables(*h.x, true, false, true);  // 0x4358
    h.cycles(50);
  });
  check_refused(kt::ext_enable(0.0, 1), ErrorCode::kNoControllerOrFeedEnable, nothing, false);
  check_refused(kt::ext_enable(0.0, 2), ErrorCode::kNoControllerOrFeedEnable, [](kt::Harness& h) {
    kt::set_enables(*h.x, true, true, false);
    h.cycles(2);
  });
  for (int type : {0, 3, -1}) {
    INFO("position type " << type);
    check_refused(kt::ext_enable(0.0, type), ErrorCode::kStartTypeNotAllowed, nothing);
  }
  check_refused(kt::ext_enable(std::numeric_limits<double>::quiet_NaN(), 1),
                ErrorCode::kPositionNotFinite, nothing);
  check_refused(kt::ext_enable(std::numeric_limits<double>::infinity(), 2),
                ErrorCode::kPositionNotFinite, nothing);
  // Beyond the planner's range (|target| > 1e12 mm, as for a move): 0x4222; a relative target
  // counts from the running move's target (fuzz: 3.6e307 overflowed a slave's TargetPos).
  check_refused(kt::ext_enable(3.6e307, 1), ErrorCode::kTargetPositionNotAllowed, nothing);
  check_refused(kt::ext_enable(-1.0e12 - 1.0e6, 1), ErrorCode::kTargetPositionNotAllowed, nothing);
  check_refused(kt::ext_enable(1.0e12 - 500.0, 2), ErrorCode::kTargetPositionNotAllowed, moving);
}

TEST_CASE("a second enable must repeat the start type; the same type takes the new target",
          "[ext_setpoint][refusals]") {
  check_refused(kt::ext_enable(0.0, 2), ErrorCode::kStartTypeNotAllowed, external(1));
  check_refused(kt::ext_enable(0.0, 1), ErrorCode::kStartTypeNotAllowed, external(2));

  kt::Harness h;
  external(1)(h);
  kt::feed(*h.x, 5.0, 0.0, 0.0, 1);
  h.cycles(1);
  const uint16_t again = h.post(kt::ext_enable(123.0, 1));
  h.cycles(1);
  CHECK(h.state_of(again) == CommandState::kDone);
  CHECK(h.x->NcToPlc.TargetPos == 123.0);
  CHECK(h.x->NcToPlc.SetPos == 5.0);  // the generation went on
}

TEST_CASE("beside a running PTP motion only the relative start type (0x4239)",
          "[ext_setpoint][refusals]") {
  check_refused(kt::ext_enable(0.0, 1), ErrorCode::kStartTypeNotAllowed, moving);
  kt::Harness h;
  moving(h);
  const uint16_t rel = h.post(kt::ext_enable(0.0, 2));
  h.cycles(1);
  CHECK(h.state_of(rel) == CommandState::kDone);
}

TEST_CASE("no PTP start while external generation is enabled, whatever its type (0x4239)",
          "[ext_setpoint][refusals]") {
  for (int type : {1, 2}) {
    INFO("position type " << type);
    check_refused(kt::move_absolute(100.0, 500.0), ErrorCode::kStartTypeNotAllowed, external(type));
    check_refused(kt::move_relative(100.0, 500.0), ErrorCode::kStartTypeNotAllowed, external(type));
    check_refused(kt::move_velocity(100.0, 1), ErrorCode::kStartTypeNotAllowed, external(type));
  }
  // Relative external generation joined a running positioning: a new PTP start is still refused.
  check_refused(kt::move_absolute(100.0, 500.0), ErrorCode::kStartTypeNotAllowed,
                [](kt::Harness& h) {
                  moving(h);
                  h.post(kt::ext_enable(0.0, 2));
                  h.cycles(5);
                });
}

TEST_CASE("no enable during a compensation (0x4245) or a stop (0x4242)",
          "[ext_setpoint][refusals]") {
  check_refused(kt::ext_enable(0.0, 2), ErrorCode::kCompensationActive, [](kt::Harness& h) {
    h.post(kt::move_absolute(10000.0, 2000.0));
    h.cycles(600);
    h.post(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
    h.cycles(10);
  });
  check_refused(kt::ext_enable(0.0, 2), ErrorCode::kStopAlreadyActive, [](kt::Harness& h) {
    moving(h);
    h.post(kt::simple(CommandType::kHalt));
    h.cycles(5);
  });
}
