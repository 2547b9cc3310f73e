// The seed's external setpoint generator example (seed 000 §4.1) as an ncsdk PLC program.
//
// A PLC-side 3-phase generator with a rectangular acceleration profile — accelerate at +A,
// cruise at V, decelerate at -A onto the target — moves an axis through the external setpoint
// interface (seed 000 §2.6): MC_ExtSetPointGenEnable (absolute start type, Position = the leg's
// target for target-window monitoring), one MC_ExtSetPointGenFeed packet every PLC cycle, and
// MC_ExtSetPointGenDisable at the end. As the seed advises, the PLC task runs with the NC cycle,
// and the direction is set to ±1 one cycle before the motion (a packet at the start position)
// and kept for one cycle after it (a packet at the target) before it returns to 0.
//
// Two legs: 0 → 1500 mm (V 1000 mm/s, A 2500 mm/s²: 0.4 s ramps around 1.1 s of cruise) and
// 1500 → 1200 mm (too short to reach V: a triangle peaking at sqrt(300·2500) = 866 mm/s). The
// second leg re-enables with the same start type and the new target, which only moves the
// target-window monitoring (seed 000 §2.6 "repeated activation"). Between the legs the program
// waits for InTargetPosition and then dwells 0.25 s.
//
// ExtSetpointGeneratorSample puts the program on a simulated axis (1 ms NC cycle, 1 ms PLC task,
// a scope every NC cycle). Header-only, so that tests/samples/test_ext_setpoint_generator_sample
// runs exactly what the sample program runs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

#include "fb/mc_ext_set_point_gen_disable.hpp"
#include "fb/mc_ext_set_point_gen_enable.hpp"
#include "fb/mc_ext_set_point_gen_feed.hpp"
#include "fb/mc_power.hpp"
#include "fb/types.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"
#include "plc_interface/axis_ref.hpp"
#include "sample_output.hpp"

namespace ext_setpoint_generator {

// The PLC's setpoint generator: 3 phases, rectangular acceleration (seed 000 §4.1). Pure
// arithmetic on doubles: start() and at() are cycle functions.
class ThreePhaseGenerator {
 public:
  struct Point {
    double p = 0.0, v = 0.0, a = 0.0;
  };

  // From `from` to `to` with at most `velocity` (> 0) and the acceleration `acceleration` (> 0).
  void start(double from, double to, double velocity, double acceleration) noexcept {
    from_ = from;
    to_ = to;
    direction_ = to >= from ? 1.0 : -1.0;
    acceleration_ = acceleration;
    const double distance = std::fabs(to - from);
    // A triangle when the distance is shorter than the two ramps to V need (V²/A together).
    peak_ = std::min(velocity, std::sqrt(distance * acceleration));
    ramp_time_ = peak_ / acceleration;
    cruise_time_ = peak_ > 0.0 ? (distance - peak_ * ramp_time_) / peak_ : 0.0;
  }

  double duration() const noexcept { return 2.0 * ramp_time_ + cruise_time_; }
  int direction() const noexcept { return direction_ > 0.0 ? 1 : -1; }
  double peak_velocity() const noexcept { return peak_; }
  double ramp_time() const noexcept { return ramp_time_; }
  double cruise_time() const noexcept { return cruise_time_; }

  // The set point at t s after the start: before it the start, from duration() on the target.
  Point at(double t) const noexcept {
    const double d = direction_;
    const double a = acceleration_;
    if (t <= 0.0) return {from_, 0.0, 0.0};
    if (t >= duration()) return {to_, 0.0, 0.0};
    if (t <= ramp_time_) return {from_ + d * 0.5 * a * t * t, d * a * t, d * a};
    if (t <= ramp_time_ + cruise_time_) {
      return {from_ + d * (0.5 * peak_ * ramp_time_ + peak_ * (t - ramp_time_)), d * peak_, 0.0};
    }
    // The closing ramp, counted back from the end so that the target is hit exactly.
    const double rest = duration() - t;
    return {to_ - d * 0.5 * a * rest * rest, d * a * rest, -d * a};
  }

