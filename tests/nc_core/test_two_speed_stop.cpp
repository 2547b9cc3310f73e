// Stop on a two-speed axis (SPEC E2; seed 004 "Creep distance for stop", "Stop call up in case of
// active positioning"): the axis creeps for the creep distance for stop, counted from where the
// stop is called, then runs the brake sequence; rapid is never switched on again. Issue 12's
// numbers: stop at 500 during rapid → rapid off, creep on after 0.02 s, creep off at 520, brake
// on 0.03 s later.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "two_speed_loop.hpp"

using ts::Sample;
using ts::State;
using C = plc::ControlByteBit;

namespace {

// Starts to `target` at `velocity` and calls stop in the first cycle whose actual position has
// passed `stop_at` (in the direction of travel); returns that cycle's index.
std::size_t run_with_stop(ts::Loop& loop, double target, double velocity, double stop_at) {
  REQUIRE(loop.start(target, velocity) == plc::ErrorCode::kNone);
  const double direction = target > loop.actual() ? 1.0 : -1.0;
  std::size_t stop_cycle = ts::kNotFound;
  const Sample& end = loop.run_to_event(20000, [&](ts::Loop& l) {
    if (stop_cycle == ts::kNotFound && (l.actual() - stop_at) * direction >= 0.0) {
      stop_cycle = l.trace.size();
      REQUIRE(l.stop() == plc::ErrorCode::kNone);
    }
  });
  REQUIRE(stop_cycle != ts::kNotFound);
  CHECK(end.event == ts::TwoSpeedEvent::kStopped);
  CHECK(ts::images_consistent(loop.trace));
  return stop_cycle;
}

}  // namespace

TEST_CASE("stop at 500 during rapid: creep 20 mm from there, then brake, no rapid after it",
          "[two_speed][stop]") {
  ts::Loop loop(ts::issue_axis());
  const std::size_t k = run_with_stop(loop, 1000.0, 2000.0, 500.0);
  const auto& trace = loop.trace;
  const double stop_position = trace[k].actual;
  REQUIRE(stop_position >= 500.0);
  CHECK(trace[k - 1].bit(C::bPlusHigh));
  for (std::size_t i = k; i < trace.size(); ++i) {
    CHECK_FALSE(trace[i].bit(C::bPlusHigh));
  }
  CHECK(trace[k].state == State::kHighToLowDelay);
  const std::size_t creep_on = ts::first(trace, [](const Sample& s) { return s.bit(C::bPlusLow); });
  REQUIRE(creep_on != ts::kNotFound);
  CHECK(creep_on == k + 20);
  const std::size_t creep_off = ts::first(
      trace, [](const Sample& s) { return !s.bit(C::bPlusLow); }, creep_on);
  REQUIRE(creep_off != ts::kNotFound);
  CHECK(trace[creep_off].actual >= stop_position + 20.0);
  CHECK(trace[creep_off - 1].actual < stop_position + 20.0);
  CHECK(trace[creep_off].state == State::kBrakeIncidenceDelay);
  const std::size_t brake_on = ts::first(trace, [](const Sample& s) { return s.brake(); });
  REQUIRE(brake_on != ts::kNotFound);
  CHECK(brake_on == creep_off + 30);
  CHECK(trace[brake_on].state == State::kStopped);
  CHECK(ts::state_sequence(trace) == std::vector<uint32_t>{21, 22, 23, 24, 20});
  loop.run_cycles();
  // The plant was still running down from rapid when the creep went off (220 mm/s): it runs
  // down at 500 mm/s / 0.1 s for the 0.03 s of brake incidence delay (to 70 mm/s), then the brake
  // stops it within 0.05 mm: the end lies short of the free run-down v² / 2a (4.84 mm).
  const double v_off = trace[creep_off - 1].velocity;
  CHECK(v_off == Approx(220.0));
  CHECK(loop.actual() > trace[creep_off].actual + 4.3);
  CHECK(loop.actual() < trace[creep_off].actual + v_off * v_off / (2.0 * 5000.0));
}

TEST_CASE("stop during creep main travel keeps creeping for the stop distance",
          "[two_speed][stop]") {
  ts::Loop loop(ts::issue_axis());
  const std::size_t k = run_with_stop(loop, 1000.0, 40.0, 500.0);
  const auto& trace = loop.trace;
  const double stop_position = trace[k].actual;
  CHECK(trace[k].state == State::kLowSpeedTravel);
  CHECK(trace[k].bit(C::bPlusLow));
  CHECK(ts::state_sequence(trace) == std::vector<uint32_t>{21, 23, 24, 20});
  const std::size_t creep_off = ts::first(
      trace, [](const Sample& s) { return !s.bit(C::bPlusLow); }, k);
  REQUIRE(creep_off != ts::kNotFound);
  CHECK(trace[creep_off].actual >= stop_position + 20.0);
  CHECK(trace[creep_off - 1].actual < stop_position + 20.0);
}

