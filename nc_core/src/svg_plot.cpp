#include "nc_core/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace nc {
namespace {

// Layout in px. The header line of a panel carries its title and legend; tick labels of the time
// axis sit under every panel so each panel reads on its own, as in the seed's figures.
constexpr double kMarginLeft = 84.0;
constexpr double kMarginRight = 24.0;
constexpr double kTitleHeight = 34.0;
constexpr double kTopPad = 10.0;
constexpr double kHeaderHeight = 26.0;
constexpr double kTickLabelHeight = 22.0;
constexpr double kPanelGap = 14.0;
constexpr double kAxisTitleHeight = 22.0;
constexpr int kTargetTicks = 5;
constexpr double kTickSlack = 0.02;  // of a tick step

struct Ticks {
  double lo = 0.0;
  double hi = 1.0;
  double step = 0.2;
};

// Steps of 1, 2, 2.5 or 5 times a power of ten covering [min, max] with 3 … 8 intervals: the
// tightest cover wins, then the count closest to 5 (so 0 … 2000 gets 500s, ±5000 gets 2500s).
Ticks nice_ticks(double min, double max) {
  if (!std::isfinite(min) || !std::isfinite(max)) return {};
  if (max - min <= 1e-12 * std::max(1.0, std::fabs(max))) {
    const double pad = max != 0.0 ? std::fabs(max) * 0.1 : 1.0;
    min -= pad;
    max += pad;
  }
  const double magnitude = std::pow(10.0, std::floor(std::log10((max - min) / 5.0)));
  Ticks best;
  bool found = false;
  for (const double scale : {0.1, 1.0, 10.0}) {
    for (const double factor : {1.0, 2.0, 2.5, 5.0}) {
      Ticks ticks;
      ticks.step = factor * scale * magnitude;
      // The slack (2 % of a step, under a pixel) keeps a value just past a tick — an actual
      // position that overshoots 2000 mm by 1 mm — from opening one more interval.
      ticks.lo = std::floor(min / ticks.step + kTickSlack) * ticks.step;
      ticks.hi = std::ceil(max / ticks.step - kTickSlack) * ticks.step;
      if (ticks.hi <= ticks.lo) ticks.hi = ticks.lo + ticks.step;
      const double count = std::round((ticks.hi - ticks.lo) / ticks.step);
      if (count < 3.0 || count > 8.0) continue;
      const double span = ticks.hi - ticks.lo;
      const double best_span = best.hi - best.lo;
      const double best_count = std::round(best_span / best.step);
      if (!found || span < best_span * (1.0 - 1e-9) ||
          (span <= best_span * (1.0 + 1e-9) &&
           std::fabs(count - kTargetTicks) < std::fabs(best_count - kTargetTicks))) {
        best = ticks;
        found = true;
      }
    }
  }
  return best;
}

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string coordinate(double value) {
  return format("%.2f", value);
}

// As many decimals as the step needs (0.25 s → 2), and never "-0".
std::string tick_label(double value, double step) {
  int decimals = 0;
  while (decimals < 9) {
    const double scaled = step * std::pow(10.0, decimals);
    if (std::fabs(scaled - std::round(scaled)) < 1e-6 * std::max(1.0, scaled)) break;
    ++decimals;
  }
  if (std::fabs(value) < step * 1e-6) value = 0.0;
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// "mm/s^2" reads better as "mm/s²" on a plot.
std::string display_unit(std::string_view unit) {
  std::string out;
  for (std::size_t i = 0; i < unit.size(); ++i) {
    if (unit[i] == '^' && i + 1 < unit.size() && (unit[i + 1] == '2' || unit[i + 1] == '3')) {
      out += unit[i + 1] == '2' ? "\u00b2" : "\u00b3";
      ++i;
    } else {
      out += unit[i];
    }
  }
  return out;
}

struct Frame {
  double left, top, width, height;
  Ticks x, y;
  double px(double t) const { return left + (t - x.lo) / (x.hi - x.lo) * width; }
  double py(double v) const { return top + height - (v - y.lo) / (y.hi - y.lo) * height; }
};

// The indices to draw: all of them, or per pixel column the first, lowest, highest and last
// sample (so peaks survive) when there are many more samples than pixels.
std::vector<std::size_t> decimate(std::span<const double> time, std::span<const double> values,
                                  const Frame& frame) {
  std::vector<std::size_t> keep;
  const std::size_t n = values.size();
  if (n <= static_cast<std::size_t>(4.0 * frame.width)) {
    keep.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      keep[i] = i;
    return keep;
  }
  std::size_t i = 0;
  while (i < n) {
    const double column = std::floor(frame.px(time[i]));
    std::size_t first = i, lowest = i, highest = i, last = i;
    while (i < n && std::floor(frame.px(time[i])) == column &&
           std::isfinite(values[i]) == std::isfinite(values[first])) {
      if (values[i] < values[lowest]) lowest = i;
      if (values[i] > values[highest]) highest = i;
      last = i;
      ++i;
    }
    std::size_t group[4] = {first, lowest, highest, last};
    std::sort(group, group + 4);
    for (std::size_t k = 0; k < 4; ++k) {
      if (k == 0 || group[k] != group[k - 1]) keep.push_back(group[k]);
    }
  }
  return keep;
}

// Vertical distance (px) a dropped point may lie from the line drawn instead: well under what the
// drawing resolution (the 0.01 px of the coordinates, the 1.5 px strokes) can show.
constexpr double kThinTolerance = 0.05;

// The path of one series, without points that change nothing at the drawn resolution: a point is
// dropped when the segment from the last kept point to the next kept one passes within
// kThinTolerance of it (and of every point dropped before it), so a stretch at constant velocity
// is one segment. The cone of slopes from the kept point that pass all dropped points narrows
// with every point; a point outside it ends the segment at the one before.
class PathWriter {
 public:
  explicit PathWriter(std::string& d) : d_(d) {}

  void add(double x, double y) {
    if (!pen_down_) {
      emit('M', x, y);
      pen_down_ = true;
      return;
    }
    if (has_pending_) {
      const double dx = x - anchor_x_;
      const double slope = dx > 0.0 ? (y - anchor_y_) / dx : 0.0;
      if (dx <= 0.0 || slope < lo_ || slope > hi_) {
        emit('L', pending_x_, pending_y_);
        has_pending_ = false;
      }
    }
    const double dx = x - anchor_x_;
    if (dx <= 0.0) {
      emit('L', x, y);
      return;
    }
    if (!has_pending_) {
      lo_ = -INFINITY;
      hi_ = INFINITY;
    }
    lo_ = std::max(lo_, (y - kThinTolerance - anchor_y_) / dx);
    hi_ = std::min(hi_, (y + kThinTolerance - anchor_y_) / dx);
    pending_x_ = x;
    pending_y_ = y;
    has_pending_ = true;
  }

  // The pen lifts (a gap): the run so far ends at its last point.
  void lift() {
    if (has_pending_) emit('L', pending_x_, pending_y_);
    has_pending_ = false;
    pen_down_ = false;
  }

 private:
  void emit(char command, double x, double y) {
    d_ += command;
    d_ += coordinate(x);
    d_ += ',';
    d_ += coordinate(y);
    anchor_x_ = x;
    anchor_y_ = y;
  }

  std::string& d_;
  bool pen_down_ = false;
  bool has_pending_ = false;
  double anchor_x_ = 0.0, anchor_y_ = 0.0;
  double pending_x_ = 0.0, pending_y_ = 0.0;
  double lo_ = -INFINITY, hi_ = INFINITY;
};

std::string path_data(std::span<const double> time, std::span<const double> values,
                      const Frame& frame) {
  std::string d;
  PathWriter path(d);
  for (const std::size_t i : decimate(time, values, frame)) {
    if (!std::isfinite(values[i]) || !std::isfinite(time[i])) {
      path.lift();
      continue;
    }
    path.add(frame.px(time[i]), frame.py(values[i]));
  }
  path.lift();
  return d;
}

void draw_panel(std::string& svg, std::span<const double> time, const PlotPanel& panel,
                const Frame& frame, bool last) {
  svg += "<g class=\"panel\" id=\"" + escape(panel.id) + "\">\n";
  // Header: title with unit, then the legend.
  std::string title = panel.title;
  if (!panel.unit.empty()) title += " [" + display_unit(panel.unit) + "]";
  const double header_y = frame.top - 9.0;
  svg += "<text x=\"" + coordinate(frame.left) + "\" y=\"" + coordinate(header_y) +
         "\" font-weight=\"bold\">" + escape(title) + "</text>\n";
  double legend_x = frame.left + 40.0 + 7.5 * static_cast<double>(title.size());
  for (const PlotSeries& series : panel.series) {
    svg += "<line x1=\"" + coordinate(legend_x) + "\" y1=\"" + coordinate(header_y - 4.0) +
           "\" x2=\"" + coordinate(legend_x + 22.0) + "\" y2=\"" + coordinate(header_y - 4.0) +
           "\" stroke=\"" + escape(series.colour) + "\" stroke-width=\"3\"/>\n";
    svg += "<text x=\"" + coordinate(legend_x + 28.0) + "\" y=\"" + coordinate(header_y) + "\">" +
           escape(series.label) + "</text>\n";
    legend_x += 28.0 + 7.0 * static_cast<double>(series.label.size()) + 22.0;
  }
  // Frame, grid and tick labels.
  svg += "<rect x=\"" + coordinate(frame.left) + "\" y=\"" + coordinate(frame.top) + "\" width=\"" +
         coordinate(frame.width) + "\" height=\"" + coordinate(frame.height) +
         "\" fill=\"#ffffff\" stroke=\"#404040\"/>\n";
  const auto y_count = static_cast<long>(std::lround((frame.y.hi - frame.y.lo) / frame.y.step));
  for (long k = 0; k <= y_count; ++k) {
    const double value = frame.y.lo + static_cast<double>(k) * frame.y.step;
    const double y = frame.py(value);
    const bool zero = std::fabs(value) < frame.y.step * 1e-6;
    svg += "<line x1=\"" + coordinate(frame.left) + "\" y1=\"" + coordinate(y) + "\" x2=\"" +
           coordinate(frame.left + frame.width) + "\" y2=\"" + coordinate(y) + "\" stroke=\"" +
           (zero ? "#9a9a9a" : "#e2e2e2") + "\"/>\n";
    svg += "<text x=\"" + coordinate(frame.left - 6.0) + "\" y=\"" + coordinate(y + 4.0) +
           "\" text-anchor=\"end\">" + tick_label(value, frame.y.step) + "</text>\n";
  }
  const auto x_count = static_cast<long>(std::lround((frame.x.hi - frame.x.lo) / frame.x.step));
  for (long k = 0; k <= x_count; ++k) {
    const double t = frame.x.lo + static_cast<double>(k) * frame.x.step;
    const double x = frame.px(t);
    svg += "<line x1=\"" + coordinate(x) + "\" y1=\"" + coordinate(frame.top) + "\" x2=\"" +
           coordinate(x) + "\" y2=\"" + coordinate(frame.top + frame.height) +
           "\" stroke=\"#e2e2e2\"/>\n";
    svg += "<line x1=\"" + coordinate(x) + "\" y1=\"" + coordinate(frame.top + frame.height) +
           "\" x2=\"" + coordinate(x) + "\" y2=\"" + coordinate(frame.top + frame.height + 4.0) +
           "\" stroke=\"#404040\"/>\n";
    svg += "<text x=\"" + coordinate(x) + "\" y=\"" + coordinate(frame.top + frame.height + 17.0) +
           "\" text-anchor=\"middle\">" + tick_label(t, frame.x.step) + "</text>\n";
  }
  if (last) {
    svg += "<text x=\"" + coordinate(frame.left + frame.width / 2.0) + "\" y=\"" +
           coordinate(frame.top + frame.height + kTickLabelHeight + 16.0) +
           "\" text-anchor=\"middle\">time [s]</text>\n";
  }
  // Lines: wider ones first, so a set value (dark, wide) stays visible under an actual value
  // (light, narrow) that follows it exactly.
  std::vector<const PlotSeries*> order;
  for (const PlotSeries& series : panel.series)
    order.push_back(&series);
  std::stable_sort(order.begin(), order.end(),
                   [](const PlotSeries* a, const PlotSeries* b) { return a->width > b->width; });
  for (const PlotSeries* series : order) {
    svg += "<path fill=\"none\" stroke=\"" + escape(series->colour) + "\" stroke-width=\"" +
           format("%.2g", series->width) + "\" stroke-linejoin=\"round\" d=\"" +
           path_data(time, series->values, frame) + "\"><title>" + escape(series->label) +
           "</title></path>\n";
  }
  svg += "</g>\n";
}

void range_of(std::span<const double> values, double& lo, double& hi) {
  for (const double v : values) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
}

void draw_markers(std::string& svg, std::span<const PlotMarker> markers, const Ticks& x, double top,
                  double panel_block, std::size_t panels, double plot_width, double panel_height) {
  if (markers.empty()) return;
  svg += "<g class=\"markers\" id=\"markers\">\n";
  for (std::size_t k = 0; k < markers.size(); ++k) {
    const PlotMarker& marker = markers[k];
    if (!std::isfinite(marker.time) || marker.time < x.lo || marker.time > x.hi) continue;
    const double px = kMarginLeft + (marker.time - x.lo) / (x.hi - x.lo) * plot_width;
    for (std::size_t i = 0; i < panels; ++i) {
      const double y = top + panel_block * static_cast<double>(i) + kHeaderHeight;
      svg += "<line x1=\"" + coordinate(px) + "\" y1=\"" + coordinate(y) + "\" x2=\"" +
             coordinate(px) + "\" y2=\"" + coordinate(y + panel_height) +
             "\" stroke=\"#555555\" stroke-width=\"1\" stroke-dasharray=\"4 3\"/>\n";
    }
    svg += "<text x=\"" + coordinate(px + 3.0) + "\" y=\"" +
           coordinate(top + kHeaderHeight + 12.0 + 13.0 * static_cast<double>(k % 4)) +
           "\" fill=\"#333333\">" + escape(marker.label) + "</text>\n";
  }
  svg += "</g>\n";
}

}  // namespace

std::string svg_plot(std::span<const double> time, const std::vector<PlotPanel>& panels,
                     const PlotOptions& options) {
  return svg_plot(time, panels, options, {});
}

std::string svg_plot(std::span<const double> time, const std::vector<PlotPanel>& panels,
                     const PlotOptions& options, std::span<const PlotMarker> markers) {
  if (panels.empty()) throw std::invalid_argument("svg_plot: no panel to draw");
  for (const PlotPanel& panel : panels) {
    for (const PlotSeries& series : panel.series) {
      if (series.values.size() != time.size()) {
        throw std::invalid_argument("svg_plot: series '" + series.label + "' has " +
                                    std::to_string(series.values.size()) + " values for " +
                                    std::to_string(time.size()) + " times");
      }
    }
  }
  double t_lo = INFINITY, t_hi = -INFINITY;
  range_of(time, t_lo, t_hi);
  if (t_lo > t_hi) t_lo = t_hi = 0.0;
  Ticks x_ticks = nice_ticks(t_lo, t_hi);
  if (t_lo >= 0.0 && x_ticks.lo < 0.0) x_ticks.lo = 0.0;

  const double width = std::max(320, options.width);
  const double plot_width = width - kMarginLeft - kMarginRight;
  const double panel_height = std::max(60, options.panel_height);
  const double top = kTopPad + (options.title.empty() ? 0.0 : kTitleHeight);
  const double panel_block = kHeaderHeight + panel_height + kTickLabelHeight + kPanelGap;
  const double height = top + panel_block * static_cast<double>(panels.size()) + kAxisTitleHeight;

  std::string svg;
  svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + coordinate(width) + "\" height=\"" +
         coordinate(height) + "\" viewBox=\"0 0 " + coordinate(width) + " " + coordinate(height) +
         "\" font-family=\"DejaVu Sans, Arial, sans-serif\" font-size=\"12\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"#f7f7f7\"/>\n";
  if (!options.title.empty()) {
    svg += "<text x=\"" + coordinate(kMarginLeft) + "\" y=\"" + coordinate(kTopPad + 20.0) +
           "\" font-size=\"16\" font-weight=\"bold\">" + escape(options.title) + "</text>\n";
  }
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const PlotPanel& panel = panels[i];
    double lo = INFINITY, hi = -INFINITY;
    for (const PlotSeries& series : panel.series)
      range_of(series.values, lo, hi);
    if (lo > hi) lo = hi = 0.0;
    Frame frame{kMarginLeft, top + panel_block * static_cast<double>(i) + kHeaderHeight,
                plot_width,  panel_height,
                x_ticks,     nice_ticks(lo, hi)};
    draw_panel(svg, time, panel, frame, i + 1 == panels.size());
  }
  draw_markers(svg, markers, x_ticks, top, panel_block, panels.size(), plot_width, panel_height);
  svg += "</svg>\n";
  return svg;
}

