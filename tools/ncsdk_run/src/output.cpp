// What a scenario leaves behind: plots, the summary and the files of DIR.
#include <algorithm>
#include <cmath>
#include <deque>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "nc_core/svg_plot.hpp"
#include "scenario_impl.hpp"
#include "scope_page.hpp"

namespace scenario {

namespace {

std::span<const double> column(const nc::Scope& scope, const std::string& name) {
  return scope.values(scope.find(name));
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace

std::vector<AxisSummary> Scenario::axis_summaries() const {
  const Impl& s = *impl_;
  std::vector<AxisSummary> out;
  for (const AxisSlot& a : s.axes) {
    AxisSummary summary;
    summary.name = a.name;
    const std::span<const double> pos = column(s.scope, a.name + ".SetPos");
    if (!pos.empty()) {
      summary.start = pos.front();
      summary.end = pos.back();
    }
    for (const double v : column(s.scope, a.name + ".SetVelo"))
      summary.max_velocity = std::max(summary.max_velocity, std::fabs(v));
    for (const double e : column(s.scope, a.name + ".PosDiff"))
      summary.max_following_error = std::max(summary.max_following_error, std::fabs(e));
    for (const auto& [code, t] : a.errors)
      summary.errors.push_back(error_text(code) + " at " + number(t) + " s");
    out.push_back(std::move(summary));
  }
  return out;
}

std::vector<std::string> Scenario::block_errors() const {
  std::vector<std::string> out;
  for (const BlockSlot& b : impl_->blocks) {
    for (const auto& [code, t] : b.errors)
      out.push_back(b.name + ": Error " + error_text(code) + " at " + number(t) + " s");
  }
  return out;
}

std::string Scenario::svg(const std::string& name) const {
  const Impl& s = *impl_;
  std::deque<std::vector<double>> owned;  // scaled copies, alive (and in place) until svg_plot
  std::vector<nc::PlotPanel> panels;
  std::string title;
  const auto axis =
      std::find_if(s.axes.begin(), s.axes.end(), [&](const AxisSlot& a) { return a.name == name; });
  if (axis != s.axes.end()) {
    panels = nc::motion_panels(s.scope, name);
    for (const std::string& field : s.extra_panels) {
      std::string column = name + ".";
      column += field;
      const std::size_t index = s.scope.find(column);
      const bool percent = field == "Override";
      std::vector<double>& values = owned.emplace_back();
      for (const double v : s.scope.values(index))
        values.push_back(percent ? v / 10'000.0 : v);
      panels.push_back({"panel-" + field,
                        field,
                        percent ? "%" : s.scope.channel(index).unit,
                        {{"PlcToNc." + field, "#6a3d9a", values, 2.0}}});
      if (field.rfind("Modulo", 0) == 0) {
        panels.back().series[0] = {field, std::string(nc::plot_colour::kSetPosition), values, 2.0};
      } else if (!percent) {
        panels.back().series[0].label = field;
      }
    }
    title = s.title.empty() ? name : (s.axes.size() == 1 ? s.title : s.title + " \u2014 " + name);
  } else {
    const auto plot = std::find_if(s.plots.begin(), s.plots.end(),
                                   [&](const PlotSpec& p) { return p.name == name; });
    if (plot == s.plots.end()) throw std::invalid_argument("no axis or plot named " + name);
    for (std::size_t k = 0; k < plot->panels.size(); ++k) {
      const PlotPanelSpec& spec = plot->panels[k];
      nc::PlotPanel panel{"panel-" + std::to_string(k + 1), spec.title, spec.unit, {}};
      for (const PlotSeriesSpec& line : spec.series) {
        std::vector<double>& values = owned.emplace_back();
        for (const double v : s.scope.values(line.column))
          values.push_back(v * line.scale);
        panel.series.push_back({line.label, line.colour, values, line.width});
      }
      panels.push_back(std::move(panel));
    }
    title = plot->title.empty() ? s.title : plot->title;
  }
  return nc::svg_plot(s.scope.time(), panels, {title, 1000, 150});
}

std::string Scenario::summary_text() const {
  const Impl& s = *impl_;
  std::ostringstream out;
  if (!s.title.empty()) out << s.title << "\n";
  const std::span<const double> time = s.scope.time();
  out << "run: " << number(time.empty() ? 0.0 : time.back()) << " s, " << time.size()
      << " samples, NC cycle " << number(s.cycle_time()) << " s, PLC task " << number(s.plc_period)
      << " s\n";
  for (const AxisSummary& a : axis_summaries()) {
    out << "axis " << a.name << ": start " << number(a.start) << " mm, end " << number(a.end)
        << " mm, max |SetVelo| " << number(a.max_velocity) << " mm/s, max |PosDiff| "
        << number(a.max_following_error) << " mm, errors: ";
    if (a.errors.empty()) out << "none";
    for (std::size_t i = 0; i < a.errors.size(); ++i)
      out << (i > 0 ? "; " : "") << a.errors[i];
    out << "\n";
  }
  for (const std::string& e : block_errors())
    out << "block " << e << "\n";
  std::size_t failed = 0;
  for (const CheckResult& c : s.results) {
    failed += c.passed ? 0 : 1;
    out << (c.passed ? "PASS " : "FAIL ") << c.pointer << " " << c.description << " (" << c.detail
        << ")\n";
  }
  out << "checks: " << s.results.size() - failed << " passed, " << failed << " failed\n";
  return out.str();
}

nlohmann::json Scenario::summary_json() const {
  const Impl& s = *impl_;
  nlohmann::json j;
  j["title"] = s.title;
  j["cycle_time"] = s.cycle_time();
  j["plc_period"] = s.plc_period;
  j["samples"] = s.scope.size();
  j["end_time"] = s.scope.size() > 0 ? s.scope.time().back() : 0.0;
  j["axes"] = nlohmann::json::array();
  for (const AxisSummary& a : axis_summaries()) {
    j["axes"].push_back({{"name", a.name},
                         {"start", a.start},
                         {"end", a.end},
                         {"max_velocity", a.max_velocity},
                         {"max_following_error", a.max_following_error},
                         {"errors", a.errors}});
  }
  j["block_errors"] = block_errors();
  j["checks"] = nlohmann::json::array();
  for (const CheckResult& c : s.results) {
    j["checks"].push_back({{"pointer", c.pointer},
                           {"description", c.description},
                           {"passed", c.passed},
                           {"detail", c.detail}});
  }
  j["passed"] = passed();
  return j;
}

void Scenario::write(const std::filesystem::path& dir, bool html) const {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::runtime_error("cannot create " + dir.string() + ": " + ec.message());
  const Impl& s = *impl_;
  s.scope.write_csv(dir / "trace.csv");
  s.scope.write_json(dir / "trace.json");
  for (const std::string& name : figure_names())
    nc::write_svg(dir / (name + ".svg"), svg(name));
  if (html) write_text(dir / "scope.html", scope_page(s.scope, s.title));
  write_text(dir / "summary.json", summary_json().dump(2) + "\n");
}

}  // namespace scenario