 private:
  double from_ = 0.0, to_ = 0.0, direction_ = 1.0, acceleration_ = 1.0;
  double peak_ = 0.0, ramp_time_ = 0.0, cruise_time_ = 0.0;
};

enum class GenState {
  STATE_INIT,         // wait for the axis to be enabled
  STATE_ENABLE,       // MC_ExtSetPointGenEnable with the leg's target
  STATE_PRE_MOTION,   // one packet at the start position, direction already ±1
  STATE_MOTION,       // the generator's packets
  STATE_POST_MOTION,  // one more packet at the target, direction still ±1
  STATE_WAIT_TARGET,  // direction 0; wait for InTargetPosition, then dwell
  STATE_DISABLE,      // MC_ExtSetPointGenDisable
  STATE_FINISHED,
  STATE_ERROR,
};

inline const char* state_name(GenState state) noexcept {
  switch (state) {
    case GenState::STATE_INIT:
      return "STATE_INIT";
    case GenState::STATE_ENABLE:
      return "STATE_ENABLE";
    case GenState::STATE_PRE_MOTION:
      return "STATE_PRE_MOTION";
    case GenState::STATE_MOTION:
      return "STATE_MOTION";
    case GenState::STATE_POST_MOTION:
      return "STATE_POST_MOTION";
    case GenState::STATE_WAIT_TARGET:
      return "STATE_WAIT_TARGET";
    case GenState::STATE_DISABLE:
      return "STATE_DISABLE";
    case GenState::STATE_FINISHED:
      return "STATE_FINISHED";
    case GenState::STATE_ERROR:
      return "STATE_ERROR";
  }
  return "?";
}

// One leg of the program.
struct Leg {
  double target;        // mm
  double velocity;      // mm/s
  double acceleration;  // mm/s²
};

inline constexpr Leg kLegs[] = {{1500.0, 1000.0, 2500.0}, {1200.0, 1000.0, 2500.0}};
inline constexpr std::size_t kLegCount = sizeof(kLegs) / sizeof(kLegs[0]);
inline constexpr double kDwellTime = 0.25;  // s in the target window between legs

// PROGRAM MAIN, one call per PLC cycle (the PLC task runs with the NC cycle). A cycle function.
struct Main {
  double cycle_time = 0.001;  // s, the PLC task's period

  fb::MC_Power Power;
  fb::MC_ExtSetPointGenEnable Enable;
  fb::MC_ExtSetPointGenDisable Disable;
  ThreePhaseGenerator Generator;

  GenState state = GenState::STATE_INIT;
  std::size_t leg = 0;
  uint64_t motion_cycles = 0;  // PLC cycles since the leg's motion began
  uint64_t dwell_cycles = 0;   // PLC cycles in the target window
  uint32_t error_id = 0;

  // The packet fed in this cycle (also recorded by the scope).
  double FedPos = 0.0, FedVelo = 0.0, FedAcc = 0.0, FedDirection = 0.0;

