// The seed's MoveAxis example (seed 000 §4.3) as an ncsdk PLC program.
//
// PROGRAM AxisEnable switches the axis on with MC_Power; PROGRAM MAIN runs the seed's CASE
// state machine: MOVESTATE_INIT waits for AxisEnable.Ready, MOVESTATE_FORWARD moves to 2000 mm,
// MOVESTATE_BACKWARDS back to 0 mm, each with one MC_MoveAbsolute (the seed's "MoveAction").
// One change to the seed: after the way back the program goes to MOVESTATE_FINISHED, where the
// seed's program would keep re-starting a zero-length move to 0.
//
// MoveAxisSample puts the program on a simulated axis: a kernel (1 ms NC cycle), a 10 ms PLC
// task (TwinCAT's default PLC task time) and a 1 ms scope task that records set and actual
// position, velocity, acceleration and following error every NC cycle. It is header-only so the
// test (tests/samples/test_move_axis_sample.cpp) runs exactly what the sample program runs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "fb/mc_move_absolute.hpp"
#include "fb/mc_power.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"
#include "plc_interface/axis_ref.hpp"
#include "sample_output.hpp"

namespace move_axis {

enum class MoveState { MOVESTATE_INIT, MOVESTATE_FORWARD, MOVESTATE_BACKWARDS, MOVESTATE_FINISHED };

inline const char* state_name(MoveState state) noexcept {
  switch (state) {
    case MoveState::MOVESTATE_INIT:
      return "MOVESTATE_INIT";
    case MoveState::MOVESTATE_FORWARD:
      return "MOVESTATE_FORWARD";
    case MoveState::MOVESTATE_BACKWARDS:
      return "MOVESTATE_BACKWARDS";
    case MoveState::MOVESTATE_FINISHED:
      return "MOVESTATE_FINISHED";
  }
  return "?";
}

// PROGRAM AxisEnable: controller and feed enables on, override 100 %.
struct AxisEnable {
  fb::MC_Power Power;
  bool Ready = false;

  void operator()(plc::AXIS_REF& axis) noexcept {
    Power.Enable = true;
    Power.Enable_Positive = true;
    Power.Enable_Negative = true;
    Power.Override = 100.0;
    Power(axis);
    Ready = Power.Status;
  }
};

// PROGRAM MAIN of seed 000 §4.3, one call per PLC cycle. A cycle function: no allocation.
struct Main {
  static constexpr double kForwardPosition = 2000.0;  // mm
  static constexpr double kBackPosition = 0.0;        // mm
  static constexpr double kVelocity = 2000.0;         // mm/s, V of the seed's figures

  double Position = 0.0;
  bool StartAxis = false;
  bool MoveDone = false;
  MoveState state = MoveState::MOVESTATE_INIT;
  AxisEnable axis_enable;
  fb::MC_MoveAbsolute MoveAxis;

