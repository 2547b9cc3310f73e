// The SVG plot of a recording: the seed's four panels in the seed's colours, axes with ticks and
// labels, well-formed XML (seed 000 §2.1 "Notes on the figures").
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"
#include "plc_interface/axis_ref.hpp"
#include "well_formed_xml.hpp"

namespace {

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

// A ramp 0 → 2000 mm over 1 s sampled at 1 ms: enough to give every panel a range.
nc::Scope ramp_recording(plc::AXIS_REF& axis) {
  nc::Scope scope(1001);
  scope.add_motion_signals(axis, "Axis1");
  for (int k = 0; k <= 1000; ++k) {
    const double t = 0.001 * k;
    axis.NcToPlc.SetPos = 2000.0 * t;
    axis.NcToPlc.ActPos = 2000.0 * t - 0.4;
    axis.NcToPlc.SetVelo = 2000.0;
    axis.NcToPlc.ActVelo = 1990.0;
    axis.NcToPlc.SetAcc = 5000.0 * std::sin(6.0 * t);
    axis.NcToPlc.ActAcc = 4900.0 * std::sin(6.0 * t);
    axis.NcToPlc.PosDiff = 0.4;
    scope.record(t);
  }
  return scope;
}

}  // namespace

TEST_CASE("the motion plot has position, velocity, acceleration and following-error panels") {
  plc::AXIS_REF axis;
  const nc::Scope scope = ramp_recording(axis);
  const std::string svg =
      nc::svg_plot(scope.time(), nc::motion_panels(scope, "Axis1"), {"MoveAxis", 1000, 180});

  CHECK(ncsdk_test::xml_problem(svg).empty());
  CHECK(count_of(svg, "class=\"panel\"") == 4);
  CHECK(count_of(svg, "id=\"panel-position\"") == 1);
  CHECK(count_of(svg, "id=\"panel-velocity\"") == 1);
  CHECK(count_of(svg, "id=\"panel-acceleration\"") == 1);
  CHECK(count_of(svg, "id=\"panel-following-error\"") == 1);
  CHECK(svg.find("Position [mm]") != std::string::npos);
  CHECK(svg.find("Acceleration [mm/s\u00b2]") != std::string::npos);
  CHECK(svg.find("time [s]") != std::string::npos);
  CHECK(svg.find(">MoveAxis<") != std::string::npos);
  // 7 lines, each with its legend entry.
  CHECK(count_of(svg, "<path ") == 7);
  for (const char* label : {"set position", "actual position", "set velocity", "actual velocity",
                            "set acceleration", "actual acceleration", "following error"}) {
    CHECK(count_of(svg, std::string(">") + label + "<") == 2);  // legend text + line title
  }
}

TEST_CASE("the motion plot uses the seed's colours for each signal") {
  plc::AXIS_REF axis;
  const nc::Scope scope = ramp_recording(axis);
  const std::string svg = nc::svg_plot(scope.time(), nc::motion_panels(scope, "Axis1"));
  // Legend swatch and line for each of the seven signals.
  for (const auto colour : {nc::plot_colour::kSetPosition, nc::plot_colour::kActualPosition,
                            nc::plot_colour::kSetVelocity, nc::plot_colour::kActualVelocity,
                            nc::plot_colour::kSetAcceleration, nc::plot_colour::kActualAcceleration,
                            nc::plot_colour::kFollowingError}) {
    CHECK(count_of(svg, "stroke=\"" + std::string(colour) + "\"") == 2);
  }
  CHECK(nc::plot_colour::kSetPosition == "#00008b");      // dark blue
  CHECK(nc::plot_colour::kSetVelocity == "#006400");      // dark green
  CHECK(nc::plot_colour::kSetAcceleration == "#8b0000");  // dark red
}

