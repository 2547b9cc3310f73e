// SVG line plots of recorded motion, drawn like the seed's scope figures (seed 000 §2.1).
//
// A plot is a stack of panels over one time axis — position, velocity, acceleration, following
// error — each with its own value axis, ticks, grid, labels and legend. Plain SVG text written by
// hand (no external library), byte-for-byte deterministic for the same data. After-run functions:
// they allocate, and write_svg throws std::runtime_error when the file cannot be written.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "nc_core/scope.hpp"

namespace nc {

// The seed's colour key (seed 000 §2.1 "Notes on the figures"). Yellow is a deep yellow so it
// stays visible on the white background.
namespace plot_colour {
inline constexpr std::string_view kSetPosition = "#00008b";         // dark blue
inline constexpr std::string_view kActualPosition = "#4aa8ff";      // light blue
inline constexpr std::string_view kSetVelocity = "#006400";         // dark green
inline constexpr std::string_view kActualVelocity = "#66d95a";      // light green
inline constexpr std::string_view kSetAcceleration = "#8b0000";     // dark red
inline constexpr std::string_view kActualAcceleration = "#ff7a7a";  // light red
inline constexpr std::string_view kFollowingError = "#e6c200";      // yellow
}  // namespace plot_colour

// One line: `values[i]` belongs to the plot's `time[i]`; non-finite values leave a gap.
struct PlotSeries {
  std::string label;
  std::string colour;              // any SVG colour, e.g. "#00008b"
  std::span<const double> values;  // not owned: must outlive the svg_plot call
  double width = 1.5;              // stroke width in px
};

struct PlotPanel {
  std::string id;     // SVG id of the panel's group, e.g. "panel-position"
  std::string title;  // e.g. "Position"
  std::string unit;   // e.g. "mm" (shown as "Position [mm]")
  std::vector<PlotSeries> series;
};

// A moment to mark (e.g. the seed's T0 … T5): a dashed vertical line through every panel, its
// label at the top of the first one (on four staggered rows in the order given, so that close
// markers stay legible). Markers outside the time axis are not drawn.
struct PlotMarker {
  double time = 0.0;  // s
  std::string label;
};

struct PlotOptions {
  std::string title;       // drawn above the first panel; empty for none
  int width = 1000;        // px
  int panel_height = 180;  // px of plot area per panel
};

// The SVG document of `panels` over `time` (s). Throws std::invalid_argument when a series has a
// different length than `time`, or when there is no panel.
std::string svg_plot(std::span<const double> time, const std::vector<PlotPanel>& panels,
                     const PlotOptions& options = {});
// The same with `markers` drawn over the panels.
std::string svg_plot(std::span<const double> time, const std::vector<PlotPanel>& panels,
                     const PlotOptions& options, std::span<const PlotMarker> markers);

// The four panels of the seed's figures for one axis of a scope: position (SetPos, ActPos),
// velocity (SetVelo, ActVelo), acceleration (SetAcc, ActAcc) and following error (PosDiff), in
// the seed's colours. Signals the scope did not record are left out; a panel with none is left
// out. Throws std::invalid_argument when the axis has none of them.
std::vector<PlotPanel> motion_panels(const Scope& scope, std::string_view axis_name);

// After-run: write `svg` to `path` (creating its parent folder).
void write_svg(const std::filesystem::path& path, std::string_view svg);

// After-run: svg_plot(scope.time(), motion_panels(scope, axis_name), options) into `path`.
void write_motion_svg(const std::filesystem::path& path, const Scope& scope,
                      std::string_view axis_name, const PlotOptions& options = {});

}  // namespace nc