  void operator()(plc::AXIS_REF& axis) noexcept {
    // enable the axis
    axis_enable(axis);

    // move the axis forward and backwards
    switch (state) {
      case MoveState::MOVESTATE_INIT:
        StartAxis = false;
        if (axis_enable.Ready) state = MoveState::MOVESTATE_FORWARD;
        break;
      case MoveState::MOVESTATE_FORWARD:
        Position = kForwardPosition;
        StartAxis = true;
        if (MoveDone) {
          StartAxis = false;
          state = MoveState::MOVESTATE_BACKWARDS;
        }
        break;
      case MoveState::MOVESTATE_BACKWARDS:
        Position = kBackPosition;
        StartAxis = true;
        if (MoveDone) {
          StartAxis = false;
          state = MoveState::MOVESTATE_FINISHED;
        }
        break;
      case MoveState::MOVESTATE_FINISHED:
        StartAxis = false;
        break;
    }

    // MoveAction
    MoveAxis.Execute = StartAxis;
    MoveAxis.Position = Position;
    MoveAxis.Velocity = kVelocity;
    MoveAxis(axis);
    MoveDone = MoveAxis.Done;
  }
};

// What the run showed, for the summary and the test.
struct Report {
  bool finished = false;              // MOVESTATE_FINISHED reached before the timeout
  bool block_error = false;           // MC_Power or MC_MoveAbsolute showed Error
  uint32_t error_id = 0;              // the block's ErrorID then
  double enabled_time = -1.0;         // s, AxisEnable.Ready first seen
  double forward_start_time = -1.0;   // s, MoveAxis Busy (command posted) towards 2000 mm
  double forward_done_time = -1.0;    // s, MoveAxis Done at 2000 mm
  double backward_start_time = -1.0;  // s, MoveAxis Busy towards 0 mm
  double backward_done_time = -1.0;   // s, MoveAxis Done at 0 mm
  double forward_set_pos = 0.0;       // mm, NcToPlc.SetPos when the forward move was Done
  double forward_act_pos = 0.0;       // mm, NcToPlc.ActPos then
  double final_set_pos = 0.0;         // mm, at the end of the run
  double final_act_pos = 0.0;         // mm
  double max_following_error = 0.0;   // mm, max |PosDiff| over the run
  double max_set_velocity = 0.0;      // mm/s, max |SetVelo| over the run
  double end_time = 0.0;              // s, simulated time at the end
  uint32_t axis_error = 0;            // NcToPlc.ErrorCode at the end

  // The sample's success rule: forward to 2000 mm, then back to 0 mm, without errors.
  bool ok() const noexcept {
    return finished && !block_error && axis_error == 0 &&
           std::fabs(forward_set_pos - Main::kForwardPosition) < 1e-9 &&
           std::fabs(final_set_pos - Main::kBackPosition) < 1e-9;
  }
};

struct Options {
  double nc_cycle = 0.001;    // s
  double plc_period = 0.010;  // s, a multiple of nc_cycle
  double timeout = 10.0;      // s of simulated time
  double settle_time = 0.3;   // s recorded after MOVESTATE_FINISHED: the drive settling
};

// The sample's axis: the kernel defaults (A+ = A- = 5000 mm/s², J = 50000 mm/s³, Vmax 2200
// mm/s, as in the seed 000 §2.1 figures) on a drive that lags a little (first-order 1 ms plus
// 1 ms dead time), so the scope shows the following error a real drive leaves, with a position
// controller gain (Kv 5 /s) that keeps it well inside the 5 mm lag limit.
inline nc::AxisConfig sample_axis_config() {
  nc::AxisConfig config;
  config.name = "Axis1";
  sample_common::use_lagging_drive(config, 5.0);
  return config;
}

class MoveAxisSample {
 public:
  // Set-up: builds the kernel, the axis, the tasks and the scope (throws on a bad option).
  explicit MoveAxisSample(const Options& options = {})
      : kernel_(nc::KernelConfig{options.nc_cycle}),
        axis_(kernel_.add_axis(sample_axis_config())),
        driver_(kernel_),
        scope_(sample_common::scope_capacity(options)),
        options_(options) {
    scope_.add_motion_signals(axis_, "Axis1");
    scope_.add_signal(axis_, "Axis1", nc::Signal::kTargetPos);
    // The scope task runs first in a tick: it records what the NC published at the end of the
    // previous cycle, stamped with the time of that cycle's end.
    driver_.add_task("Scope", options.nc_cycle, [this] { sample(); });
    driver_.add_task("PlcTask", options.plc_period, [this] { plc_cycle(); });
  }

  MoveAxisSample(const MoveAxisSample&) = delete;
  MoveAxisSample& operator=(const MoveAxisSample&) = delete;

  // Runs until MOVESTATE_FINISHED (then settle_time longer), a block error or the timeout;
  // records the last cycle too.
  const Report& run() {
    report_.finished = sample_common::run_and_settle(
        driver_,
        [this] { return main_.state == MoveState::MOVESTATE_FINISHED || report_.block_error; },
        [this] { return main_.state == MoveState::MOVESTATE_FINISHED; }, options_.timeout,
        options_.settle_time);
    sample();
    report_.final_set_pos = axis_.NcToPlc.SetPos;
    report_.final_act_pos = axis_.NcToPlc.ActPos;
    report_.axis_error = axis_.NcToPlc.ErrorCode;
    report_.end_time = kernel_.time();
    return report_;
  }

