// svg_plot's markers (used by the two-speed timing diagrams for the seed's T0 … T5): a dashed
// line through every panel per marker inside the time axis, its label (escaped) once; markers
// outside the time axis or not finite are left out; without markers the document is the one the
// three-argument call writes.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "nc_core/svg_plot.hpp"
#include "well_formed_xml.hpp"

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

}  // namespace

TEST_CASE("markers are dashed lines through every panel with their label once",
          "[svg_plot][markers]") {
  const std::vector<double> time{0.0, 0.5, 1.0};
  const std::vector<double> a{0.0, 1.0, 2.0};
  const std::vector<double> b{1.0, 0.0, 1.0};
  const std::vector<nc::PlotPanel> panels{{"panel-a", "A", "mm", {{"a", "#000000", a, 1.5}}},
                                          {"panel-b", "B", "", {{"b", "#ff0000", b, 1.5}}}};
  const nc::PlotOptions options{"title", 800, 100};
  const std::vector<nc::PlotMarker> markers{
      {0.25, "T0"}, {0.75, "T<1>"}, {5.0, "outside"}, {NAN, "nan"}};
  const std::string svg = nc::svg_plot(time, panels, options, markers);
  CHECK(ncsdk_test::xml_problem(svg).empty());
  CHECK(count(svg, "id=\"markers\"") == 1);
  CHECK(count(svg, "stroke-dasharray=\"4 3\"") == 4);  // 2 markers x 2 panels
  CHECK(count(svg, ">T0<") == 1);
  CHECK(count(svg, ">T&lt;1&gt;<") == 1);
  CHECK(svg.find("outside") == std::string::npos);
  CHECK(svg.find(">nan<") == std::string::npos);

  CHECK(nc::svg_plot(time, panels, options, {}) == nc::svg_plot(time, panels, options));
  CHECK(nc::svg_plot(time, panels, options).find("markers") == std::string::npos);
}
