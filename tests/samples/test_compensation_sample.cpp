// The compensation sample reproduces the seed's three figures (seed 000 §2.5): on a 0 → 10000 mm
// positioning at V 2000 mm/s, MC_MoveSuperImposed started at constant velocity with AK+ 500,
// AK- 1000 mm/s² and VP 2000 mm/s
//   L 5000, D  250, VK 300 → end 10250 mm;
//   L 2000, D  500, VK 500 → T = L/VP = 1 s only fits a triangle with 1 s = v/500 + v/1000,
//                            v = 333.33 mm/s, D = v · T / 2 = 500/3 mm → end 10166.67 mm and
//                            the warning 0x4243 (the seed reads "10165.0" off its plot);
//   L 5000, D -250, VK 300 → end 9750 mm.
// The compensation lasts T = L / VP: 2.5 s, 1 s, 2.5 s — always the whole T (seed 000 §2.5
// "compensation occurs over the whole compensation length"), so a feasible D is done with the
// peak extra velocity v that spreads it over T: D = v·T - v²·c/2, c = 1/AK+ + 1/AK- = 0.003
// s²/mm, v = (T - sqrt(T² - 2·c·|D|)) / c = 106.85 mm/s for |D| = 250 (below VK = 300).
#include <cmath>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "../../samples/compensation/compensation_program.hpp"
#include "text_file.hpp"
#include "well_formed_xml.hpp"

namespace {

using ncsdk_test::read_text;

using compensation::CompensationSample;
using compensation::Figure;
using compensation::kFigures;

struct Expected {
  double end;            // mm
  double distance;       // ActualDistance, mm
  double velocity_diff;  // ActualVelocityDiff, mm/s (signed as D)
  double duration;       // s, T = L / VP
  bool warning;
};

// Peak extra velocity that spreads |D| over T with the slopes AK+ 500 and AK- 1000 mm/s².
double spread_peak(double distance, double duration) {
  const double c = 1.0 / 500.0 + 1.0 / 1000.0;
  return (duration - std::sqrt(duration * duration - 2.0 * c * distance)) / c;
}

Expected expected(const Figure& f) {
  if (f.distance < 0.0) return {9750.0, -250.0, -spread_peak(250.0, 2.5), 2.5, false};
  if (f.length == 2000.0) return {10000.0 + 500.0 / 3.0, 500.0 / 3.0, 1000.0 / 3.0, 1.0, true};
  return {10250.0, 250.0, spread_peak(250.0, 2.5), 2.5, false};
}

}  // namespace

TEST_CASE("each seed figure ends at the seed's end position") {
  for (const Figure& figure : kFigures) {
    CompensationSample sample(figure);
    const compensation::Report& report = sample.run();
    INFO(sample.summary());
    const Expected e = expected(figure);
    REQUIRE(report.finished);
    CHECK(report.error_id == 0);
    CHECK(report.axis_error == 0);
    CHECK(report.final_set_pos == Approx(e.end).margin(1e-9));
    CHECK(std::fabs(report.final_act_pos - e.end) <= sample.kernel().config("Axis1").target_window);
    CHECK(sample.ok());
  }
}

TEST_CASE(
    "MC_MoveSuperImposed reports D done, L and the peak extra velocity; the warning only "
    "where D was not feasible") {
  CHECK(spread_peak(250.0, 2.5) == Approx(106.8501).margin(1e-4));
  for (const Figure& figure : kFigures) {
    CompensationSample sample(figure);
    const compensation::Report& report = sample.run();
    INFO(sample.summary());
    const Expected e = expected(figure);
    REQUIRE(report.compensation_done);
    CHECK(report.actual_distance == Approx(e.distance).margin(1e-9));
    CHECK(report.actual_length == figure.length);
    CHECK(report.actual_velocity_diff == Approx(e.velocity_diff).margin(1e-9));
    CHECK(report.warning == e.warning);
    CHECK(report.warning_id == (e.warning ? 0x4243U : 0U));
  }
}

TEST_CASE("the compensation starts at constant velocity and lasts T = L / VP") {
  for (const Figure& figure : kFigures) {
    CompensationSample sample(figure);
    const compensation::Report& report = sample.run();
    INFO(sample.summary());
    const Expected e = expected(figure);
    // The ramp to 2000 mm/s takes 0.5 s and covers 500 mm (A 5000 mm/s², J 50000 mm/s³).
    CHECK(report.compensation_start_time == Approx(0.5).margin(0.005));
    CHECK(report.compensation_start_pos == Approx(500.0).margin(10.0));
    const double took = report.compensation_done_time - report.compensation_start_time;
    CHECK(took >= e.duration);
    CHECK(took <= e.duration + 0.003);  // posted, taken, then seen by the PLC: a few cycles
    // The basic move ends after the compensation (it lengthens or shortens nothing in time).
    CHECK(report.move_done_time > report.compensation_done_time);
    // The peak is sampled on the 1 ms grid: within one cycle of the slope AK+ below it.
    CHECK(report.max_set_velocity <= 2000.0 + std::fmax(e.velocity_diff, 0.0) + 1e-9);
    CHECK(report.max_set_velocity >= 2000.0 + std::fmax(e.velocity_diff, 0.0) - 0.5);
  }
}

TEST_CASE("the compensation distance published by the NC grows to D over the compensation") {
  const Figure& figure = kFigures[0];
  CompensationSample sample(figure);
  REQUIRE(sample.run().compensation_done);
  const nc::Scope& s = sample.scope();
  const auto comp = s.values(s.find("Axis1", nc::Signal::kCompensationDistance));
  const auto t = s.time();
  double before = 0.0;
  for (std::size_t i = 1; i < comp.size(); ++i) {
    CAPTURE(t[i]);
    REQUIRE(comp[i] >= before - 1e-12);  // D > 0: it only grows
    before = comp[i];
  }
  CHECK(comp.back() == Approx(250.0).margin(1e-9));
}

TEST_CASE("the sample writes one CSV and one well-formed SVG per figure") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsdk_test_compensation";
  std::filesystem::remove_all(dir);
  for (const Figure& figure : kFigures) {
    CompensationSample sample(figure);
    REQUIRE(sample.run().finished);
    const auto [csv, svg] = sample.write(dir);
    CHECK(csv.filename() == std::string(figure.name) + ".csv");
    const std::string text = read_text(csv);
    CHECK(text.find("Axis1.CompensationDistance [mm]") != std::string::npos);
    const std::string plot = read_text(svg);
    CHECK(ncsdk_test::xml_problem(plot).empty());
    CHECK(plot.find("id=\"panel-compensation\"") != std::string::npos);
    CHECK(plot.find(figure.title) != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}
