// The seed's three position-compensation figures (seed 000 §2.5) reproduced with PLC blocks.
//
// The basic positioning is an MC_MoveAbsolute from 0 to 10000 mm at V 2000 mm/s (axis dynamics
// A 5000 mm/s², J 50000 mm/s³). Once the axis runs at constant velocity (StateDWord bit 12), the
// program starts an MC_MoveSuperImposed with the figure's parameters — AK+ 500 mm/s², AK- 1000
// mm/s², VP 2000 mm/s and
//   full:     L 5000 mm, D  250 mm, VK 300 mm/s → end position 10250 mm;
//   partial:  L 2000 mm, D  500 mm, VK 500 mm/s → D is not feasible within T = L/VP = 1 s: the
//             largest feasible D is a triangle peaking at 1 s / (1/500 + 1/1000) s²/mm = 333.3
//             mm/s, i.e. D = 333.3 · 1 / 2 = 500/3 mm, end position 10166.67 mm (the seed reads
//             "10165.0" off its plot), with the warning 0x4243;
//   negative: L 5000 mm, D -250 mm, VK 300 mm/s → end position 9750 mm.
// The program then waits for the basic move's Done.
//
// CompensationSample runs one figure on a simulated axis (1 ms NC cycle, 1 ms PLC task, a scope
// every NC cycle). Header-only, so that tests/samples/test_compensation_sample.cpp runs exactly
// what the sample program runs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "fb/mc_move_absolute.hpp"
#include "fb/mc_move_superimposed.hpp"
#include "fb/mc_power.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"
#include "plc_interface/axis_ref.hpp"
#include "sample_output.hpp"

namespace compensation {

// One of the seed's figures: the compensation's start parameters and the end position it shows.
struct Figure {
  const char* name;      // file stem and title
  const char* title;     // the seed's caption
  double length;         // L, mm
  double distance;       // D, mm
  double velocity_diff;  // VK, mm/s
  double expected_end;   // mm
  bool expect_warning;   // the largest feasible D replaces D (0x4243)
};

inline constexpr double kStart = 0.0;                 // mm
inline constexpr double kTarget = 10000.0;            // mm
inline constexpr double kVelocity = 2000.0;           // mm/s, V of the basic positioning
inline constexpr double kAccelerationPlus = 500.0;    // AK+, mm/s²
inline constexpr double kAccelerationMinus = 1000.0;  // AK-, mm/s²
inline constexpr double kProcessVelocity = 2000.0;    // VP, mm/s

inline constexpr Figure kFigures[] = {
    {"compensation_full", "Full compensation", 5000.0, 250.0, 300.0, 10250.0, false},
    {"compensation_partial", "Partial compensation", 2000.0, 500.0, 500.0, 10000.0 + 500.0 / 3.0,
     true},
    {"compensation_negative", "Full negative compensation", 5000.0, -250.0, 300.0, 9750.0, false},
};

enum class CompState {
  STATE_INIT,        // wait for MC_Power's Status
  STATE_MOVE,        // MC_MoveAbsolute running, wait for constant velocity
  STATE_COMPENSATE,  // MC_MoveSuperImposed started, wait for the basic move's Done
  STATE_FINISHED,
  STATE_ERROR,
};

inline const char* state_name(CompState state) noexcept {
  switch (state) {
    case CompState::STATE_INIT:
      return "STATE_INIT";
    case CompState::STATE_MOVE:
      return "STATE_MOVE";
    case CompState::STATE_COMPENSATE:
      return "STATE_COMPENSATE";
    case CompState::STATE_FINISHED:
      return "STATE_FINISHED";
    case CompState::STATE_ERROR:
      return "STATE_ERROR";
  }
  return "?";
}

// PROGRAM MAIN, one call per PLC cycle. A cycle function.
struct Main {
  Figure figure = kFigures[0];
  fb::MC_Power Power;
  fb::MC_MoveAbsolute Move;
  fb::MC_MoveSuperImposed Compensate;
  CompState state = CompState::STATE_INIT;
  uint32_t error_id = 0;