  void operator()(plc::AXIS_REF& axis) noexcept {
    Power.Enable = Power.Enable_Positive = Power.Enable_Negative = true;
    Power(axis);
    Enable.Execute = false;
    Disable.Execute = false;

    int direction = 0;  // of this cycle's packet
    ThreePhaseGenerator::Point point{FedPos, 0.0, 0.0};
    switch (state) {
      case GenState::STATE_INIT:
        point.p = axis.NcToPlc.SetPos;
        if (Power.Status) state = GenState::STATE_ENABLE;
        break;
      case GenState::STATE_ENABLE:
        Enable.Execute = true;
        Enable.Position = kLegs[leg].target;
        Enable.PositionType = fb::POSITIONTYPE_ABSOLUTE;
        break;
      case GenState::STATE_PRE_MOTION:
        Generator.start(FedPos, kLegs[leg].target, kLegs[leg].velocity, kLegs[leg].acceleration);
        direction = Generator.direction();
        point = Generator.at(0.0);
        motion_cycles = 0;
        state = GenState::STATE_MOTION;
        break;
      case GenState::STATE_MOTION:
        ++motion_cycles;
        direction = Generator.direction();
        point = Generator.at(static_cast<double>(motion_cycles) * cycle_time);
        if (static_cast<double>(motion_cycles) * cycle_time >= Generator.duration()) {
          state = GenState::STATE_POST_MOTION;
        }
        break;
      case GenState::STATE_POST_MOTION:
        direction = Generator.direction();
        point = {kLegs[leg].target, 0.0, 0.0};
        dwell_cycles = 0;
        state = GenState::STATE_WAIT_TARGET;
        break;
      case GenState::STATE_WAIT_TARGET:
        point = {kLegs[leg].target, 0.0, 0.0};
        if (plc::test_bit(axis.NcToPlc.StateDWord, plc::kStateInTargetPosition)) ++dwell_cycles;
        if (static_cast<double>(dwell_cycles) * cycle_time >= kDwellTime) {
          ++leg;
          state = leg < kLegCount ? GenState::STATE_ENABLE : GenState::STATE_DISABLE;
        }
        break;
      case GenState::STATE_DISABLE:
        Disable.Execute = true;
        break;
      case GenState::STATE_FINISHED:
      case GenState::STATE_ERROR:
        break;
    }
    Enable(axis);
    Disable(axis);
    if (state == GenState::STATE_ENABLE && Enable.Done) state = GenState::STATE_PRE_MOTION;
    if (state == GenState::STATE_DISABLE && Disable.Done) state = GenState::STATE_FINISHED;
    if (Enable.Error || Disable.Error || Power.Error) {
      error_id = Enable.Error ? Enable.ErrorID : Disable.Error ? Disable.ErrorID : Power.ErrorID;
      state = GenState::STATE_ERROR;
    }

    // The packet of this cycle, every cycle (direction 0 outside the motion: nothing is taken).
    const uint32_t feed = fb::MC_ExtSetPointGenFeed(point.p, point.v, point.a, direction, axis);
    if (feed != 0) {
      error_id = feed;
      state = GenState::STATE_ERROR;
    }
    FedPos = point.p;
    FedVelo = point.v;
    FedAcc = point.a;
    FedDirection = direction;
  }
};

// What the run showed, for the summary and the test.
struct LegReport {
  double start_time = -1.0;      // s, first packet with direction ±1
  double end_time = -1.0;        // s, last packet with direction ±1
  double in_target_time = -1.0;  // s, InTargetPosition first seen by the program
  double set_pos = 0.0;          // mm, NcToPlc.SetPos then
  double act_pos = 0.0;          // mm, NcToPlc.ActPos then
  double peak_velocity = 0.0;    // mm/s, the generator's peak
};

struct Report {
  bool finished = false;  // STATE_FINISHED before the timeout
  uint32_t error_id = 0;  // a block's ErrorID or the feed's result
  LegReport legs[kLegCount];
  double enabled_time = -1.0;        // s, StateDWord bit 14 first seen
  double disabled_time = -1.0;       // s, bit 14 gone after the last leg
  double max_set_minus_fed = 0.0;    // mm, max |SetPos - FedPos| over the taken packets
  double max_following_error = 0.0;  // mm
  double final_set_pos = 0.0;        // mm
  double final_act_pos = 0.0;        // mm
  bool final_in_target = false;      // InTargetPosition at the end
  bool final_enabled = true;         // ExtSetPointGenEnabled at the end
  uint32_t axis_error = 0;
  double end_time = 0.0;

