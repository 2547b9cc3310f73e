// Looping distance (SPEC E2; seed 004 "OPERATION MODE: looping distance", "Positioning A → B,
// with loop movement > 0.0"): every target is approached from the same side. A positive looping
// distance passes a target reached with positive velocity by the distance (the creep distance is
// then measured to that reversal point) and comes back with negative velocity; a target reached
// with negative velocity needs no loop. A negative looping distance is the mirror.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "two_speed_loop.hpp"

using ts::Sample;
using C = plc::ControlByteBit;

namespace {

nc::AxisConfig looping_axis(double distance) {
  nc::AxisConfig c = ts::issue_axis();
  c.looping_distance_enabled = true;
  c.looping_distance = distance;
  return c;
}

struct Run {
  std::vector<Sample> trace;
  double final_position = 0.0;
  double highest = 0.0;
  double lowest = 0.0;
};

Run position(double looping, double from, double to) {
  ts::Loop loop(looping_axis(looping), from);
  REQUIRE(loop.start(to, 2000.0) == plc::ErrorCode::kNone);
  REQUIRE(loop.run_to_event().event == ts::TwoSpeedEvent::kDone);
  loop.run_cycles();
  Run r{loop.trace, loop.actual(), from, from};
  for (const Sample& s : loop.trace) {
    r.highest = std::max(r.highest, s.actual);
    r.lowest = std::min(r.lowest, s.actual);
  }
  CHECK(ts::images_consistent(r.trace));
  return r;
}

// The travel bits of the last cycle that had any: the direction of the final approach.
uint8_t last_travel(const std::vector<Sample>& trace) {
  for (auto it = trace.rbegin(); it != trace.rend(); ++it) {
    if (it->travel()) return static_cast<uint8_t>(it->image.nControlByte & 0x0F);
  }
  return 0;
}

}  // namespace

TEST_CASE("looping 30 mm: 0 to 1000 and 2000 to 1000 both end approaching from above",
          "[two_speed][looping]") {
  const Run up = position(30.0, 0.0, 1000.0);
  const Run down = position(30.0, 2000.0, 1000.0);

  // 0 → 1000 overshoots towards 1030: rapid off 100 mm before the reversal point (at 930), creep
  // off 5 mm before it, then the return leg creeps back (30 mm < creep distance 120).
  const std::size_t rapid_off =
      ts::first(up.trace, [](const Sample& s) { return s.state == ts::State::kHighToLowDelay; });
  REQUIRE(rapid_off != ts::kNotFound);
  REQUIRE(rapid_off > 0);
  CHECK(up.trace[rapid_off].actual >= 930.0);
  CHECK(up.trace[rapid_off - 1].actual < 930.0);
  CHECK(up.highest > 1030.0 - 5.0);
  CHECK(up.highest <= 1030.0);
  CHECK(ts::state_sequence(up.trace) == std::vector<uint32_t>{21, 22, 23, 24, 23, 24, 20});
  // No brake at the reversal: the brake comes on once, at the end.
  int brake_edges = 0;
  for (std::size_t k = 1; k < up.trace.size(); ++k) {
    if (up.trace[k].brake() && !up.trace[k - 1].brake()) ++brake_edges;
  }
  CHECK(brake_edges == 1);

  // 2000 → 1000 already approaches with negative velocity: one leg.
  CHECK(ts::state_sequence(down.trace) == std::vector<uint32_t>{21, 22, 23, 24, 20});
  CHECK(down.lowest > 1000.0);

  // Both final approaches are in creep, negative; both ends lie above 1000 within the negative
  // braking distance, and within one cycle of creep travel (0.05 mm) of each other.
  const auto minus_low = plc::bit_mask(C::bMinusLow);
  CHECK(last_travel(up.trace) == minus_low);
  CHECK(last_travel(down.trace) == minus_low);
  CHECK(up.final_position > 1000.0);
  CHECK(up.final_position <= 1006.0);
  CHECK(down.final_position > 1000.0);
  CHECK(down.final_position <= 1006.0);
  CHECK(std::abs(up.final_position - down.final_position) <= 0.05 + 1e-9);
}

TEST_CASE("looping -30 mm: both ends approach from below", "[two_speed][looping]") {
  const Run up = position(-30.0, 0.0, 1000.0);
  const Run down = position(-30.0, 2000.0, 1000.0);
  CHECK(ts::state_sequence(up.trace) == std::vector<uint32_t>{21, 22, 23, 24, 20});
  // 2000 → 1000 passes 1000 down to the reversal point 970 and comes back up.
  CHECK(down.lowest < 970.0 + 6.0);
  CHECK(down.lowest >= 970.0);
  CHECK(ts::state_sequence(down.trace) == std::vector<uint32_t>{21, 22, 23, 24, 23, 24, 20});
  const auto plus_low = plc::bit_mask(C::bPlusLow);
  CHECK(last_travel(up.trace) == plus_low);
  CHECK(last_travel(down.trace) == plus_low);
  CHECK(up.final_position < 1000.0);
  CHECK(up.final_position >= 995.0);
  CHECK(down.final_position < 1000.0);
  CHECK(down.final_position >= 995.0);
  CHECK(std::abs(up.final_position - down.final_position) <= 0.05 + 1e-9);
}

TEST_CASE("a looping start is refused by its distance to the target, not to the reversal point",
          "[two_speed][looping]") {
  // 2 mm to the target is inside the braking distance, although the loop leg would be 32 mm.
  ts::Loop loop(looping_axis(30.0), 998.0);
  CHECK(loop.start(1000.0, 2000.0) == plc::ErrorCode::kTwoSpeedDistanceTooShort);
  CHECK(loop.start(1005.5, 2000.0) == plc::ErrorCode::kNone);
}

TEST_CASE("a stop during the first leg of a loop ends there, without the return leg",
          "[two_speed][looping]") {
  ts::Loop loop(looping_axis(30.0));
  REQUIRE(loop.start(1000.0, 2000.0) == plc::ErrorCode::kNone);
  const Sample& end = loop.run_to_event(20000, [](ts::Loop& l) {
    if (l.trace.size() == 1000) REQUIRE(l.stop() == plc::ErrorCode::kNone);
  });
  CHECK(end.event == ts::TwoSpeedEvent::kStopped);
  CHECK(ts::first(loop.trace, [](const Sample& s) {
          return s.bit(C::bMinusLow) || s.bit(C::bMinusHigh);
        }) == ts::kNotFound);
  loop.run_cycles();
  CHECK(loop.actual() < 1000.0);
}
