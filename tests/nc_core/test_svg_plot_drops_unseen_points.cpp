// The SVG writer drops points that change nothing at the drawn resolution (issue 15 item 4): a
// stretch at constant velocity is one segment, and every dropped sample still lies on the drawn
// line within a twentieth of a pixel (plus the 0.01 px rounding of the coordinates).
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "nc_core/svg_plot.hpp"

namespace {

using Points = std::vector<std::pair<double, double>>;

// The vertices of the first <path> of the plot.
Points path_points(const std::string& svg) {
  const std::size_t path = svg.find("<path ");
  const std::size_t begin = svg.find("d=\"", path) + 3;
  const std::size_t end = svg.find('"', begin);
  Points points;
  const char* p = svg.c_str() + begin;
  while (p < svg.c_str() + end) {
    ++p;  // M or L
    char* next = nullptr;
    const double x = std::strtod(p, &next);
    const double y = std::strtod(next + 1, &next);
    points.emplace_back(x, y);
    p = next;
  }
  return points;
}

std::string plot(const std::vector<double>& time, const std::vector<double>& values) {
  return nc::svg_plot(time, {{"panel", "Signal", "mm", {{"signal", "#00008b", values, 2.0}}}});
}

}  // namespace

TEST_CASE("a stretch at constant velocity is drawn as one segment") {
  std::vector<double> time, ramp, trapezoid;
  for (int k = 0; k <= 1000; ++k) {
    const double t = 0.001 * k;
    time.push_back(t);
    ramp.push_back(2000.0 * t);
    trapezoid.push_back(std::min({t, 0.3, 1.0 - t}));  // up, flat, down: corners on samples
  }
  CHECK(path_points(plot(time, ramp)).size() == 2);
  CHECK(path_points(plot(time, trapezoid)).size() == 4);
}

TEST_CASE("every dropped sample lies on the drawn line within 0.05 px") {
  std::vector<double> time, wave;
  for (int k = 0; k <= 3000; ++k) {
    const double t = 0.001 * k;
    time.push_back(t);
    wave.push_back(std::sin(t * 3.0 * std::numbers::pi / 2.0 / 3.0) + 0.2 * std::sin(40.0 * t));
  }
  const Points points = path_points(plot(time, wave));
  REQUIRE(points.size() >= 2);
  CHECK(points.size() < time.size() / 4);  // thinned
  // Pixel mapping from the first and last sample, which are always kept.
  const double x_scale =
      (points.back().first - points.front().first) / (time.back() - time.front());
  const double y_scale =
      (points.back().second - points.front().second) / (wave.back() - wave.front());
  std::size_t segment = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    const double x = points.front().first + (time[i] - time.front()) * x_scale;
    const double y = points.front().second + (wave[i] - wave.front()) * y_scale;
    while (segment + 2 < points.size() && points[segment + 1].first < x)
      ++segment;
    const auto [x0, y0] = points[segment];
    const auto [x1, y1] = points[segment + 1];
    const double on_line = y0 + (y1 - y0) * (x - x0) / (x1 - x0);
    worst = std::max(worst, std::fabs(y - on_line));
  }
  CHECK(worst <= 0.05 + 0.03);
}