  bool ok() const noexcept {
    return finished && error_id == 0 && axis_error == 0 && max_set_minus_fed == 0.0 &&
           final_set_pos == kLegs[kLegCount - 1].target && final_in_target && !final_enabled;
  }
};

struct Options {
  double nc_cycle = 0.001;   // s; the PLC task runs with it, as the seed advises
  double timeout = 10.0;     // s of simulated time
  double settle_time = 0.2;  // s recorded after STATE_FINISHED
};

// The sample's axis: kernel defaults on a drive that lags a little (as in the MoveAxis sample),
// so the plot shows the actual values following the fed ones.
inline nc::AxisConfig sample_axis_config() {
  nc::AxisConfig config;
  config.name = "Axis1";
  sample_common::use_lagging_drive(config, 5.0);
  return config;
}

class ExtSetpointGeneratorSample {
 public:
  // Set-up: kernel, axis, tasks and scope (throws on a bad option).
  explicit ExtSetpointGeneratorSample(const Options& options = {})
      : kernel_(nc::KernelConfig{options.nc_cycle}),
        axis_(kernel_.add_axis(sample_axis_config())),
        driver_(kernel_),
        scope_(sample_common::scope_capacity(options)),
        options_(options) {
    main_.cycle_time = options.nc_cycle;
    scope_.add_motion_signals(axis_, "Axis1");
    scope_.add_signal(axis_, "Axis1", nc::Signal::kStateDWord);
    scope_.add_variable(&main_.FedPos, "MAIN.FedPos", "mm");
    scope_.add_variable(&main_.FedVelo, "MAIN.FedVelo", "mm/s");
    scope_.add_variable(&main_.FedAcc, "MAIN.FedAcc", "mm/s²");
    scope_.add_variable(&main_.FedDirection, "MAIN.FedDirection", "");
    // The scope runs first in a tick: it records what the NC published at the end of the last
    // cycle beside the packet the PLC fed for that cycle.
    driver_.add_task("Scope", options.nc_cycle, [this] { sample(); });
    driver_.add_task("PlcTask", options.nc_cycle, [this] { plc_cycle(); });
  }

  ExtSetpointGeneratorSample(const ExtSetpointGeneratorSample&) = delete;
  ExtSetpointGeneratorSample& operator=(const ExtSetpointGeneratorSample&) = delete;

  const Report& run() {
    report_.finished =
        sample_common::run_to_state(driver_, main_.state, GenState::STATE_FINISHED,
                                    GenState::STATE_ERROR, options_.timeout, options_.settle_time);
    sample();
    report_.error_id = main_.error_id;
    report_.final_set_pos = axis_.NcToPlc.SetPos;
    report_.final_act_pos = axis_.NcToPlc.ActPos;
    report_.final_in_target = plc::test_bit(axis_.NcToPlc.StateDWord, plc::kStateInTargetPosition);
    report_.final_enabled =
        plc::test_bit(axis_.NcToPlc.StateDWord, plc::kStateExtSetPointGenEnabled);
    report_.axis_error = axis_.NcToPlc.ErrorCode;
    report_.end_time = kernel_.time();
    return report_;
  }

  // After-run: <dir>/ext_setpoint_generator.csv and .svg; returns their paths.
  std::pair<std::filesystem::path, std::filesystem::path> write(
      const std::filesystem::path& dir) const {
    const auto [csv, svg] = sample_common::csv_and_svg(dir, "ext_setpoint_generator");
    scope_.write_csv(csv);
    std::vector<nc::PlotPanel> panels = nc::motion_panels(scope_, "Axis1");
    // The fed packet beside the set values: they coincide wherever the direction is ±1.
    panels[0].series.push_back(
        {"FedPos", "#ff8c00", scope_.values(scope_.find("MAIN.FedPos")), 1.0});
    panels[1].series.push_back(
        {"FedVelo", "#ff8c00", scope_.values(scope_.find("MAIN.FedVelo")), 1.0});
    panels[2].series.push_back(
        {"FedAcc", "#ff8c00", scope_.values(scope_.find("MAIN.FedAcc")), 1.0});
    panels.push_back(
        {"panel-direction",
         "ExtSetDirection",
         "",
         {{"FedDirection", "#555555", scope_.values(scope_.find("MAIN.FedDirection")), 1.5}}});
    nc::write_svg(svg, nc::svg_plot(scope_.time(), panels,
                                    {"External setpoint generator (seed 000 \u00a74.1): "
                                     "rectangular acceleration, 0 \u2192 1500 \u2192 1200 mm",
                                     1000, 150}));
    return {csv, svg};
  }

