// The MoveAxis sample (seed 000 §4.3) reaches 2000 mm and returns to 0 mm, with the timing of
// the time-optimal profile, and writes a well-formed trace and plot.
//
// The expected times come from the planner's rule for the axis defaults A = D = 5000 mm/s²,
// J = 50000 mm/s³ and V = 2000 mm/s: the jerk phases last A/J = 0.1 s and gain A²/J = 500 mm/s
// together, so the constant-acceleration phase lasts (2000 - 500)/5000 = 0.3 s and a ramp to V
// 0.5 s, covering V·0.5/2 = 500 mm. Two ramps cover 1000 mm; the other 1000 mm take 0.5 s at V.
// A 2000 mm move therefore takes 1.5 s: 0.5 s up, 0.5 s at 2000 mm/s, 0.5 s down.
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "../../samples/move_axis/move_axis_program.hpp"
#include "text_file.hpp"
#include "well_formed_xml.hpp"

namespace {

using ncsdk_test::read_text;

constexpr double kRampTime = 0.5;   // s, 0 → 2000 mm/s
constexpr double kMoveTime = 1.5;   // s, 2000 mm
constexpr double kNcCycle = 0.001;  // s
constexpr double kTolerance = 1e-9;

struct Trace {
  std::span<const double> t, set_pos, set_velo, set_acc, pos_diff;
};

Trace trace_of(const nc::Scope& scope) {
  return {scope.time(), scope.values(scope.find("Axis1.SetPos")),
          scope.values(scope.find("Axis1.SetVelo")), scope.values(scope.find("Axis1.SetAcc")),
          scope.values(scope.find("Axis1.PosDiff"))};
}

// First sample at or after `from` where the set values rest exactly at `target`.
double set_values_end(const Trace& trace, double from, double target) {
  for (std::size_t i = 0; i < trace.t.size(); ++i) {
    if (trace.t[i] >= from - kTolerance && trace.set_pos[i] == target && trace.set_velo[i] == 0.0 &&
        trace.set_acc[i] == 0.0) {
      return trace.t[i];
    }
  }
  return -1.0;
}

// Set value at the sample nearest to time `t`.
double at(std::span<const double> time, std::span<const double> values, double t) {
  std::size_t best = 0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (std::fabs(time[i] - t) < std::fabs(time[best] - t)) best = i;
  }
  return values[best];
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string part; std::getline(in, part, separator);)
    parts.push_back(part);
  return parts;
}

}  // namespace

TEST_CASE("the MoveAxis sample reaches 2000 mm and returns to 0 mm") {
  move_axis::MoveAxisSample sample;
  const move_axis::Report& report = sample.run();
  INFO(sample.summary());

  REQUIRE(report.finished);
  CHECK_FALSE(report.block_error);
  CHECK(report.axis_error == 0);
  // The set position ends exactly on the target; the actual one within the target window.
  CHECK(report.forward_set_pos == 2000.0);
  CHECK(std::fabs(report.forward_act_pos - 2000.0) <=
        sample.kernel().config("Axis1").target_window);
  CHECK(report.final_set_pos == 0.0);
  CHECK(std::fabs(report.final_act_pos) <= sample.kernel().config("Axis1").target_window);
  CHECK(report.ok());
  CHECK(sample.program().state == move_axis::MoveState::MOVESTATE_FINISHED);
}

TEST_CASE("each MoveAxis leg takes the time-optimal 1.5 s: 0.5 s ramps around 0.5 s at 2000 mm/s") {
  move_axis::MoveAxisSample sample;
  const move_axis::Report& report = sample.run();
  INFO(sample.summary());
  REQUIRE(report.ok());
  const Trace trace = trace_of(sample.scope());

  struct Leg {
    double start, done, from, target, direction;
  };
  for (const Leg leg :
       {Leg{report.forward_start_time, report.forward_done_time, 0.0, 2000.0, 1.0},
        Leg{report.backward_start_time, report.backward_done_time, 2000.0, 0.0, -1.0}}) {
    CAPTURE(leg.start, leg.target);
    REQUIRE(leg.start >= 0.0);
    // Set-value generation ends 1.5 s after the command was accepted (the NC accepts it in the
    // tick it is posted; its first set value may belong to that cycle's end: one cycle slack).
    const double end = set_values_end(trace, leg.start, leg.target);
    REQUIRE(end > 0.0);
    CHECK(end - leg.start >= kMoveTime - kTolerance);
    CHECK(end - leg.start <= kMoveTime + kNcCycle + kTolerance);
    // Cruise at exactly V between the ramps; half-way the axis is half-way (1000 mm).
    const double cruise_from = end - kMoveTime + kRampTime + 2 * kNcCycle;
    const double cruise_to = end - kRampTime - 2 * kNcCycle;
    for (std::size_t i = 0; i < trace.t.size(); ++i) {
      if (trace.t[i] < cruise_from || trace.t[i] > cruise_to) continue;
      CHECK(std::fabs(trace.set_velo[i] - leg.direction * 2000.0) < 1e-6);
    }
    CHECK(std::fabs(at(trace.t, trace.set_pos, end - kMoveTime / 2) - 1000.0) < 1e-6);
    // Done once the actual position has stayed in the target window for its time, seen by the
    // 10 ms PLC task: after the set values ended, and not long after.
    const auto& config = sample.kernel().config("Axis1");
    CHECK(leg.done >= end - kTolerance);
    CHECK(leg.done <= end + config.target_window_time + 0.010 + 2 * kNcCycle + kTolerance);
  }
  // The way back starts within two PLC cycles of the forward Done (StartAxis low for one call).
  CHECK(report.backward_start_time - report.forward_done_time <= 0.020 + kTolerance);
}

