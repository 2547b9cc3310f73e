// Start velocity and override on a two-speed axis (SPEC E3; seed 004 "Velocity and override"):
// v > 50 rapid, 0 < v <= 50 creep; override > 50 % rapid, 0 < o <= 50 % creep, below 0.01 %
// stationary; an override change acts only in the main travel phase and leaves a braking phase
// exactly as it would have run.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "two_speed_loop.hpp"

using ts::Sample;
using ts::State;
using C = plc::ControlByteBit;

namespace {

bool ever(const std::vector<Sample>& trace, C bit) {
  return ts::first(trace, [bit](const Sample& s) { return s.bit(bit); }) != ts::kNotFound;
}

// A positioning 0 → 1000 with `override_value` (0 … 1'000'000) set before the start.
std::vector<Sample> run(double velocity, uint32_t override_value) {
  ts::Loop loop(ts::issue_axis());
  REQUIRE(loop.sequencer.set_override(override_value) == plc::ErrorCode::kNone);
  REQUIRE(loop.start(1000.0, velocity) == plc::ErrorCode::kNone);
  REQUIRE(loop.run_to_event().event == ts::TwoSpeedEvent::kDone);
  CHECK(ts::images_consistent(loop.trace));
  return loop.trace;
}

}  // namespace

TEST_CASE("start velocity above 50 is rapid, 50 and below creep only", "[two_speed][override]") {
  for (const double v : {40.0, 50.0, 1e-3}) {
    INFO("v " << v);
    const auto trace = run(v, plc::kOverrideFull);
    CHECK_FALSE(ever(trace, C::bPlusHigh));
    CHECK(ts::first(trace, [](const Sample& s) { return s.bit(C::bPlusLow); }) == 50);
    // No rapid, so no rapid-to-creep delay: main travel in creep, then the creep phase at 900.
    CHECK(ts::state_sequence(trace) == std::vector<uint32_t>{21, 23, 24, 20});
    const std::size_t creep_phase =
        ts::first(trace, [](const Sample& s) { return s.state == State::kLowSpeedTravel; });
    REQUIRE(creep_phase != ts::kNotFound);
    CHECK(trace[creep_phase].actual >= 900.0);
  }
  for (const double v : {50.001, 2000.0}) {
    INFO("v " << v);
    CHECK(ts::first(run(v, plc::kOverrideFull),
                    [](const Sample& s) { return s.bit(C::bPlusHigh); }) == 50);
  }
}

