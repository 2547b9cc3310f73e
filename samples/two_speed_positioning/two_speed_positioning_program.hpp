// The three positioning examples of the two-speed axis (seed 004 "Positioning examples", SPEC E)
// run with PLC blocks on a simulated rapid/creep drive:
//   1. A → B without loop movement: 0 → 1000 mm;
//   2. A → B with loop movement > 0: 0 → 1000 mm with a looping distance of 30 mm (overshoot
//      towards 1030 mm, come back with negative velocity);
//   3. stop during an active positioning: 0 → 1000 mm, MC_Stop once the axis passed 500 mm.
// Issue 12's parameters: rapid 500 mm/s, creep 50 mm/s, creep distance 100 / 120 mm (+ / -),
// braking distance 5 / 6 mm, brake release delay 0.05 s, rapid-to-creep delay 0.02 s, brake
// incidence delay 0.03 / 0.04 s, creep distance for stop 20 mm; start velocity 2000 mm/s.
//
// TwoSpeedSample runs one example (1 ms NC cycle, 1 ms PLC task, a record every NC cycle of the
// NC→PLC image and the 12-byte drive image) and writes it as CSV and a timing diagram (SVG:
// position, velocity, the six nControlByte bits as digital traces, nAxisState; the moments the
// control byte changes marked T0, T1, … as in the seed's figures). Header-only, so that
// tests/samples/test_two_speed_positioning_sample.cpp runs exactly what the sample runs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fb/mc_move_absolute.hpp"
#include "fb/mc_power.hpp"
#include "fb/mc_stop.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "nc_core/svg_plot.hpp"
#include "plc_interface/axis_ref.hpp"
#include "plc_interface/two_speed.hpp"
#include "sample_output.hpp"

namespace two_speed_positioning {

struct Example {
  const char* name;   // file stem
  const char* title;  // the seed's caption
  double target;      // mm
  bool looping;       // looping distance 30 mm on
  double stop_at;     // mm: MC_Stop once ActPos passed it; NaN for none
};

inline constexpr double kVelocity = 2000.0;  // mm/s, the start velocity: rapid (> 50)
inline constexpr double kLoopingDistance = 30.0;

inline constexpr Example kExamples[] = {
    {"two_speed_positioning_1", "Positioning A \u2192 B, without loop movement", 1000.0, false,
     NAN},
    {"two_speed_positioning_2", "Positioning A \u2192 B, with loop movement > 0.0", 1000.0, true,
     NAN},
    {"two_speed_positioning_3", "Stop call up in case of active positioning", 1000.0, false, 500.0},
};

// The sample's axis: issue 12's parameters; the plant ramps 0 → 500 mm/s in 0.1 s.
inline nc::AxisConfig sample_axis_config(bool looping) {
  nc::AxisConfig c;
  c.name = "Axis1";
  c.kind = nc::AxisKind::kTwoSpeed;
  c.rapid_velocity = 500.0;
  c.creep_velocity = 50.0;
  c.creep_distance_positive = 100.0;
  c.creep_distance_negative = 120.0;
  c.braking_distance_positive = 5.0;
  c.braking_distance_negative = 6.0;
  c.brake_release_delay = 0.05;
  c.rapid_to_creep_delay = 0.02;
  c.brake_incidence_delay_positive = 0.03;
  c.brake_incidence_delay_negative = 0.04;
  c.creep_distance_stop = 20.0;
  c.looping_distance_enabled = looping;
  c.looping_distance = kLoopingDistance;
  c.two_speed_ramp_time = 0.1;
  c.encoder_increment = 1e-4;
  return c;
}

enum class State { STATE_INIT, STATE_MOVE, STATE_STOP, STATE_FINISHED, STATE_ERROR };

inline const char* state_name(State state) noexcept {
  switch (state) {
    case State::STATE_INIT:
      return "STATE_INIT";
    case State::STATE_MOVE:
      return "STATE_MOVE";
    case State::STATE_STOP:
      return "STATE_STOP";
    case State::STATE_FINISHED:
      return "STATE_FINISHED";
    case State::STATE_ERROR:
      return "STATE_ERROR";
  }
  return "?";
}

// PROGRAM MAIN, one call per PLC cycle. A cycle function.
struct Main {
  Example example = kExamples[0];
  fb::MC_Power Power;
  fb::MC_MoveAbsolute Move;
  fb::MC_Stop Stop;
  State state = State::STATE_INIT;
  uint32_t error_id = 0;