TEST_CASE("plot axes carry 1-2-5 ticks that cover the data") {
  plc::AXIS_REF axis;
  const nc::Scope scope = ramp_recording(axis);
  const std::string svg = nc::svg_plot(scope.time(), nc::motion_panels(scope, "Axis1"));
  // Position 0 … 2000 mm in steps of 500 (or finer); time 0 … 1 s in steps of 0.2 s.
  CHECK(svg.find(">2000</text>") != std::string::npos);
  CHECK(svg.find(">500</text>") != std::string::npos);
  CHECK(svg.find(">0.2</text>") != std::string::npos);
  CHECK(svg.find(">1.0</text>") != std::string::npos);
  CHECK(svg.find(">-5000</text>") != std::string::npos);  // acceleration: ±5000 in 2500s
  CHECK(svg.find(">2500</text>") != std::string::npos);
  CHECK(svg.find("-0<") == std::string::npos);
}

TEST_CASE("a constant signal still gets a readable value axis") {
  const std::vector<double> time = {0.0, 0.5, 1.0};
  const std::vector<double> zero = {0.0, 0.0, 0.0};
  const std::string svg = nc::svg_plot(
      time, {nc::PlotPanel{"panel-lag", "Lag", "mm", {{"lag", "#e6c200", zero, 2.0}}}});
  CHECK(ncsdk_test::xml_problem(svg).empty());
  CHECK(svg.find("nan") == std::string::npos);
  CHECK(svg.find("inf") == std::string::npos);
  CHECK(svg.find(">1.0</text>") != std::string::npos);
  CHECK(svg.find(">-1.0</text>") != std::string::npos);
}

TEST_CASE("non-finite samples leave a gap in the line instead of breaking the plot") {
  const std::vector<double> time = {0.0, 1.0, 2.0, 3.0};
  const std::vector<double> values = {0.0, NAN, 2.0, 3.0};
  const std::string svg =
      nc::svg_plot(time, {nc::PlotPanel{"panel-x", "X", "mm", {{"x", "#000000", values, 1.0}}}});
  CHECK(ncsdk_test::xml_problem(svg).empty());
  CHECK(svg.find("nan") == std::string::npos);
  CHECK(count_of(svg, "d=\"M") == 1);
  CHECK(count_of(svg, "M") >= 2);  // the pen is lifted at the NaN
}

TEST_CASE("long recordings are thinned per pixel column but keep their peaks") {
  std::vector<double> time(200'000);
  std::vector<double> values(200'000, 0.0);
  for (std::size_t i = 0; i < time.size(); ++i)
    time[i] = 1e-5 * static_cast<double>(i);
  values[123'457] = 100.0;  // a one-sample spike
  const std::string svg = nc::svg_plot(
      time, {nc::PlotPanel{"panel-x", "X", "mm", {{"x", "#000000", values, 1.0}}}}, {"", 800, 120});
  CHECK(svg.size() < 200'000);
  // The spike is the top of the value axis (100 mm): a point of the line lies on the frame's top.
  CHECK(svg.find(">100</text>") != std::string::npos);
  const auto frame = svg.find("fill=\"#ffffff\"");
  REQUIRE(frame != std::string::npos);
  const auto y_at = svg.rfind(" y=\"", frame) + 4;
  const std::string frame_top = svg.substr(y_at, svg.find('"', y_at) - y_at);
  const auto path = svg.find("<path ");
  REQUIRE(path != std::string::npos);
  const std::string d = svg.substr(path, svg.find("</path>", path) - path);
  CHECK(d.find("," + frame_top) != std::string::npos);
}

TEST_CASE("a plot refuses series whose length differs from the time axis") {
  const std::vector<double> time = {0.0, 1.0};
  const std::vector<double> values = {0.0};
  CHECK_THROWS_AS(
      nc::svg_plot(time, {nc::PlotPanel{"p", "P", "", {{"v", "#000000", values, 1.0}}}}),
      std::invalid_argument);
  CHECK_THROWS_AS(nc::svg_plot(time, {}), std::invalid_argument);
  plc::AXIS_REF axis;
  nc::Scope scope(2);
  scope.add_signal(axis, "A", nc::Signal::kStateDWord);
  CHECK_THROWS_AS(nc::motion_panels(scope, "A"), std::invalid_argument);
}