TEST_CASE("stop in the negative direction uses the negative brake incidence delay",
          "[two_speed][stop]") {
  ts::Loop loop(ts::issue_axis());
  const std::size_t k = run_with_stop(loop, -1000.0, 2000.0, -500.0);
  const auto& trace = loop.trace;
  const double stop_position = trace[k].actual;
  const std::size_t creep_on =
      ts::first(trace, [](const Sample& s) { return s.bit(C::bMinusLow); });
  REQUIRE(creep_on != ts::kNotFound);
  CHECK(creep_on == k + 20);
  const std::size_t creep_off = ts::first(
      trace, [](const Sample& s) { return !s.bit(C::bMinusLow); }, creep_on);
  REQUIRE(creep_off != ts::kNotFound);
  CHECK(trace[creep_off].actual <= stop_position - 20.0);
  const std::size_t brake_on = ts::first(trace, [](const Sample& s) { return s.brake(); });
  REQUIRE(brake_on != ts::kNotFound);
  CHECK(brake_on == creep_off + 40);
}

TEST_CASE("a stop near the target creeps off at the braking point when that comes first",
          "[two_speed][stop]") {
  ts::Loop loop(ts::issue_axis());
  run_with_stop(loop, 1000.0, 2000.0, 990.0);  // in the creep phase; 990 + 20 is beyond 995
  const auto& trace = loop.trace;
  const std::size_t creep_off =
      ts::first(trace, [](const Sample& s) { return s.state == State::kBrakeIncidenceDelay; });
  REQUIRE(creep_off != ts::kNotFound);
  CHECK(trace[creep_off].actual >= 995.0);
  CHECK(trace[creep_off - 1].actual < 995.0);
  CHECK(ts::state_sequence(trace) == std::vector<uint32_t>{21, 22, 23, 24, 20});
}

TEST_CASE("a stop in the brake incidence delay lets it run out", "[two_speed][stop]") {
  ts::Loop plain(ts::issue_axis());
  REQUIRE(plain.start(1000.0, 2000.0) == plc::ErrorCode::kNone);
  plain.run_to_event();
  ts::Loop stopped(ts::issue_axis());
  const std::size_t k = run_with_stop(stopped, 1000.0, 2000.0, 995.0);
  CHECK(stopped.trace[k].state == State::kBrakeIncidenceDelay);
  // Same cycles, same image; only the event says stopped instead of done.
  REQUIRE(plain.trace.size() == stopped.trace.size());
  CHECK(plain.trace.back().event == ts::TwoSpeedEvent::kDone);
  stopped.trace.back().event = ts::TwoSpeedEvent::kDone;
  CHECK(plain.trace == stopped.trace);
}

TEST_CASE("a stop during the brake release delay brakes at once", "[two_speed][stop]") {
  ts::Loop loop(ts::issue_axis());
  REQUIRE(loop.start(1000.0, 2000.0) == plc::ErrorCode::kNone);
  for (int i = 0; i < 10; ++i)
    REQUIRE_FALSE(loop.cycle().brake());
  REQUIRE(loop.stop() == plc::ErrorCode::kNone);
  const Sample& s = loop.cycle();
  CHECK(s.event == ts::TwoSpeedEvent::kStopped);
  CHECK(s.brake());
  CHECK_FALSE(s.travel());
  CHECK(s.state == State::kStopped);
  loop.run_cycles();
  CHECK(loop.actual() == 0.0);
}

TEST_CASE("a stop at rest completes in the next cycle and moves nothing", "[two_speed][stop]") {
  ts::Loop loop(ts::issue_axis());
  loop.cycle();
  REQUIRE(loop.stop() == plc::ErrorCode::kNone);
  const Sample& s = loop.cycle();
  CHECK(s.event == ts::TwoSpeedEvent::kStopped);
  CHECK(s.state == State::kInactive);  // no start yet
  CHECK(s.brake());
  CHECK(loop.cycle().event == ts::TwoSpeedEvent::kNone);
}

TEST_CASE("a stop while the override holds the axis stationary brakes without creeping",
          "[two_speed][stop]") {
  ts::Loop loop(ts::issue_axis());
  REQUIRE(loop.start(1000.0, 2000.0) == plc::ErrorCode::kNone);
  loop.run_cycles(400);
  loop.set_override_percent(0.0);
  loop.run_cycles(400);
  REQUIRE(loop.trace.back().state == State::kMainTravel);
  REQUIRE_FALSE(loop.trace.back().travel());
  const std::size_t k = loop.trace.size();
  REQUIRE(loop.stop() == plc::ErrorCode::kNone);
  const Sample& end = loop.run_to_event();
  CHECK(end.event == ts::TwoSpeedEvent::kStopped);
  CHECK(loop.trace[k].state == State::kBrakeIncidenceDelay);
  CHECK(loop.trace.size() - k == 31);  // 0.03 s of brake incidence delay, then brake on
  for (std::size_t i = k; i < loop.trace.size(); ++i)
    CHECK_FALSE(loop.trace[i].travel());
}

TEST_CASE("a creep distance for stop of 0 switches the creep off at once", "[two_speed][stop]") {
  nc::AxisConfig c = ts::issue_axis();
  c.creep_distance_stop = 0.0;
  ts::Loop loop(c);
  const std::size_t k = run_with_stop(loop, 1000.0, 40.0, 300.0);
  CHECK(loop.trace[k].state == State::kBrakeIncidenceDelay);
  CHECK_FALSE(loop.trace[k].travel());
}