  void operator()(plc::AXIS_REF& axis) noexcept {
    Power.Enable = Power.Enable_Positive = Power.Enable_Negative = true;
    Power(axis);
    switch (state) {
      case State::STATE_INIT:
        if (Power.Status) state = State::STATE_MOVE;
        break;
      case State::STATE_MOVE:
        Move.Execute = true;
        // The comparison is false for NaN: no stop in examples 1 and 2.
        if (axis.NcToPlc.ActPos >= example.stop_at) {
          Stop.Execute = true;
          state = State::STATE_STOP;
        }
        break;
      case State::STATE_STOP:
      case State::STATE_FINISHED:
      case State::STATE_ERROR:
        break;
    }
    Move.Position = example.target;
    Move.Velocity = kVelocity;
    Move(axis);
    Stop(axis);
    if (state == State::STATE_MOVE && Move.Done) state = State::STATE_FINISHED;
    if (state == State::STATE_STOP && Stop.Done) state = State::STATE_FINISHED;
    if (Power.Error || Move.Error || Stop.Error) {
      error_id = Power.Error ? Power.ErrorID : Move.Error ? Move.ErrorID : Stop.ErrorID;
      state = State::STATE_ERROR;
    }
  }
};

// The six bits of nControlByte in the diagram, bottom to top.
struct BitTrace {
  plc::ControlByteBit bit;
  const char* label;
  const char* colour;
};
inline constexpr BitTrace kBits[] = {
    {plc::ControlByteBit::bMinusHigh, "bMinusHigh", "#8b0000"},
    {plc::ControlByteBit::bMinusLow, "bMinusLow", "#ff7a7a"},
    {plc::ControlByteBit::bPlusLow, "bPlusLow", "#66d95a"},
    {plc::ControlByteBit::bPlusHigh, "bPlusHigh", "#006400"},
    {plc::ControlByteBit::bBreakInv, "bBreakInv", "#4aa8ff"},
    {plc::ControlByteBit::bBreak, "bBreak", "#00008b"},
};
inline constexpr std::size_t kBitCount = std::size(kBits);
inline constexpr double kBitSpacing = 1.5;  // digital traces: bit k drawn at k · 1.5 + value

// One moment the control byte changed (T0, T1, …): the time the NC published it and where the
// axis was.
struct Change {
  double time = 0.0;      // s
  double position = 0.0;  // mm, ActPos published with it
  uint8_t control = 0;    // nControlByte from then on
  uint32_t axis_state = 0;
};

struct Report {
  bool finished = false;
  uint32_t error_id = 0;
  std::vector<Change> changes;     // T0, T1, …
  double stop_time = -1.0;         // s, MC_Stop posted (example 3)
  double stop_position = 0.0;      // mm, ActPos then
  double highest = 0.0;            // mm, largest ActPos
  bool rapid_after_stop = false;   // a rapid bit after the stop was called
  bool consistent = true;          // both control bytes consistent in every cycle
  bool move_aborted = false;       // MC_MoveAbsolute CommandAborted (example 3)
  std::vector<uint32_t> sequence;  // nAxisState, each run once
  double final_position = 0.0;     // mm, after the settle time
  uint32_t axis_error = 0;
  double end_time = 0.0;
};

struct Options {
  double nc_cycle = 0.001;   // s; the PLC task runs with it
  double timeout = 10.0;     // s of simulated time
  double settle_time = 0.3;  // s recorded after the end (the plant runs down under the brake)
};

class TwoSpeedSample {
 public:
  // Set-up: kernel, axis, tasks and the reserved record for one example.
  explicit TwoSpeedSample(const Example& example, const Options& options = {})
      : kernel_(nc::KernelConfig{options.nc_cycle}),
        axis_(kernel_.add_axis(sample_axis_config(example.looping))),
        image_(kernel_.two_speed_output("Axis1")),
        driver_(kernel_),
        options_(options) {
    main_.example = example;
    const std::size_t capacity = sample_common::scope_capacity(options);
    for (std::vector<double>* v : {&time_, &position_, &set_velocity_, &velocity_, &state_})
      v->reserve(capacity);
    for (std::vector<double>& v : bits_)
      v.reserve(capacity);
    controls_.reserve(capacity);
    report_.changes.reserve(64);
    report_.sequence.reserve(64);
    driver_.add_task("Scope", options.nc_cycle, [this] { record(); });
    driver_.add_task("PlcTask", options.nc_cycle, [this] { plc_cycle(); });
  }

  TwoSpeedSample(const TwoSpeedSample&) = delete;
  TwoSpeedSample& operator=(const TwoSpeedSample&) = delete;

