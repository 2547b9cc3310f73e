// The two-speed positioning sample reproduces seed 004's three positioning examples with issue
// 12's parameters (rapid 500, creep 50 mm/s, creep distance 100 / 120 mm, braking distance 5 / 6
// mm, brake release 0.05 s, rapid-to-creep 0.02 s, brake incidence 0.03 / 0.04 s, stop creep 20
// mm, looping 30 mm):
//   1. 0 → 1000: T0 brake off, T1 = T0 + 0.05 s rapid on, T2 rapid off at ≥ 900, T3 = T2 +
//      0.02 s creep on, T4 creep off at ≥ 995, T5 = T4 + 0.03 s brake on; nAxisState 21 22 23 24
//      20; the end within 5 mm of 1000;
//   2. with looping 30 mm: past 1025 (the reversal point 1030 less the braking distance), back
//      with negative velocity, 21 22 23 24 23 24 20, the end above 1000 within 6 mm;
//   3. MC_Stop at 500 during rapid: rapid off at once, creep 20 mm from the stop's position, the
//      brake; no rapid after the stop, MC_MoveAbsolute CommandAborted.
// The sample writes a CSV and a timing-diagram SVG per example with T0 … marked.
#include <cmath>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "../../samples/two_speed_positioning/two_speed_positioning_program.hpp"
#include "text_file.hpp"
#include "well_formed_xml.hpp"

namespace {

using ncsdk_test::read_text;

using two_speed_positioning::Change;
using two_speed_positioning::kExamples;
using two_speed_positioning::Report;
using two_speed_positioning::TwoSpeedSample;
using C = plc::ControlByteBit;

bool on(const Change& c, C bit) {
  return plc::bit_set(c.control, bit);
}

// Whole NC cycles between two changes.
long cycles(const Change& from, const Change& to) {
  return std::lround((to.time - from.time) / 0.001);
}

}  // namespace

TEST_CASE("example 1, A → B without loop: T0 … T5 with the issue's delays and distances",
          "[two_speed][sample]") {
  TwoSpeedSample sample(kExamples[0]);
  const Report& r = sample.run();
  INFO(sample.summary());
  REQUIRE(sample.ok());
  REQUIRE(r.changes.size() == 6);
  const auto& t = r.changes;
  CHECK_FALSE(on(t[0], C::bBreak));  // T0: brake released, nothing travels
  CHECK((t[0].control & 0x0F) == 0);
  CHECK(on(t[1], C::bPlusHigh));  // T1: rapid on
  CHECK(cycles(t[0], t[1]) == 50);
  CHECK(t[2].control == plc::bit_mask(C::bBreakInv));  // T2: rapid off
  CHECK(t[2].position >= 900.0);
  CHECK(t[2].axis_state == 22U);
  CHECK(on(t[3], C::bPlusLow));  // T3: creep on
  CHECK(cycles(t[2], t[3]) == 20);
  CHECK(t[4].control == plc::bit_mask(C::bBreakInv));  // T4: creep off
  CHECK(t[4].position >= 995.0);
  CHECK(t[4].axis_state == 24U);
  CHECK(t[5].control == plc::bit_mask(C::bBreak));  // T5: brake on
  CHECK(cycles(t[4], t[5]) == 30);
  CHECK(t[5].axis_state == 20U);
  CHECK(r.sequence == std::vector<uint32_t>{0, 21, 22, 23, 24, 20});
  CHECK(std::fabs(r.final_position - 1000.0) <= 5.0);
  CHECK(r.consistent);
}

TEST_CASE("example 2, loop movement > 0: overshoot, approach 1000 from above",
          "[two_speed][sample]") {
  TwoSpeedSample sample(kExamples[1]);
  const Report& r = sample.run();
  INFO(sample.summary());
  REQUIRE(sample.ok());
  CHECK(r.highest > 1025.0);
  CHECK(r.highest < 1030.0);
  CHECK(r.sequence == std::vector<uint32_t>{0, 21, 22, 23, 24, 23, 24, 20});
  REQUIRE(r.changes.size() == 8);
  CHECK(on(r.changes[5], C::bMinusLow));            // the return leg creeps with negative velocity
  CHECK(cycles(r.changes[6], r.changes[7]) == 40);  // brake incidence delay −
  CHECK(r.final_position > 1000.0);
  CHECK(r.final_position - 1000.0 <= 6.0);
}

TEST_CASE("example 3, stop during the positioning: creep 20 mm, brake, no rapid",
          "[two_speed][sample]") {
  TwoSpeedSample sample(kExamples[2]);
  const Report& r = sample.run();
  INFO(sample.summary());
  REQUIRE(sample.ok());
  CHECK(r.stop_position >= 500.0);
  CHECK(r.stop_position < 501.0);
  CHECK_FALSE(r.rapid_after_stop);
  CHECK(r.move_aborted);
  CHECK(sample.program().Stop.Done);
  REQUIRE(r.changes.size() == 6);
  // T2 is the stop's own cycle: rapid off.
  CHECK(r.changes[2].control == plc::bit_mask(C::bBreakInv));
  CHECK(on(r.changes[3], C::bPlusLow));
  CHECK(cycles(r.changes[2], r.changes[3]) == 20);
  CHECK(r.changes[4].position >= r.stop_position + 20.0);
  CHECK(cycles(r.changes[4], r.changes[5]) == 30);
  CHECK(r.final_position < 1000.0 - 400.0);
}

TEST_CASE("the sample writes a CSV and a timing diagram per example", "[two_speed][sample]") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsdk_test_two_speed_positioning";
  std::filesystem::remove_all(dir);
  for (const auto& example : kExamples) {
    TwoSpeedSample sample(example);
    REQUIRE(sample.run().finished);
    const auto [csv, svg] = sample.write(dir);
    const std::string text = read_text(csv);
    CHECK(text.rfind("time,ActPos,SetVelo,ActVelo,nAxisState,nControlByte,nExtControlByte,"
                     "bMinusHigh,bMinusLow,bPlusLow,bPlusHigh,bBreakInv,bBreak\n",
                     0) == 0);
    const std::string plot = read_text(svg);
    CHECK(ncsdk_test::xml_problem(plot).empty());
    for (const char* id : {"panel-position", "panel-velocity", "panel-control-byte",
                           "panel-axis-state", "markers"}) {
      CHECK(plot.find(std::string("id=\"") + id + "\"") != std::string::npos);
    }
    for (const char* label : {">T0<", ">T5<", ">bPlusHigh<", ">bBreak<"})
      CHECK(plot.find(label) != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}
