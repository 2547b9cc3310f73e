// Refusals on a two-speed axis (SPEC E2, E3; seed 004: "An axis start will only be initiated if
// the distance from the target point is in fact larger than the parameterized braking distance",
// "v ≤ 0 Error"): each bad start gets its own code and changes nothing — not the image, not
// nAxisState, not a positioning already running; errors during motion brake at once.
#include <catch2/catch.hpp>

#include <limits>
#include <string_view>
#include <vector>

#include "nc_core/config.hpp"
#include "two_speed_loop.hpp"

using ts::Sample;
using ts::State;
using E = plc::ErrorCode;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// `start` on a loop at rest at 0 is refused with `code`, and the next 100 cycles are those of an
// axis that was never started.
void expect_refused(double target, double velocity, E code) {
  ts::Loop refused(ts::issue_axis());
  ts::Loop untouched(ts::issue_axis());
  refused.cycle();
  untouched.cycle();
  CHECK(refused.start(target, velocity) == code);
  CHECK_FALSE(refused.sequencer.busy());
  for (int i = 0; i < 100; ++i) {
    refused.cycle();
    untouched.cycle();
  }
  CHECK(refused.trace == untouched.trace);
}

}  // namespace

TEST_CASE("a start velocity <= 0 is an error (0x4231), a non-finite one 0x4F02",
          "[two_speed][refusal]") {
  expect_refused(1000.0, 0.0, E::kVelocityNotPositive);
  expect_refused(1000.0, -40.0, E::kVelocityNotPositive);
  expect_refused(1000.0, -0.0, E::kVelocityNotPositive);
  expect_refused(1000.0, kNaN, E::kParameterNotFinite);
  expect_refused(1000.0, kInf, E::kParameterNotFinite);
  CHECK(plc::to_id(E::kVelocityNotPositive) == 0x4231);
}

TEST_CASE("a non-finite target is refused with 0x4F01", "[two_speed][refusal]") {
  expect_refused(kNaN, 2000.0, E::kPositionNotFinite);
  expect_refused(-kInf, 2000.0, E::kPositionNotFinite);
}

TEST_CASE("a distance not larger than the braking distance is refused with 0x4F0C",
          "[two_speed][refusal]") {
  expect_refused(5.0, 2000.0, E::kTwoSpeedDistanceTooShort);   // = braking distance +
  expect_refused(-6.0, 2000.0, E::kTwoSpeedDistanceTooShort);  // = braking distance -
  expect_refused(3.0, 2000.0, E::kTwoSpeedDistanceTooShort);
  expect_refused(0.0, 2000.0, E::kTwoSpeedDistanceTooShort);
  CHECK(plc::to_id(E::kTwoSpeedDistanceTooShort) == 0x4F0C);
  CHECK(plc::error_text(0x4F0Cu) != std::string_view("unknown error code"));

  // Just beyond: accepted, and the creep alone brings it there.
  for (const double target : {5.5, -6.5}) {
    ts::Loop loop(ts::issue_axis());
    REQUIRE(loop.start(target, 2000.0) == E::kNone);
    CHECK(loop.run_to_event().event == ts::TwoSpeedEvent::kDone);
    CHECK(ts::state_sequence(loop.trace) == std::vector<uint32_t>{21, 23, 24, 20});
  }
}

TEST_CASE("a start needs the enable (0x4356) and an axis at rest (0x424E)",
          "[two_speed][refusal]") {
  ts::Loop loop(ts::issue_axis());
  loop.sequencer.set_enabled(false);
  CHECK(loop.start(1000.0, 2000.0) == E::kControllerEnableMissing);
  CHECK(loop.stop() == E::kControllerEnableMissing);
  CHECK(loop.cycle().state == State::kInactive);

  // A second start while a positioning runs leaves the positioning exactly as it was.
  ts::Loop plain(ts::issue_axis());
  REQUIRE(plain.start(1000.0, 2000.0) == E::kNone);
  plain.run_to_event();
  ts::Loop busy(ts::issue_axis());
  REQUIRE(busy.start(1000.0, 2000.0) == E::kNone);
  busy.run_to_event(20000, [](ts::Loop& l) {
    if (l.trace.size() % 500 == 10) CHECK(l.start(-500.0, 40.0) == E::kFunctionNotAllowed);
  });
  CHECK(busy.trace == plain.trace);
}

TEST_CASE("a non-finite actual position refuses a start and ends a running positioning",
          "[two_speed][refusal]") {
  ts::Loop loop(ts::issue_axis());
  CHECK(loop.sequencer.start(1000.0, 2000.0, kNaN) == E::kActualValueNotFinite);
  REQUIRE(loop.start(1000.0, 2000.0) == E::kNone);
  loop.run_cycles(300);
  REQUIRE(loop.trace.back().bit(plc::ControlByteBit::bPlusHigh));
  const nc::detail::TwoSpeedCycle out = loop.sequencer.step(kNaN, 0.001);
  CHECK(out.event == ts::TwoSpeedEvent::kError);
  CHECK(out.error == E::kActualValueNotFinite);
  CHECK(out.state == State::kStopped);
  CHECK(plc::read_control_byte(loop.sequencer.image().nControlByte) ==
        plc::TwoSpeedDriveCommand{});  // no travel, brake on
  CHECK(plc::control_bytes_consistent(loop.sequencer.image()));
}

TEST_CASE("disabling during a positioning brakes at once and shows nAxisState 0",
          "[two_speed][refusal]") {
  ts::Loop loop(ts::issue_axis());
  REQUIRE(loop.start(1000.0, 2000.0) == E::kNone);
  loop.run_cycles(300);
  loop.sequencer.set_enabled(false);
  const Sample& s = loop.cycle();
  CHECK(s.state == State::kInactive);
  CHECK(s.brake());
  CHECK_FALSE(s.travel());
  CHECK(s.event == ts::TwoSpeedEvent::kNone);
  CHECK_FALSE(loop.sequencer.busy());
}

TEST_CASE("the sequencer refuses a configuration that breaks the two-speed rules",
          "[two_speed][refusal]") {
  nc::AxisConfig c = ts::issue_axis();
  c.braking_distance_negative = 121.0;
  CHECK_THROWS_AS(nc::detail::TwoSpeedSequencer(c), nc::ConfigError);
}