  const Report& run() {
    report_.finished =
        sample_common::run_to_state(driver_, main_.state, State::STATE_FINISHED, State::STATE_ERROR,
                                    options_.timeout, options_.settle_time);
    record();
    report_.error_id = main_.error_id;
    report_.final_position = axis_.NcToPlc.ActPos;
    report_.axis_error = axis_.NcToPlc.ErrorCode;
    report_.end_time = kernel_.time();
    return report_;
  }

  // The sample's own check: finished without error, consistent images, ended within the braking
  // distance of the target (example 3: 20 … 40 mm past the stop, well short of the target), the
  // approach of example 2 from above, and no rapid after a stop.
  bool ok() const noexcept {
    const Report& r = report_;
    if (!r.finished || r.error_id != 0 || r.axis_error != 0 || !r.consistent) return false;
    const Example& e = main_.example;
    if (!std::isnan(e.stop_at)) {
      return r.stop_time >= 0.0 && !r.rapid_after_stop && r.move_aborted &&
             r.final_position > r.stop_position + 20.0 && r.final_position < r.stop_position + 40.0;
    }
    if (e.looping) return r.final_position > e.target && r.final_position - e.target <= 6.0;
    return std::fabs(r.final_position - e.target) <= 5.0;
  }

  // After-run: <dir>/<name>.csv and .svg; returns their paths.
  std::pair<std::filesystem::path, std::filesystem::path> write(
      const std::filesystem::path& dir) const {
    const Example& e = main_.example;
    const auto [csv, svg] = sample_common::csv_and_svg(dir, e.name);
    write_csv(csv);
    std::vector<nc::PlotPanel> panels;
    panels.push_back(
        {"panel-position",
         "Position",
         "mm",
         {{"actual position", std::string(nc::plot_colour::kActualPosition), position_, 1.5}}});
    panels.push_back(
        {"panel-velocity",
         "Velocity",
         "mm/s",
         {{"commanded speed", std::string(nc::plot_colour::kSetVelocity), set_velocity_, 3.0},
          {"actual velocity", std::string(nc::plot_colour::kActualVelocity), velocity_, 1.5}}});
    nc::PlotPanel bits{"panel-control-byte", "nControlByte (bit k at 1.5 k)", "", {}};
    for (std::size_t k = 0; k < kBitCount; ++k)
      bits.series.push_back({kBits[k].label, kBits[k].colour, bits_[k], 1.5});
    panels.push_back(std::move(bits));
    panels.push_back(
        {"panel-axis-state", "nAxisState", "", {{"nAxisState", "#333333", state_, 1.5}}});

    nc::PlotOptions options;
    char title[256];
    std::snprintf(title, sizeof title, "%s: 0 \u2192 %.0f mm%s, end %.3f mm", e.title, e.target,
                  e.looping ? " (looping 30 mm)" : "", report_.final_position);
    options.title = title;
    options.panel_height = 150;
    // T0, T1, … in time order, the stop's call ("stop") among them.
    std::vector<nc::PlotMarker> markers;
    for (std::size_t i = 0; i < report_.changes.size(); ++i) {
      if (report_.stop_time >= 0.0 && report_.stop_time < report_.changes[i].time &&
          (i == 0 || report_.stop_time >= report_.changes[i - 1].time)) {
        markers.push_back({report_.stop_time, "stop"});
      }
      char label[24];
      std::snprintf(label, sizeof label, "T%zu", i);
      markers.push_back({report_.changes[i].time, label});
    }
    nc::write_svg(svg, nc::svg_plot(time_, panels, options, markers));
    return {csv, svg};
  }

  std::string summary() const {
    const Example& e = main_.example;
    std::string out = e.title;
    out += " (seed 004): ";
    out += ok() ? "ok\n" : "FAILED\n";
    char line[256];
    for (std::size_t i = 0; i < report_.changes.size(); ++i) {
      const Change& c = report_.changes[i];
      std::snprintf(line, sizeof line,
                    "  T%zu %.3f s at %.4f mm: nControlByte 0x%02X, nAxisState %u\n", i, c.time,
                    c.position, static_cast<unsigned>(c.control),
                    static_cast<unsigned>(c.axis_state));
      out += line;
    }
    if (report_.stop_time >= 0.0) {
      std::snprintf(line, sizeof line, "  MC_Stop %.3f s at %.4f mm\n", report_.stop_time,
                    report_.stop_position);
      out += line;
    }
    out += "  nAxisState";
    for (const uint32_t s : report_.sequence) {
      out += ' ';
      out += std::to_string(s);
    }
    std::snprintf(line, sizeof line, "\n  end %.4f mm (highest %.4f mm), simulated %.3f s\n",
                  report_.final_position, report_.highest, report_.end_time);
    out += line;
    if (report_.error_id != 0 || report_.axis_error != 0) {
      out += sample_common::error_line("block", report_.error_id, report_.axis_error,
                                       state_name(main_.state));
    }
    return out;
  }