  void operator()(plc::AXIS_REF& axis) noexcept {
    Power.Enable = Power.Enable_Positive = Power.Enable_Negative = true;
    Power(axis);

    switch (state) {
      case CompState::STATE_INIT:
        if (Power.Status) state = CompState::STATE_MOVE;
        break;
      case CompState::STATE_MOVE:
        Move.Execute = true;
        // Seed 000 §2.5 note 2: started at the axis's target velocity, VP = that velocity.
        if (Move.Active && plc::test_bit(axis.NcToPlc.StateDWord, plc::kStateConstantVelocity)) {
          Compensate.Execute = true;
          state = CompState::STATE_COMPENSATE;
        }
        break;
      case CompState::STATE_COMPENSATE:
        if (Move.Done) state = CompState::STATE_FINISHED;
        break;
      case CompState::STATE_FINISHED:
      case CompState::STATE_ERROR:
        break;
    }

    Move.Position = kTarget;
    Move.Velocity = kVelocity;
    Move(axis);
    Compensate.Distance = figure.distance;
    Compensate.VelocityDiff = figure.velocity_diff;
    Compensate.Acceleration = kAccelerationPlus;
    Compensate.Deceleration = kAccelerationMinus;
    Compensate.VelocityProcess = kProcessVelocity;
    Compensate.Length = figure.length;
    Compensate(axis);
    if (Move.Done && state == CompState::STATE_COMPENSATE) state = CompState::STATE_FINISHED;
    if (Power.Error || Move.Error || Compensate.Error) {
      error_id = Power.Error ? Power.ErrorID : Move.Error ? Move.ErrorID : Compensate.ErrorID;
      state = CompState::STATE_ERROR;
    }
  }
};

// What the run showed, for the summary and the test.
struct Report {
  bool finished = false;
  uint32_t error_id = 0;
  double compensation_start_time = -1.0;  // s, MC_MoveSuperImposed posted
  double compensation_start_pos = 0.0;    // mm, SetPos then
  double compensation_done_time = -1.0;   // s, MC_MoveSuperImposed Done
  double move_done_time = -1.0;           // s, MC_MoveAbsolute Done
  double actual_distance = 0.0;           // MC_MoveSuperImposed.ActualDistance at its Done
  double actual_length = 0.0;             // .ActualLength
  double actual_velocity_diff = 0.0;      // .ActualVelocityDiff
  bool warning = false;                   // .Warning at its Done
  uint32_t warning_id = 0;
  bool compensation_done = false;    // it showed Done (not CommandAborted / Error)
  double max_set_velocity = 0.0;     // mm/s
  double max_following_error = 0.0;  // mm
  double final_set_pos = 0.0;        // mm
  double final_act_pos = 0.0;        // mm
  uint32_t axis_error = 0;
  double end_time = 0.0;
};

// The sample's success rule for one figure: the end position of the seed (exact to 1e-6 mm,
// the partial figure's 500/3 being no round number), the warning exactly where D was not
// feasible.
inline bool figure_ok(const Figure& figure, const Report& report) noexcept {
  return report.finished && report.error_id == 0 && report.axis_error == 0 &&
         report.compensation_done && report.warning == figure.expect_warning &&
         std::fabs(report.final_set_pos - figure.expected_end) <= 1e-6;
}

struct Options {
  double nc_cycle = 0.001;   // s; the PLC task runs with it
  double timeout = 15.0;     // s of simulated time
  double settle_time = 0.2;  // s recorded after the basic move's Done
};

// The sample's axis: kernel dynamics (A 5000 mm/s², J 50000 mm/s³), room above V for the extra
// velocity, and the lagging drive of the other samples.
inline nc::AxisConfig sample_axis_config() {
  nc::AxisConfig config;
  config.name = "Axis1";
  config.max_velocity = 3000.0;
  config.ref_velocity = 3000.0;
  sample_common::use_lagging_drive(config, 5.0);
  return config;
}

class CompensationSample {
 public:
  // Set-up: kernel, axis, tasks and scope for one figure (throws on a bad option).
  explicit CompensationSample(const Figure& figure, const Options& options = {})
      : kernel_(nc::KernelConfig{options.nc_cycle}),
        axis_(kernel_.add_axis(sample_axis_config())),
        driver_(kernel_),
        scope_(sample_common::scope_capacity(options)),
        options_(options) {
    main_.figure = figure;
    scope_.add_motion_signals(axis_, "Axis1");
    scope_.add_signal(axis_, "Axis1", nc::Signal::kCompensationDistance);
    scope_.add_signal(axis_, "Axis1", nc::Signal::kStateDWord);
    driver_.add_task("Scope", options.nc_cycle, [this] { sample(); });
    driver_.add_task("PlcTask", options.nc_cycle, [this] { plc_cycle(); });
  }

  CompensationSample(const CompensationSample&) = delete;
  CompensationSample& operator=(const CompensationSample&) = delete;

