// What the sample programs (samples/*/…_program.hpp) share around their PROGRAM MAIN: the size
// of the scope for a run, the lagging drive of the sample axes, running to the end and settling,
// the running maxima the scope task keeps, and the names and error line of their outputs.
// Set-up and after-run helpers (they may allocate); track_max is called from the scope task.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"

namespace sample_common {

// Records for a whole run: `timeout + settle_time` s of NC cycles plus the first and the last
// record. `Options` is a sample's options (nc_cycle, timeout, settle_time in s).
template <class Options>
std::size_t scope_capacity(const Options& options) {
  return static_cast<std::size_t>(
             std::ceil((options.timeout + options.settle_time) / options.nc_cycle)) +
         2;
}

// The drive of the sample axes: first-order lag of 1 ms plus 1 ms dead time, so the scope shows
// the following error a real drive leaves; `position_kv` in 1/s.
inline void use_lagging_drive(nc::AxisConfig& config, double position_kv) {
  config.drive_model = nc::DriveModel::kFirstOrderLag;
  config.drive_time_constant = 0.001;
  config.drive_dead_time = 0.001;
  config.position_kv = position_kv;
}

// A sample axis: default dynamics, `name`, the lagging drive with `position_kv` (1/s).
inline nc::AxisConfig lagging_axis(const char* name, double position_kv) {
  nc::AxisConfig config;
  config.name = name;
  use_lagging_drive(config, position_kv);
  return config;
}

// The figure of the multi-axis samples: one panel per `signals` entry with one series per axis
// (`names[i]` drawn in `colours[i]`, 1.5 px), read from the scope's motion signals. After-run.
struct AxisPanel {
  const char* id;
  const char* title;
  const char* unit;
  nc::Signal signal;
};
inline std::vector<nc::PlotPanel> axis_panels(const nc::Scope& scope,
                                              std::span<const char* const> names,
                                              std::span<const char* const> colours,
                                              std::span<const AxisPanel> signals) {
  std::vector<nc::PlotPanel> panels;
  for (const AxisPanel& k : signals) {
    nc::PlotPanel panel{k.id, k.title, k.unit, {}};
    for (std::size_t i = 0; i < names.size(); ++i) {
      panel.series.push_back(
          {names[i], colours[i], scope.values(scope.find(names[i], k.signal)), 1.5});
    }
    panels.push_back(std::move(panel));
  }
  return panels;
}

// Runs until `stopped()` or the timeout; when then `finished()`, runs `settle_time` s longer to
// record the drive settling. Returns whether the program finished.
template <class Stopped, class Finished>
bool run_and_settle(nc::CycleDriver& driver, Stopped&& stopped, Finished&& finished, double timeout,
                    double settle_time) {
  const bool done = driver.run_until(stopped, timeout) && finished();
  if (done) driver.run_for(settle_time);
  return done;
}

// run_and_settle for a program that ends in one of two states: stops at `finished` or `error`
// (`state` is read live), settles after `finished`.
template <class State>
bool run_to_state(nc::CycleDriver& driver, const State& state, State finished, State error,
                  double timeout, double settle_time) {
  return run_and_settle(
      driver, [&] { return state == finished || state == error; },
      [&] { return state == finished; }, timeout, settle_time);
}

// Keeps the largest |value| seen.
inline void track_max(double& max, double value) noexcept {
  max = std::max(max, std::fabs(value));
}

// <dir>/<stem>.csv and <dir>/<stem>.svg.
inline std::pair<std::filesystem::path, std::filesystem::path> csv_and_svg(
    const std::filesystem::path& dir, const std::string& stem) {
  return {dir / (stem + ".csv"), dir / (stem + ".svg")};
}

// The summary's error line: "  error: <who> 0x…, axis 0x… (state …)".
inline std::string error_line(const char* who, uint32_t error_id, uint32_t axis_error,
                              const char* state) {
  char text[160];
  std::snprintf(text, sizeof text, "  error: %s 0x%X, axis 0x%X (state %s)\n", who,
                static_cast<unsigned>(error_id), static_cast<unsigned>(axis_error), state);
  return text;
}

// Runs `sample`, writes its trace and plot into `out` and prints its summary with the two file
// names; true when the sample met its checks (`Sample`: run(), write(dir) → {csv, svg},
// summary(), ok()).
template <class Sample>
bool run_and_show(Sample& sample, const std::filesystem::path& out) {
  sample.run();
  const auto [csv, svg] = sample.write(out);
  std::fputs(sample.summary().c_str(), stdout);
  std::printf("  trace: %s\n  plot:  %s\n", csv.string().c_str(), svg.string().c_str());
  return sample.ok();
}

// One `Sample` per case (constructed from it), each run and shown; true when all met their checks.
template <class Sample, class Cases>
bool run_each(const Cases& cases, const std::filesystem::path& out) {
  bool all_ok = true;
  for (const auto& one : cases) {
    Sample sample(one);
    all_ok = run_and_show(sample, out) && all_ok;
  }
  return all_ok;
}

}  // namespace sample_common
