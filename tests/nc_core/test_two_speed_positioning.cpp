// Two-speed positioning without loop (SPEC E1, E4, E5; seed 004 "Positioning A → B, without loop
// movement") in closed loop with the simulated plant, with issue 12's numbers: brake released at
// T0, rapid on at T0 + 0.05 s, rapid off at the creep distance, creep on 0.02 s later, creep off
// at the braking distance, brake on after the brake incidence delay; nAxisState 21 → 22 → 23 → 24
// → 20 at exactly those cycles; both control bytes consistent in every cycle; the end within the
// braking distance of the target and the same, bit for bit, in a second run.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

#include "two_speed_loop.hpp"

using ts::Sample;
using ts::State;
using C = plc::ControlByteBit;

namespace {

struct Direction {
  double target;
  double creep_point;    // rapid off when the actual position passes it
  double braking_point;  // creep off when the actual position passes it
  std::size_t brake_incidence_cycles;
  C rapid;
  C creep;
  C other_rapid;
  C other_creep;
};

// 0 → +1000: creep distance 100, braking distance 5, brake incidence 0.03 s;
// 0 → -1000: creep distance 120, braking distance 6, brake incidence 0.04 s.
const Direction kPositive{1000.0,       900.0,       995.0,         30,
                          C::bPlusHigh, C::bPlusLow, C::bMinusHigh, C::bMinusLow};
const Direction kNegative{-1000.0,       -880.0,       -994.0,       40,
                          C::bMinusHigh, C::bMinusLow, C::bPlusHigh, C::bPlusLow};

bool passed(double p, double point, double target) {
  return target > 0.0 ? p >= point : p <= point;
}

std::vector<Sample> run(const Direction& d, double& final_position) {
  ts::Loop loop(ts::issue_axis());
  REQUIRE(loop.start(d.target, 2000.0) == plc::ErrorCode::kNone);
  const Sample& end = loop.run_to_event();
  REQUIRE(end.event == ts::TwoSpeedEvent::kDone);
  loop.run_cycles();
  final_position = loop.actual();
  return loop.trace;
}

void check_positioning(const Direction& d) {
  double final_position = 0.0;
  const std::vector<Sample> trace = run(d, final_position);
  CHECK(ts::images_consistent(trace));

  // T0: brake released in the start's cycle, nothing travelling yet.
  const std::size_t t0 = 0;
  CHECK_FALSE(trace[t0].brake());
  CHECK_FALSE(trace[t0].travel());
  CHECK(trace[t0].state == State::kMainTravel);

  // T1 = T0 + brake release delay 0.05 s: rapid on.
  const std::size_t rapid_on = ts::first(trace, [&](const Sample& s) { return s.bit(d.rapid); });
  REQUIRE(rapid_on != ts::kNotFound);
  CHECK(rapid_on == t0 + 50);

  // T2: rapid off in the first cycle whose actual position has passed the creep point.
  const std::size_t rapid_off = ts::first(
      trace, [&](const Sample& s) { return !s.bit(d.rapid); }, rapid_on);
  REQUIRE(rapid_off != ts::kNotFound);
  REQUIRE(rapid_off > rapid_on);
  CHECK(passed(trace[rapid_off].actual, d.creep_point, d.target));
  CHECK_FALSE(passed(trace[rapid_off - 1].actual, d.creep_point, d.target));
  CHECK(trace[rapid_off].state == State::kHighToLowDelay);

  // T3 = T2 + 0.02 s: creep on.
  const std::size_t creep_on = ts::first(trace, [&](const Sample& s) { return s.bit(d.creep); });
  REQUIRE(creep_on != ts::kNotFound);
  CHECK(creep_on == rapid_off + 20);
  CHECK(trace[creep_on - 1].state == State::kHighToLowDelay);
  CHECK(trace[creep_on].state == State::kLowSpeedTravel);

  // T4: creep off in the first cycle past the braking point.
  const std::size_t creep_off = ts::first(
      trace, [&](const Sample& s) { return !s.bit(d.creep); }, creep_on);
  REQUIRE(creep_off != ts::kNotFound);
  REQUIRE(creep_off > creep_on);
  CHECK(passed(trace[creep_off].actual, d.braking_point, d.target));
  CHECK_FALSE(passed(trace[creep_off - 1].actual, d.braking_point, d.target));
  CHECK(trace[creep_off].state == State::kBrakeIncidenceDelay);

  // T5 = T4 + brake incidence delay: brake on, positioning done, nAxisState 20.
  const std::size_t brake_on = ts::first(trace, [](const Sample& s) { return s.brake(); });
  REQUIRE(brake_on != ts::kNotFound);
  CHECK(brake_on == creep_off + d.brake_incidence_cycles);
  CHECK(trace[brake_on].state == State::kStopped);
  CHECK(trace[brake_on].event == ts::TwoSpeedEvent::kDone);
  CHECK(trace[brake_on - 1].state == State::kBrakeIncidenceDelay);

  CHECK(ts::state_sequence(trace) == std::vector<uint32_t>{21, 22, 23, 24, 20});
  // Never the other direction, never a travel bit with the brake on.
  for (const Sample& s : trace) {
    CHECK_FALSE(s.bit(d.other_rapid));
    CHECK_FALSE(s.bit(d.other_creep));
    CHECK_FALSE((s.brake() && s.travel()));
  }

  // The end lies short of the target by less than the braking distance; the plant coasts
  // 0.25 mm from the creep speed.
  const double braking = d.target > 0.0 ? 5.0 : 6.0;
  CHECK(std::abs(final_position - d.target) <= braking);
  CHECK(std::abs(final_position - d.braking_point) < 0.35);

  // A second run is the same, bit for bit.
  double again = 0.0;
  CHECK(run(d, again) == trace);
  CHECK(again == final_position);
}

}  // namespace