  // After-run: <dir>/move_axis.csv and <dir>/move_axis.svg; returns their paths.
  std::pair<std::filesystem::path, std::filesystem::path> write(
      const std::filesystem::path& dir) const {
    const auto [csv, svg] = sample_common::csv_and_svg(dir, "move_axis");
    scope_.write_csv(csv);
    nc::write_motion_svg(svg, scope_, "Axis1",
                         {"MoveAxis (seed 000 \u00a74.3): 0 \u2192 2000 mm \u2192 0 mm, "
                          "V 2000 mm/s, A 5000 mm/s\u00b2, J 50000 mm/s\u00b3",
                          1000, 170});
    return {csv, svg};
  }

  // After-run: the short summary the sample prints.
  std::string summary() const {
    char text[1024];
    std::snprintf(
        text, sizeof text,
        "MoveAxis (seed 000 4.3): %s\n"
        "  axis enabled at %.3f s\n"
        "  forward  to 2000 mm: started %.3f s, done %.3f s (set %.6f mm, actual %.4f mm)\n"
        "  backward to    0 mm: started %.3f s, done %.3f s (set %.6f mm, actual %.4f mm)\n"
        "  max set velocity    %9.3f mm/s\n"
        "  max following error %9.4f mm\n"
        "  samples recorded    %zu (%zu dropped), simulated %.3f s\n",
        report_.ok() ? "reached 2000 mm and returned to 0 mm" : "FAILED", report_.enabled_time,
        report_.forward_start_time, report_.forward_done_time, report_.forward_set_pos,
        report_.forward_act_pos, report_.backward_start_time, report_.backward_done_time,
        report_.final_set_pos, report_.final_act_pos, report_.max_set_velocity,
        report_.max_following_error, scope_.size(), scope_.dropped(), report_.end_time);
    std::string out = text;
    if (report_.block_error || report_.axis_error != 0) {
      std::snprintf(text, sizeof text, "  error: block ErrorID 0x%X, axis ErrorCode 0x%X\n",
                    static_cast<unsigned>(report_.error_id),
                    static_cast<unsigned>(report_.axis_error));
      out += text;
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

  // Runs PROGRAM MAIN and notes when things happen. Times are the tick's time: the NcToPlc the
  // program sees was published at the end of the NC cycle that ended then.
  void plc_cycle() noexcept {
    main_(axis_);
    const double now = kernel_.time();
    const fb::MC_MoveAbsolute& move = main_.MoveAxis;
    if (main_.axis_enable.Ready && report_.enabled_time < 0.0) report_.enabled_time = now;
    if (main_.state == MoveState::MOVESTATE_FORWARD) {
      if (move.Busy && report_.forward_start_time < 0.0) report_.forward_start_time = now;
      if (move.Done && report_.forward_done_time < 0.0) {
        report_.forward_done_time = now;
        report_.forward_set_pos = axis_.NcToPlc.SetPos;
        report_.forward_act_pos = axis_.NcToPlc.ActPos;
      }
    }
    if (main_.state == MoveState::MOVESTATE_BACKWARDS) {
      if (move.Busy && report_.backward_start_time < 0.0) report_.backward_start_time = now;
      if (move.Done && report_.backward_done_time < 0.0) report_.backward_done_time = now;
    }
    if (move.Error || main_.axis_enable.Power.Error) {
      report_.block_error = true;
      report_.error_id = move.Error ? move.ErrorID : main_.axis_enable.Power.ErrorID;
    }
  }

  nc::Kernel kernel_;
  plc::AXIS_REF& axis_;
  nc::CycleDriver driver_;
  nc::Scope scope_;
  Options options_;
  Main main_;
  Report report_;
};

}  // namespace move_axis