std::vector<PlotPanel> motion_panels(const Scope& scope, std::string_view axis_name) {
  struct Line {
    Signal signal;
    std::string_view label;
    std::string_view colour;
    double width;
  };
  struct Spec {
    std::string_view id;
    std::string_view title;
    std::string_view unit;
    Line lines[2];
    std::size_t count;
  };
  // Set values are drawn wide and dark, actual values narrow and light (seed 000 §2.1 colours).
  const Spec specs[] = {
      {"panel-position",
       "Position",
       "mm",
       {{Signal::kSetPos, "set position", plot_colour::kSetPosition, 3.0},
        {Signal::kActPos, "actual position", plot_colour::kActualPosition, 1.5}},
       2},
      {"panel-velocity",
       "Velocity",
       "mm/s",
       {{Signal::kSetVelo, "set velocity", plot_colour::kSetVelocity, 3.0},
        {Signal::kActVelo, "actual velocity", plot_colour::kActualVelocity, 1.5}},
       2},
      {"panel-acceleration",
       "Acceleration",
       "mm/s^2",
       {{Signal::kSetAcc, "set acceleration", plot_colour::kSetAcceleration, 3.0},
        {Signal::kActAcc, "actual acceleration", plot_colour::kActualAcceleration, 1.5}},
       2},
      {"panel-following-error",
       "Following error",
       "mm",
       {{Signal::kPosDiff, "following error", plot_colour::kFollowingError, 2.0}, {}},
       1},
  };
  std::vector<PlotPanel> panels;
  for (const Spec& spec : specs) {
    PlotPanel panel;
    panel.id = std::string(spec.id);
    panel.title = std::string(spec.title);
    panel.unit = std::string(spec.unit);
    for (std::size_t k = 0; k < spec.count; ++k) {
      const Line& line = spec.lines[k];
      const std::size_t index = scope.find(axis_name, line.signal);
      if (index == scope.channel_count()) continue;
      panel.series.push_back(PlotSeries{std::string(line.label), std::string(line.colour),
                                        scope.values(index), line.width});
    }
    if (!panel.series.empty()) panels.push_back(std::move(panel));
  }
  if (panels.empty()) {
    throw std::invalid_argument("motion_panels: the scope records no motion signal of axis '" +
                                std::string(axis_name) + "'");
  }
  return panels;
}

void write_svg(const std::filesystem::path& path, std::string_view svg) {
  const auto parent = path.parent_path();
  if (!parent.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(parent, ec);
    if (ec) {
      throw std::runtime_error("cannot create folder " + parent.string() + ": " + ec.message());
    }
  }
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot open " + path.string() + " for writing");
  out.write(svg.data(), static_cast<std::streamsize>(svg.size()));
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void write_motion_svg(const std::filesystem::path& path, const Scope& scope,
                      std::string_view axis_name, const PlotOptions& options) {
  write_svg(path, svg_plot(scope.time(), motion_panels(scope, axis_name), options));
}

}  // namespace nc