  const Report& report() const noexcept { return report_; }
  const Main& program() const noexcept { return main_; }
  const plc::AXIS_REF& axis() const noexcept { return axis_; }

 private:
  // The scope task: what the last NC cycle published (within the reserve: no allocation).
  void record() noexcept {
    if (time_.size() == time_.capacity()) return;
    const plc::NCTOPLC_AXIS_REF& nc = axis_.NcToPlc;
    const double now = kernel_.time();
    time_.push_back(now);
    position_.push_back(nc.ActPos);
    set_velocity_.push_back(nc.SetVelo);
    velocity_.push_back(nc.ActVelo);
    state_.push_back(static_cast<double>(nc.AxisState));
    for (std::size_t k = 0; k < kBitCount; ++k) {
      const double on = plc::bit_set(image_.nControlByte, kBits[k].bit) ? 1.0 : 0.0;
      bits_[k].push_back(static_cast<double>(k) * kBitSpacing + on);
    }
    controls_.push_back(image_);
    report_.consistent = report_.consistent && plc::control_bytes_consistent(image_);
    report_.highest = time_.size() == 1 ? nc.ActPos : std::max(report_.highest, nc.ActPos);
    if (controls_.size() > 1 &&
        controls_[controls_.size() - 2].nControlByte != image_.nControlByte &&
        report_.changes.size() < report_.changes.capacity()) {
      report_.changes.push_back({now, nc.ActPos, image_.nControlByte, nc.AxisState});
    }
    if ((report_.sequence.empty() || report_.sequence.back() != nc.AxisState) &&
        report_.sequence.size() < report_.sequence.capacity()) {
      report_.sequence.push_back(nc.AxisState);
    }
    const uint8_t rapid = plc::bit_mask(plc::ControlByteBit::bPlusHigh) |
                          plc::bit_mask(plc::ControlByteBit::bMinusHigh);
    if (report_.stop_time >= 0.0 && now > report_.stop_time && (image_.nControlByte & rapid) != 0)
      report_.rapid_after_stop = true;
  }

  void plc_cycle() noexcept {
    const bool stopping = main_.state == State::STATE_STOP;
    main_(axis_);
    if (!stopping && main_.state == State::STATE_STOP) {
      report_.stop_time = kernel_.time();
      report_.stop_position = axis_.NcToPlc.ActPos;
    }
    report_.move_aborted = report_.move_aborted || main_.Move.CommandAborted;
  }

  void write_csv(const std::filesystem::path& path) const {
    if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
    std::ofstream out(path);
    out << "time,ActPos,SetVelo,ActVelo,nAxisState,nControlByte,nExtControlByte";
    for (const BitTrace& b : kBits)
      out << ',' << b.label;
    out << '\n';
    char line[256];
    for (std::size_t i = 0; i < time_.size(); ++i) {
      const plc::NCTOIO_DRIVE_TWO_SPEED& image = controls_[i];
      std::snprintf(line, sizeof line, "%.3f,%.6f,%.3f,%.6f,%.0f,%u,%u", time_[i], position_[i],
                    set_velocity_[i], velocity_[i], state_[i],
                    static_cast<unsigned>(image.nControlByte),
                    static_cast<unsigned>(image.nExtControlByte));
      out << line;
      for (const BitTrace& b : kBits)
        out << ',' << (plc::bit_set(image.nControlByte, b.bit) ? 1 : 0);
      out << '\n';
    }
    if (!out) {
      std::string message = "cannot write ";
      message += path.string();
      throw std::runtime_error(message);
    }
  }

  nc::Kernel kernel_;
  plc::AXIS_REF& axis_;
  const plc::NCTOIO_DRIVE_TWO_SPEED& image_;
  nc::CycleDriver driver_;
  Options options_;
  Main main_;
  Report report_;
  std::vector<double> time_, position_, set_velocity_, velocity_, state_;
  std::vector<double> bits_[kBitCount];
  std::vector<plc::NCTOIO_DRIVE_TWO_SPEED> controls_;
};

}  // namespace two_speed_positioning