TEST_CASE("override above 50 % is rapid, 0.01 % … 50 % creep, below 0.01 % stationary",
          "[two_speed][override]") {
  CHECK(ever(run(2000.0, 500'001), C::bPlusHigh));
  for (const uint32_t o : {500'000U, 400'000U, 100U}) {
    INFO("override " << o);
    const auto trace = run(2000.0, o);
    CHECK_FALSE(ever(trace, C::bPlusHigh));
    CHECK(ever(trace, C::bPlusLow));
  }
  // 0.0099 %: stationary — brake released, no travel bit, main travel phase, nothing moves.
  ts::Loop loop(ts::issue_axis());
  REQUIRE(loop.sequencer.set_override(99) == plc::ErrorCode::kNone);
  REQUIRE(loop.start(1000.0, 2000.0) == plc::ErrorCode::kNone);
  for (int i = 0; i < 1000; ++i) {
    const Sample& s = loop.cycle();
    CHECK_FALSE(s.travel());
    CHECK_FALSE(s.brake());
    CHECK(s.state == State::kMainTravel);
  }
  CHECK(loop.actual() == 0.0);
}

TEST_CASE("override 40 % during rapid switches to creep through the rapid-to-creep delay",
          "[two_speed][override]") {
  ts::Loop loop(ts::issue_axis());
  REQUIRE(loop.start(1000.0, 2000.0) == plc::ErrorCode::kNone);
  loop.run_cycles(500);
  REQUIRE(loop.trace.back().bit(C::bPlusHigh));
  const std::size_t k = loop.trace.size();
  loop.set_override_percent(40.0);
  REQUIRE(loop.run_to_event().event == ts::TwoSpeedEvent::kDone);
  const auto& trace = loop.trace;
  CHECK(ts::images_consistent(trace));
  for (std::size_t i = k; i < trace.size(); ++i)
    CHECK_FALSE(trace[i].bit(C::bPlusHigh));
  for (std::size_t i = k; i < k + 20; ++i) {
    CHECK_FALSE(trace[i].travel());
    CHECK(trace[i].state == State::kMainTravel);
  }
  CHECK(trace[k + 20].bit(C::bPlusLow));
  CHECK(trace[k + 20].state == State::kMainTravel);
  // The rapid was off long before the creep distance: no second delay there.
  CHECK(ts::state_sequence(trace) == std::vector<uint32_t>{21, 23, 24, 20});
  loop.run_cycles();
  CHECK(std::abs(loop.actual() - 1000.0) <= 5.0);
}

TEST_CASE("override 0 holds the axis in main travel and a rising override resumes it",
          "[two_speed][override]") {
  ts::Loop loop(ts::issue_axis());
  REQUIRE(loop.start(1000.0, 2000.0) == plc::ErrorCode::kNone);
  loop.run_cycles(500);
  loop.set_override_percent(0.0);
  for (int i = 0; i < 1000; ++i) {
    const Sample& s = loop.cycle();
    CHECK_FALSE(s.travel());
    CHECK_FALSE(s.brake());
    CHECK(s.state == State::kMainTravel);
  }
  // At rest: 0.1 s of run-down from 500 mm/s, then still.
  const double held = loop.actual();
  CHECK(loop.plant.velocity() == 0.0);
  loop.run_cycles(100);
  CHECK(loop.actual() == held);
  loop.set_override_percent(100.0);
  const std::size_t k = loop.trace.size();
  CHECK(loop.cycle().bit(C::bPlusHigh));
  REQUIRE(loop.run_to_event().event == ts::TwoSpeedEvent::kDone);
  CHECK(loop.trace[k].state == State::kMainTravel);
  CHECK(ts::images_consistent(loop.trace));
  loop.run_cycles();
  CHECK(std::abs(loop.actual() - 1000.0) <= 5.0);
}

TEST_CASE("an override change in a braking phase changes nothing", "[two_speed][override]") {
  ts::Loop plain(ts::issue_axis());
  REQUIRE(plain.start(1000.0, 2000.0) == plc::ErrorCode::kNone);
  plain.run_to_event();

  // 0 % in the high-to-low delay, 40 % in the creep phase, 100 % in the brake incidence delay.
  ts::Loop changed(ts::issue_axis());
  REQUIRE(changed.start(1000.0, 2000.0) == plc::ErrorCode::kNone);
  changed.run_to_event(20000, [](ts::Loop& l) {
    if (l.trace.empty()) return;
    switch (l.trace.back().state) {
      case State::kHighToLowDelay:
        l.set_override_percent(0.0);
        break;
      case State::kLowSpeedTravel:
        l.set_override_percent(40.0);
        break;
      case State::kBrakeIncidenceDelay:
        l.set_override_percent(100.0);
        break;
      default:
        break;
    }
  });
  CHECK(changed.trace == plain.trace);
}

TEST_CASE("an override above 100 % is refused and the last valid one stays",
          "[two_speed][override]") {
  ts::Loop loop(ts::issue_axis());
  REQUIRE(loop.sequencer.set_override(400'000) == plc::ErrorCode::kNone);
  CHECK(loop.sequencer.set_override(plc::kOverrideFull + 1) == plc::ErrorCode::kOverrideNotAllowed);
  REQUIRE(loop.start(1000.0, 2000.0) == plc::ErrorCode::kNone);
  loop.run_to_event();
  CHECK_FALSE(ever(loop.trace, C::bPlusHigh));
}