  std::string summary() const {
    std::string out;
    char text[512];
    std::snprintf(text, sizeof text,
                  "External setpoint generator (seed 000 4.1): %s\n"
                  "  external setpoint generation enabled at %.3f s, disabled at %.3f s\n",
                  report_.ok() ? "both legs fed, set position = fed position" : "FAILED",
                  report_.enabled_time, report_.disabled_time);
    out += text;
    double from = 0.0;
    for (std::size_t i = 0; i < kLegCount; ++i) {
      const LegReport& leg = report_.legs[i];
      std::snprintf(text, sizeof text,
                    "  leg %zu: %7.1f -> %7.1f mm, peak %6.1f mm/s, packets %.3f..%.3f s, "
                    "InTargetPosition %.3f s (set %.6f mm, actual %.4f mm)\n",
                    i + 1, from, kLegs[i].target, leg.peak_velocity, leg.start_time, leg.end_time,
                    leg.in_target_time, leg.set_pos, leg.act_pos);
      out += text;
      from = kLegs[i].target;
    }
    std::snprintf(text, sizeof text,
                  "  max |SetPos - FedPos| over taken packets %.3g mm\n"
                  "  max following error %.4f mm\n"
                  "  end: set %.6f mm, actual %.4f mm, InTargetPosition %s, enabled %s\n"
                  "  samples recorded %zu (%zu dropped), simulated %.3f s\n",
                  report_.max_set_minus_fed, report_.max_following_error, report_.final_set_pos,
                  report_.final_act_pos, report_.final_in_target ? "yes" : "no",
                  report_.final_enabled ? "yes" : "no", scope_.size(), scope_.dropped(),
                  report_.end_time);
    out += text;
    if (report_.error_id != 0 || report_.axis_error != 0) {
      out += sample_common::error_line("program", report_.error_id, report_.axis_error,
                                       state_name(main_.state));
    }
    return out;
  }

  const nc::Scope& scope() const noexcept { return scope_; }
  const Main& program() const noexcept { return main_; }
  const plc::AXIS_REF& axis() const noexcept { return axis_; }
  const nc::Kernel& kernel() const noexcept { return kernel_; }

 private:
  // Scope task: the NC image of the last cycle beside the packet the PLC fed for it.
  void sample() noexcept {
    scope_.record(kernel_.time());
    sample_common::track_max(report_.max_following_error, axis_.NcToPlc.PosDiff);
    if (fed_direction_ != 0 && kernel_.cycle_count() > 0) {
      report_.max_set_minus_fed =
          std::max(report_.max_set_minus_fed, std::fabs(axis_.NcToPlc.SetPos - fed_pos_));
    }
  }

  void plc_cycle() noexcept {
    main_(axis_);
    const double now = kernel_.time();
    const bool enabled = plc::test_bit(axis_.NcToPlc.StateDWord, plc::kStateExtSetPointGenEnabled);
    if (enabled && report_.enabled_time < 0.0) report_.enabled_time = now;
    if (!enabled && report_.enabled_time >= 0.0 && main_.leg == kLegCount &&
        report_.disabled_time < 0.0) {
      report_.disabled_time = now;
    }
    const std::size_t leg = std::min(main_.leg, kLegCount - 1);
    LegReport& r = report_.legs[leg];
    if (main_.FedDirection != 0.0) {
      if (r.start_time < 0.0) r.start_time = now;
      r.end_time = now;
      r.peak_velocity = main_.Generator.peak_velocity();
    }
    LegReport& reached = report_.legs[std::min(main_.leg, kLegCount - 1)];
    if (main_.state == GenState::STATE_WAIT_TARGET && main_.dwell_cycles > 0 &&
        reached.in_target_time < 0.0) {
      reached.in_target_time = now;
      reached.set_pos = axis_.NcToPlc.SetPos;
      reached.act_pos = axis_.NcToPlc.ActPos;
    }
    fed_pos_ = main_.FedPos;
    fed_direction_ = static_cast<int>(main_.FedDirection);
  }

  nc::Kernel kernel_;
  plc::AXIS_REF& axis_;
  nc::CycleDriver driver_;
  nc::Scope scope_;
  Options options_;
  Main main_;
  Report report_;
  double fed_pos_ = 0.0;
  int fed_direction_ = 0;
};

}  // namespace ext_setpoint_generator