  const Report& run() {
    report_.finished =
        sample_common::run_to_state(driver_, main_.state, CompState::STATE_FINISHED,
                                    CompState::STATE_ERROR, options_.timeout, options_.settle_time);
    sample();
    report_.error_id = main_.error_id;
    report_.final_set_pos = axis_.NcToPlc.SetPos;
    report_.final_act_pos = axis_.NcToPlc.ActPos;
    report_.axis_error = axis_.NcToPlc.ErrorCode;
    report_.end_time = kernel_.time();
    return report_;
  }

  bool ok() const noexcept { return figure_ok(main_.figure, report_); }

  // After-run: <dir>/<figure name>.csv and .svg; returns their paths.
  std::pair<std::filesystem::path, std::filesystem::path> write(
      const std::filesystem::path& dir) const {
    const Figure& f = main_.figure;
    const auto [csv, svg] = sample_common::csv_and_svg(dir, f.name);
    scope_.write_csv(csv);
    std::vector<nc::PlotPanel> panels = nc::motion_panels(scope_, "Axis1");
    panels.push_back(
        {"panel-compensation",
         "Compensation distance",
         "mm",
         {{"CompensationDistance", "#8a2be2",
           scope_.values(scope_.find("Axis1", nc::Signal::kCompensationDistance)), 1.5}}});
    char title[256];
    std::snprintf(title, sizeof title,
                  "%s: L %.0f mm, D %.0f mm, VK %.0f mm/s (AK+ 500, AK- 1000, VP 2000) "
                  "\u2192 %.2f mm",
                  f.title, f.length, f.distance, f.velocity_diff, report_.final_set_pos);
    nc::write_svg(svg, nc::svg_plot(scope_.time(), panels, {title, 1000, 150}));
    return {csv, svg};
  }

  std::string summary() const {
    const Figure& f = main_.figure;
    char text[1024];
    std::snprintf(text, sizeof text,
                  "%s (seed 000 2.5): L %.0f mm, D %.0f mm, VK %.0f mm/s: %s\n"
                  "  compensation started %.3f s at %.3f mm, done %.3f s; move done %.3f s\n"
                  "  ActualDistance %.6f mm, ActualLength %.3f mm, ActualVelocityDiff %.3f mm/s, "
                  "Warning %s (0x%X)\n"
                  "  end: set %.6f mm (expected %.6f mm), actual %.4f mm\n"
                  "  max set velocity %.3f mm/s, max following error %.4f mm, simulated %.3f s\n",
                  f.title, f.length, f.distance, f.velocity_diff, ok() ? "ok" : "FAILED",
                  report_.compensation_start_time, report_.compensation_start_pos,
                  report_.compensation_done_time, report_.move_done_time, report_.actual_distance,
                  report_.actual_length, report_.actual_velocity_diff,
                  report_.warning ? "yes" : "no", static_cast<unsigned>(report_.warning_id),
                  report_.final_set_pos, f.expected_end, report_.final_act_pos,
                  report_.max_set_velocity, report_.max_following_error, report_.end_time);
    std::string out = text;
    if (report_.error_id != 0 || report_.axis_error != 0) {
      out += sample_common::error_line("block", report_.error_id, report_.axis_error,
                                       state_name(main_.state));
    }
    return out;
  }

  const nc::Scope& scope() const noexcept { return scope_; }
  const Main& program() const noexcept { return main_; }
  const plc::AXIS_REF& axis() const noexcept { return axis_; }
  const nc::Kernel& kernel() const noexcept { return kernel_; }

 private:
  void sample() noexcept {
    scope_.record(kernel_.time());
    sample_common::track_max(report_.max_following_error, axis_.NcToPlc.PosDiff);
    sample_common::track_max(report_.max_set_velocity, axis_.NcToPlc.SetVelo);
  }

  void plc_cycle() noexcept {
    main_(axis_);
    const double now = kernel_.time();
    const fb::MC_MoveSuperImposed& c = main_.Compensate;
    if (c.Busy && report_.compensation_start_time < 0.0) {
      report_.compensation_start_time = now;
      report_.compensation_start_pos = axis_.NcToPlc.SetPos;
    }
    if (c.Done && report_.compensation_done_time < 0.0) {
      report_.compensation_done_time = now;
      report_.compensation_done = true;
      report_.actual_distance = c.ActualDistance;
      report_.actual_length = c.ActualLength;
      report_.actual_velocity_diff = c.ActualVelocityDiff;
      report_.warning = c.Warning;
      report_.warning_id = c.WarningID;
    }
    if (main_.Move.Done && report_.move_done_time < 0.0) report_.move_done_time = now;
  }

  nc::Kernel kernel_;
  plc::AXIS_REF& axis_;
  nc::CycleDriver driver_;
  nc::Scope scope_;
  Options options_;
  Main main_;
  Report report_;
};

}  // namespace compensation