TEST_CASE("0 to 1000 at v 2000: brake, rapid, creep and brake at the seed's points",
          "[two_speed][positioning]") {
  check_positioning(kPositive);
}

TEST_CASE("0 to -1000 at v 2000 uses the negative-direction distances and delays",
          "[two_speed][positioning]") {
  check_positioning(kNegative);
}

TEST_CASE("nAxisState is 0 before the first start and while disabled, 20 at rest after one",
          "[two_speed][positioning]") {
  ts::Loop loop(ts::issue_axis());
  CHECK(loop.cycle().state == State::kInactive);
  CHECK(loop.cycle().brake());
  REQUIRE(loop.start(200.0, 2000.0) == plc::ErrorCode::kNone);
  REQUIRE(loop.run_to_event().event == ts::TwoSpeedEvent::kDone);
  CHECK(loop.cycle().state == State::kStopped);
  loop.sequencer.set_enabled(false);
  CHECK(loop.cycle().state == State::kInactive);
  loop.sequencer.set_enabled(true);
  CHECK(loop.cycle().state == State::kInactive);
}

TEST_CASE("a start inside the creep distance creeps at once, without rapid and its delay",
          "[two_speed][positioning]") {
  ts::Loop loop(ts::issue_axis());
  REQUIRE(loop.start(60.0, 2000.0) == plc::ErrorCode::kNone);
  REQUIRE(loop.run_to_event().event == ts::TwoSpeedEvent::kDone);
  const auto& trace = loop.trace;
  CHECK(ts::images_consistent(trace));
  CHECK(ts::first(trace, [](const Sample& s) { return s.bit(C::bPlusHigh); }) == ts::kNotFound);
  CHECK(ts::first(trace, [](const Sample& s) { return s.bit(C::bPlusLow); }) == 50);
  CHECK(ts::state_sequence(trace) == std::vector<uint32_t>{21, 23, 24, 20});
  loop.run_cycles();
  CHECK(std::abs(loop.actual() - 55.0) < 0.35);
}
