// A scenario: a JSON timeline of PLC actions played against a kernel configured from JSON, with
// checks (SPEC H, API.md "Scenarios"; the format is docs/scenarios/README.md).
//
// Construction reads and checks both documents completely — block types, inputs and their value
// types, axes, times, check subjects — and throws InputError naming the file, the JSON pointer and
// the broken rule before anything runs, so a bad input never yields output. play() runs the PLC
// task (the timeline's actions, then every declared block in declaration order) and the NC in the
// cycle driver's simulated time; a trace task records every axis's NcToPlc (and PlcToNc.Override,
// ControlDWord, GearRatio1) and every block's outputs after the PLC task of each NC cycle. The
// checks are evaluated on that trace. Everything here is set-up / after-run code: it allocates.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "nc_core/scope.hpp"

namespace scenario {

// A bad input (exit status 2): which file, where in it (a JSON pointer, "" for the whole
// document) and the rule it breaks.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string pointer, std::string rule);
  const std::string& file() const noexcept { return file_; }
  const std::string& pointer() const noexcept { return pointer_; }
  const std::string& rule() const noexcept { return rule_; }

 private:
  std::string file_;
  std::string pointer_;
  std::string rule_;
};

struct CheckResult {
  std::string pointer;      // "/expect/3"
  std::string description;  // what it checks, e.g. "Axis.SetPos at 1 s = 1000 ± 1e-09"
  bool passed = false;
  std::string detail;  // what was seen
};

struct AxisSummary {
  std::string name;
  double start = 0.0;                // mm, SetPos of the first sample
  double end = 0.0;                  // mm, SetPos of the last sample
  double max_velocity = 0.0;         // mm/s, largest |SetVelo|
  double max_following_error = 0.0;  // mm, largest |PosDiff|
  std::vector<std::string> errors;   // "0x4550 (text) at 1.234 s", in order of appearance
};

// Reads a JSON document; InputError (pointer "") when the file cannot be read or is malformed.
nlohmann::json read_json_file(const std::filesystem::path& path);

class Scenario {
 public:
  // Set-up: `axes_file` / `timeline_file` name the documents in error messages.
  Scenario(const nlohmann::json& axes, const nlohmann::json& timeline,
           std::string axes_file = "AXES.json", std::string timeline_file = "TIMELINE.json");
  ~Scenario();
  Scenario(const Scenario&) = delete;
  Scenario& operator=(const Scenario&) = delete;

  // Plays the timeline once and evaluates the checks.
  void play();

  bool passed() const;  // every check passed (after play())
  const std::vector<CheckResult>& checks() const;
  std::vector<AxisSummary> axis_summaries() const;
  std::vector<std::string> block_errors() const;  // "mv1: Error 0x4221 (text) at 0.5 s"
  const nc::Scope& trace() const;
  const std::string& title() const;

  // The plot of an axis (the seed's four panels plus the timeline's extra panels) or of one of the
  // timeline's "plots", as SVG; `name` is an axis or plot name (see figure_names()).
  std::string svg(const std::string& name) const;
  std::vector<std::string> figure_names() const;  // axes, then plots
  std::string figure() const;  // the timeline's "figure" (default: the only axis, else the first)

  // The summary as printed, and as written to summary.json.
  std::string summary_text() const;
  nlohmann::json summary_json() const;

  // DIR/trace.csv, trace.json, summary.json, one SVG per axis and plot, and with `html`
  // DIR/scope.html. Throws std::runtime_error naming a file that cannot be written.
  void write(const std::filesystem::path& dir, bool html) const;

  struct Impl;  // the implementation's (opaque)

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace scenario