TEST_CASE("MoveAxis set values stay within V, A and D and the following error within its limit") {
  move_axis::MoveAxisSample sample;
  const move_axis::Report& report = sample.run();
  REQUIRE(report.ok());
  const Trace trace = trace_of(sample.scope());
  const auto& config = sample.kernel().config("Axis1");
  double max_velo = 0.0, max_acc = 0.0, max_lag = 0.0;
  for (std::size_t i = 0; i < trace.t.size(); ++i) {
    max_velo = std::max(max_velo, std::fabs(trace.set_velo[i]));
    max_acc = std::max(max_acc, std::fabs(trace.set_acc[i]));
    max_lag = std::max(max_lag, std::fabs(trace.pos_diff[i]));
  }
  CHECK(max_velo == Approx(2000.0).epsilon(1e-12));
  CHECK(max_acc == Approx(5000.0).epsilon(1e-9));
  CHECK(max_lag > 0.0);  // the sample's drive lags: the plot has a following error to show
  CHECK(max_lag < config.following_error_limit);
  CHECK(report.max_following_error == max_lag);
}

TEST_CASE("the MoveAxis sample writes a CSV trace and an SVG plot that are well-formed") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsdk_test_move_axis";
  std::filesystem::remove_all(dir);
  move_axis::MoveAxisSample sample;
  REQUIRE(sample.run().ok());
  const auto [csv_path, svg_path] = sample.write(dir / "out");
  REQUIRE(std::filesystem::exists(csv_path));
  REQUIRE(std::filesystem::exists(svg_path));

  // CSV: a header of 9 columns, then one row per NC cycle, 1 ms apart, every cell a number.
  const auto lines = split(read_text(csv_path), '\n');
  REQUIRE(lines.size() == sample.scope().size() + 1);
  const auto header = split(lines[0], ',');
  REQUIRE(header.size() == 9);
  CHECK(header[0] == "time [s]");
  CHECK(header[1] == "Axis1.SetPos [mm]");
  CHECK(header[7] == "Axis1.PosDiff [mm]");
  double previous_time = -1.0;
  double max_set_pos = 0.0;
  for (std::size_t row = 1; row < lines.size(); ++row) {
    const auto cells = split(lines[row], ',');
    REQUIRE(cells.size() == header.size());
    std::vector<double> values;
    for (const auto& cell : cells) {
      std::size_t used = 0;
      values.push_back(std::stod(cell, &used));
      REQUIRE(used == cell.size());
    }
    if (row > 1) CHECK(values[0] - previous_time == Approx(kNcCycle).margin(1e-12));
    previous_time = values[0];
    max_set_pos = std::max(max_set_pos, values[1]);
  }
  CHECK(max_set_pos == 2000.0);

  // SVG: well-formed, the four panels, the seed's colours.
  const std::string svg = read_text(svg_path);
  CHECK(ncsdk_test::xml_problem(svg).empty());
  for (const char* id :
       {"panel-position", "panel-velocity", "panel-acceleration", "panel-following-error"}) {
    CHECK(svg.find(std::string("id=\"") + id + "\"") != std::string::npos);
  }
  for (const auto colour : {nc::plot_colour::kSetPosition, nc::plot_colour::kActualPosition,
                            nc::plot_colour::kSetVelocity, nc::plot_colour::kActualVelocity,
                            nc::plot_colour::kSetAcceleration, nc::plot_colour::kActualAcceleration,
                            nc::plot_colour::kFollowingError}) {
    CHECK(svg.find("stroke=\"" + std::string(colour) + "\"") != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("two MoveAxis runs give bit-identical traces") {
  move_axis::MoveAxisSample first;
  move_axis::MoveAxisSample second;
  first.run();
  second.run();
  std::ostringstream a, b;
  first.scope().write_csv(a);
  second.scope().write_csv(b);
  CHECK(a.str() == b.str());
}
