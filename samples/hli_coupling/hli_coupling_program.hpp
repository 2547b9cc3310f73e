// HLI axis coupling (seed 002 §3 and §4, P-AXIS-00460) reproduced with a PLC program that writes
// the seed's lines into the mirrored control unit: gpAx[axis_idx]^.lr_mc_control.axis_coupling
// … becomes gpAx[axis_idx]->lr_mc_control.axis_coupling ….
//
// Examples 1–3: Y2 is the axis with logical axis number 8; axis 1 is X. The PLC couples Y2, moves
// X from 0 to 900 mm, then commands a PTP move of Y2 (its program) to 100 mm:
//   1  desc[0] = 1 DIRECT                      → Y2's drive 900 mm (the move on Y2 runs its
//                                                program only: no self entry)
//   2  desc[0] = 1 DIRECT, desc[1] = 8 DIRECT  → Y2's drive 900 + 100 = 1000 mm
//   3  desc[0] = 8 DIRECT, desc[1] = 1 FRACT −5/9 → Y2's drive −500 + 100 = −400 mm
// Forward mapping (P-AXIS-00460's example): X at 40 mm, three X1 axes at 50 mm (default,
// P-AXIS-00436, P-AXIS-00436 + 00460), each coupled 1:1 to X and to itself; the command-position
// request gives 50 / 50 / 10 right after the coupling and 70 / 50 / 10 after X moves +20 mm.
//
// Each runs on its own kernel (1 ms NC cycle, 1 ms PLC task, a scope every NC cycle). Header-only,
// so that tests/samples/test_hli_coupling_sample.cpp runs exactly what the sample runs.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "fb/mc_move_absolute.hpp"
#include "fb/mc_power.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"
#include "plc_interface/axis_ref.hpp"
#include "plc_interface/hli.hpp"
#include "sample_output.hpp"

namespace hli_coupling {

using GpAx = std::span<plc::hli::HLI_AX* const>;

inline constexpr double kXTarget = 900.0;     // mm
inline constexpr double kXVelocity = 2000.0;  // mm/s
inline constexpr double kY2Target = 100.0;    // mm, Y2's own PTP move (its program)
inline constexpr double kY2Velocity = 500.0;  // mm/s

// The seed's three coupling lists for Y2 (axis_idx y2), written as the seed writes them.
inline void write_example_1(GpAx gpAx, std::size_t y2) noexcept {
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[0].ax_nr = 1;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[0].mode = plc::hli::HLI_AXIS_COUPLING_DIRECT;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[1].ax_nr = 0;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[1].mode =
      plc::hli::HLI_AXIS_COUPLING_INACTIVE;
}
inline void write_example_2(GpAx gpAx, std::size_t y2) noexcept {
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[0].ax_nr = 1;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[0].mode = plc::hli::HLI_AXIS_COUPLING_DIRECT;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[1].ax_nr = 8;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[1].mode = plc::hli::HLI_AXIS_COUPLING_DIRECT;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[2].ax_nr = 0;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[2].mode =
      plc::hli::HLI_AXIS_COUPLING_INACTIVE;
}
inline void write_example_3(GpAx gpAx, std::size_t y2) noexcept {
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[0].ax_nr = 8;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[0].mode = plc::hli::HLI_AXIS_COUPLING_DIRECT;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[1].ax_nr = 1;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[1].mode = plc::hli::HLI_AXIS_COUPLING_FRACT;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[1].fract_num = -5;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[1].fract_denom = 9;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[2].ax_nr = 0;
  gpAx[y2]->lr_mc_control.axis_coupling.command_w.desc[2].mode =
      plc::hli::HLI_AXIS_COUPLING_INACTIVE;
}

// One of the seed's examples: how the PLC writes the list, and the drive position Y2 ends at.
struct Example {
  const char* name;   // file stem
  const char* title;  // the seed's heading
  void (*write)(GpAx, std::size_t) noexcept;
  std::size_t entries;    // couplings the list holds (state_r.desc shows them)
  double expected_drive;  // Y2's NcToPlc.SetPos at the end, mm
};

inline constexpr Example kExamples[] = {
    {"hli_example_1_direct", "Example 1: Y2 cannot be moved by the NC program", write_example_1, 1,
     kXTarget},
    {"hli_example_2_direct_self", "Example 2: Y2 is moved by the NC program", write_example_2, 2,
     kXTarget + kY2Target},
    {"hli_example_3_fract", "Example 3: Y2 with coupling factor -5/9", write_example_3, 2,
     -5.0 / 9.0 * kXTarget + kY2Target},
};

enum class State {
  STATE_INIT,      // wait for MC_Power's Status on every axis
  STATE_POSITION,  // forward mapping only: X to 40 mm, the X1 axes to 50 mm
  STATE_COUPLE,    // write the lists, set semaphor_rw
  STATE_COUPLED,   // wait until the NC has reset semaphor_rw; error_r tells the outcome
  STATE_MOVE_X,    // X moves (to 900 mm; forward mapping: +20 mm)
  STATE_MOVE_Y2,   // examples: Y2's own PTP move to 100 mm
  STATE_FINISHED,
  STATE_ERROR,
};

inline const char* state_name(State state) noexcept {
  switch (state) {
    case State::STATE_INIT:
      return "STATE_INIT";
    case State::STATE_POSITION:
      return "STATE_POSITION";
    case State::STATE_COUPLE:
      return "STATE_COUPLE";
    case State::STATE_COUPLED:
      return "STATE_COUPLED";
    case State::STATE_MOVE_X:
      return "STATE_MOVE_X";
    case State::STATE_MOVE_Y2:
      return "STATE_MOVE_Y2";
    case State::STATE_FINISHED:
      return "STATE_FINISHED";
    case State::STATE_ERROR:
      return "STATE_ERROR";
  }
  return "?";
}

// PROGRAM MAIN over `n` axes (index 0 = X, the others coupled), one call per PLC cycle. The list
// writer and the moves are what differs between the examples and the forward mapping.
template <std::size_t N>
struct Main {
  std::array<fb::MC_Power, N> Power;
  std::array<fb::MC_MoveAbsolute, N> Move;
  State state = State::STATE_INIT;
  uint32_t error_id = 0;
  int semaphore_cycles = 0;  // PLC cycles from setting semaphor_rw until it is seen reset

  // Runs the blocks; `plan` is the step chain (the only part that differs).
  template <class Plan>
  void operator()(std::array<plc::AXIS_REF*, N>& axes, GpAx gpAx, Plan&& plan) noexcept {
    for (fb::MC_Power& p : Power)
      p.Enable = p.Enable_Positive = p.Enable_Negative = true;
    for (std::size_t i = 0; i < N; ++i)
      Power[i](*axes[i]);
    plan(*this, gpAx);
    for (std::size_t i = 0; i < N; ++i)
      Move[i](*axes[i]);
    for (std::size_t i = 0; i < N; ++i) {
      const bool failed = Power[i].Error || Move[i].Error ||
                          gpAx[i]->lr_mc_control.axis_coupling.state_r.error_r != 0;
      if (failed && state != State::STATE_ERROR) {
        error_id = Power[i].Error  ? Power[i].ErrorID
                   : Move[i].Error ? Move[i].ErrorID
                                   : gpAx[i]->lr_mc_control.axis_coupling.state_r.error_r;
        state = State::STATE_ERROR;
      }
    }
  }

  bool powered() const noexcept {
    for (const fb::MC_Power& p : Power) {
      if (!p.Status) return false;
    }
    return true;
  }
  // Starts MC_MoveAbsolute on axis i (Execute's rising edge in this call).
  void start(std::size_t i, double position, double velocity) noexcept {
    Move[i].Position = position;
    Move[i].Velocity = velocity;
    Move[i].Execute = true;
  }
  // True once axis i's move is Done; Execute falls then (the next start is a new edge).
  bool done(std::size_t i) noexcept {
    if (!Move[i].Done) return false;
    Move[i].Execute = false;
    return true;
  }
  // done() for every axis at once (each block shows Done only until Execute falls).
  bool all_done() noexcept {
    for (const fb::MC_MoveAbsolute& m : Move) {
      if (!m.Done) return false;
    }
    for (fb::MC_MoveAbsolute& m : Move)
      m.Execute = false;
    return true;
  }
  // The handshake: true once the NC has reset every given axis's semaphore.
  bool semaphores_reset(GpAx gpAx, std::span<const std::size_t> targets) noexcept {
    ++semaphore_cycles;
    for (std::size_t i : targets) {
      if (gpAx[i]->lr_mc_control.axis_coupling.command_w.semaphor_rw) return false;
    }
    return true;
  }
};

struct Options {
  double nc_cycle = 0.001;   // s; the PLC task runs with it
  double timeout = 10.0;     // s of simulated time
  double settle_time = 0.2;  // s recorded after the program finished
};

// The sample axes: the seed's Dynamics 1.1 parameters and the other samples' lagging drive.
inline nc::AxisConfig sample_axis(const char* name, int ax_nr) {
  nc::AxisConfig config;
  config.name = name;
  config.id = ax_nr;
  config.max_velocity = 2200.0;
  config.ref_velocity = 2200.0;
  sample_common::use_lagging_drive(config, 5.0);
  return config;
}

// What each sample owns: a kernel with N axes (index 0 = X), the cycle driver with the scope
// task and the PLC task (in that order, every NC cycle), the scope and PROGRAM MAIN.
template <std::size_t N>
class Bench {
 public:
  Bench(const Bench&) = delete;
  Bench& operator=(const Bench&) = delete;

  const nc::Scope& scope() const noexcept { return scope_; }
  const nc::Kernel& kernel() const noexcept { return kernel_; }

 protected:
  explicit Bench(const Options& options)
      : kernel_(nc::KernelConfig{options.nc_cycle}),
        driver_(kernel_),
        scope_(sample_common::scope_capacity(options)),
        options_(options) {}
  ~Bench() = default;

  // Set-up, once the axes and the scope's channels are there.
  void add_tasks(std::function<void()> sample, std::function<void()> plc) {
    driver_.add_task("Scope", options_.nc_cycle, std::move(sample));
    driver_.add_task("PlcTask", options_.nc_cycle, std::move(plc));
  }
  // Runs until MAIN finishes (then settles) or fails, or the timeout; true when it finished.
  bool run_program() {
    return sample_common::run_to_state(driver_, main_.state, State::STATE_FINISHED,
                                       State::STATE_ERROR, options_.timeout, options_.settle_time);
  }

  nc::Kernel kernel_;
  std::array<plc::AXIS_REF*, N> axes_{};
  nc::CycleDriver driver_;
  nc::Scope scope_;
  Options options_;
  Main<N> main_;
};

// ------------------------------------------------------------------------------------------
// Examples 1–3.

struct ExampleReport {
  bool finished = false;
  uint32_t error_id = 0;
  int semaphore_cycles = 0;  // 1: the NC reset it in the cycle that evaluated the list
  bool active = false;       // state_r.active_r after the coupling
  std::array<plc::hli::HLI_AX_COUPLING_STATE_DESC, 8> in_force{};  // state_r.desc then
  uint32_t couple_state_x = 0;  // NcToPlc.CoupleState after the coupling
  uint32_t couple_state_y2 = 0;
  double y2_drive_after_x = 0.0;   // Y2's SetPos when X's move is Done, mm
  double y2_program_target = 0.0;  // Y2's TargetPos at the end (its program), mm
  double final_x = 0.0;            // X's SetPos at the end, mm
  double final_y2 = 0.0;           // Y2's SetPos (drive d) at the end, mm
  double final_y2_actual = 0.0;    // mm
  int32_t max_active_rev = 0;      // max |lr_state.active_rev_r|, 1e-3 mm/s
  double max_following_error = 0.0;
  uint32_t axis_error = 0;
  double end_time = 0.0;
};

inline bool example_ok(const Example& example, const ExampleReport& r) noexcept {
  return r.finished && r.error_id == 0 && r.axis_error == 0 && r.semaphore_cycles == 1 &&
         r.active && r.in_force[example.entries - 1].ax_nr != 0 &&
         (example.entries == 8 || r.in_force[example.entries].ax_nr == 0) &&
         std::fabs(r.final_x - kXTarget) <= 1e-9 &&
         std::fabs(r.final_y2 - example.expected_drive) <= 1e-9;
}

class ExampleSample : public Bench<2> {
 public:
  static constexpr std::size_t kX = 0;
  static constexpr std::size_t kY2 = 1;

  explicit ExampleSample(const Example& example, const Options& options = {})
      : Bench<2>(options), example_(example) {
    axes_[kX] = &kernel_.add_axis(sample_axis("X", 1));
    axes_[kY2] = &kernel_.add_axis(sample_axis("Y2", 8));
    scope_.add_motion_signals(*axes_[kX], "X");
    scope_.add_motion_signals(*axes_[kY2], "Y2");
    scope_.add_variable(&y2_active_rev_, "Y2.active_rev_r", "mm/s");
    add_tasks([this] { sample(); }, [this] { plc_cycle(); });
  }

  const ExampleReport& run() {
    report_.finished = run_program();
    sample();
    report_.error_id = main_.error_id;
    report_.semaphore_cycles = main_.semaphore_cycles;
    report_.final_x = axes_[kX]->NcToPlc.SetPos;
    report_.final_y2 = axes_[kY2]->NcToPlc.SetPos;
    report_.final_y2_actual = axes_[kY2]->NcToPlc.ActPos;
    report_.y2_program_target = axes_[kY2]->NcToPlc.TargetPos;
    report_.axis_error = axes_[kX]->NcToPlc.ErrorCode | axes_[kY2]->NcToPlc.ErrorCode;
    report_.end_time = kernel_.time();
    return report_;
  }

  bool ok() const noexcept { return example_ok(example_, report_); }

  std::pair<std::filesystem::path, std::filesystem::path> write(
      const std::filesystem::path& dir) const {
    const auto [csv, svg] = sample_common::csv_and_svg(dir, example_.name);
    scope_.write_csv(csv);
    const auto series = [this](const char* axis, nc::Signal signal) {
      return scope_.values(scope_.find(axis, signal));
    };
    const std::vector<nc::PlotPanel> panels = {
        {"panel-position",
         "Position",
         "mm",
         {{"X.SetPos", "#00008b", series("X", nc::Signal::kSetPos), 1.5},
          {"Y2.SetPos (drive)", "#c06000", series("Y2", nc::Signal::kSetPos), 1.5},
          {"Y2.ActPos", "#f0b070", series("Y2", nc::Signal::kActPos), 1.0}}},
        {"panel-velocity",
         "Velocity",
         "mm/s",
         {{"X.SetVelo", "#00008b", series("X", nc::Signal::kSetVelo), 1.5},
          {"Y2.SetVelo", "#c06000", series("Y2", nc::Signal::kSetVelo), 1.5},
          {"Y2 active_rev_r", "#2e8b57", scope_.values(scope_.find("Y2.active_rev_r")), 1.0}}},
        {"panel-following-error",
         "Following error",
         "mm",
         {{"X.PosDiff", "#00008b", series("X", nc::Signal::kPosDiff), 1.0},
          {"Y2.PosDiff", "#c06000", series("Y2", nc::Signal::kPosDiff), 1.0}}},
    };
    char title[256];
    std::snprintf(title, sizeof title, "%s \u2014 Y2's drive ends at %.0f mm", example_.title,
                  report_.final_y2);
    nc::write_svg(svg, nc::svg_plot(scope_.time(), panels, {title, 1000, 150}));
    return {csv, svg};
  }

  std::string summary() const {
    char text[1024];
    const ExampleReport& r = report_;
    std::snprintf(text, sizeof text,
                  "%s (seed 002 3): %s\n"
                  "  list taken after %d PLC cycle(s); active_r %s; CoupleState X %u, Y2 %u\n"
                  "  X done at 900 mm: Y2's drive %.6f mm; Y2's program ends at %.3f mm\n"
                  "  end: X %.6f mm, Y2 drive %.6f mm (expected %.6f mm), Y2 actual %.4f mm\n"
                  "  max |active_rev_r| %d (1e-3 mm/s), max following error %.4f mm, "
                  "simulated %.3f s\n",
                  example_.title, ok() ? "ok" : "FAILED", r.semaphore_cycles,
                  r.active ? "TRUE" : "FALSE", static_cast<unsigned>(r.couple_state_x),
                  static_cast<unsigned>(r.couple_state_y2), r.y2_drive_after_x, r.y2_program_target,
                  r.final_x, r.final_y2, example_.expected_drive, r.final_y2_actual,
                  static_cast<int>(r.max_active_rev), r.max_following_error, r.end_time);
    std::string out = text;
    if (r.error_id != 0 || r.axis_error != 0) {
      out +=
          sample_common::error_line("block/HLI", r.error_id, r.axis_error, state_name(main_.state));
    }
    return out;
  }

 private:
  void sample() noexcept {
    const int32_t rev = kernel_.gpAx()[kY2]->lr_state.active_rev_r;
    y2_active_rev_ = 1e-3 * static_cast<double>(rev);
    scope_.record(kernel_.time());
    report_.max_active_rev = std::max(report_.max_active_rev, rev < 0 ? -rev : rev);
    sample_common::track_max(report_.max_following_error, axes_[kX]->NcToPlc.PosDiff);
    sample_common::track_max(report_.max_following_error, axes_[kY2]->NcToPlc.PosDiff);
  }

  void plc_cycle() noexcept {
    const Example& example = example_;
    ExampleReport& report = report_;
    std::array<plc::AXIS_REF*, 2>& axes = axes_;
    main_(axes_, kernel_.gpAx(), [&example, &report, &axes](Main<2>& m, GpAx gpAx) noexcept {
      static constexpr std::array<std::size_t, 1> kTargets{kY2};
      switch (m.state) {
        case State::STATE_INIT:
          if (m.powered()) m.state = State::STATE_COUPLE;
          break;
        case State::STATE_COUPLE:
          example.write(gpAx, kY2);
          gpAx[kY2]->lr_mc_control.axis_coupling.command_w.semaphor_rw = true;
          m.state = State::STATE_COUPLED;
          break;
        case State::STATE_COUPLED:
          if (m.semaphores_reset(gpAx, kTargets)) {
            const plc::hli::HLI_AX_COUPLING_STATE& s =
                gpAx[kY2]->lr_mc_control.axis_coupling.state_r;
            report.active = s.active_r;
            std::copy(s.desc.begin(), s.desc.end(), report.in_force.begin());
            report.couple_state_x = axes[kX]->NcToPlc.CoupleState;
            report.couple_state_y2 = axes[kY2]->NcToPlc.CoupleState;
            m.start(kX, kXTarget, kXVelocity);
            m.state = State::STATE_MOVE_X;
          }
          break;
        case State::STATE_MOVE_X:
          if (m.done(kX)) {
            report.y2_drive_after_x = axes[kY2]->NcToPlc.SetPos;
            m.start(kY2, kY2Target, kY2Velocity);
            m.state = State::STATE_MOVE_Y2;
          }
          break;
        case State::STATE_MOVE_Y2:
          if (m.done(kY2)) m.state = State::STATE_FINISHED;
          break;
        case State::STATE_POSITION:  // the examples start where the axes stand
        case State::STATE_FINISHED:
        case State::STATE_ERROR:
          break;
      }
    });
  }

  Example example_;
  ExampleReport report_;
  double y2_active_rev_ = 0.0;  // mm/s, what the scope records of lr_state.active_rev_r
};

// ------------------------------------------------------------------------------------------
// Forward mapping (P-AXIS-00436 / 00460, seed 002 §4).

inline constexpr double kX0 = 40.0;   // mm, X when coupled
inline constexpr double kX10 = 50.0;  // mm, every X1 when coupled
inline constexpr double kXMove = 20.0;

// The X1 axes: logical numbers 2, 3, 4; P-AXIS-00436 / 00460 as named.
struct Mapping {
  const char* name;
  int ax_nr;
  bool p436;
  bool p460;
  double expected_at_coupling;  // command-position request right after the coupling, mm
  double expected_after_move;   // … after X moved +20 mm
};

inline constexpr Mapping kMappings[] = {
    {"X1", 2, false, false, 50.0, 70.0},
    {"X1_436", 3, true, false, 50.0, 50.0},
    {"X1_436_460", 4, true, true, 10.0, 10.0},
};

struct MappingReport {
  bool finished = false;
  uint32_t error_id = 0;
  uint32_t axis_error = 0;
  std::array<double, 3> at_coupling{};  // Kernel::command_position_request, per kMappings
  std::array<double, 3> after_move{};
  std::array<double, 3> drive_after_move{};  // SetPos, mm
  double final_x = 0.0;
  double end_time = 0.0;
};

inline bool mapping_ok(const MappingReport& r) noexcept {
  if (!r.finished || r.error_id != 0 || r.axis_error != 0) return false;
  for (std::size_t k = 0; k < 3; ++k) {
    if (std::fabs(r.at_coupling[k] - kMappings[k].expected_at_coupling) > 1e-9) return false;
    if (std::fabs(r.after_move[k] - kMappings[k].expected_after_move) > 1e-9) return false;
  }
  return std::fabs(r.final_x - (kX0 + kXMove)) <= 1e-9;
}

class MappingSample : public Bench<4> {
 public:
  static constexpr const char* kName = "hli_forward_mapping";

  explicit MappingSample(const Options& options = {}) : Bench<4>(options) {
    axes_[0] = &kernel_.add_axis(sample_axis("X", 1));
    for (std::size_t k = 0; k < 3; ++k) {
      nc::AxisConfig c = sample_axis(kMappings[k].name, kMappings[k].ax_nr);
      c.recalc_link_main_input_position = kMappings[k].p436;
      c.recalc_input_position_absolute = kMappings[k].p460;
      axes_[k + 1] = &kernel_.add_axis(c);
    }
    scope_.add_signal(*axes_[0], "X", nc::Signal::kSetPos);
    for (std::size_t k = 0; k < 3; ++k) {
      scope_.add_signal(*axes_[k + 1], kMappings[k].name, nc::Signal::kSetPos);
      scope_.add_variable(&request_[k], std::string(kMappings[k].name) + ".CMDPOS", "mm");
    }
    add_tasks([this] { sample(); }, [this] { plc_cycle(); });
  }

  const MappingReport& run() {
    report_.finished = run_program();
    sample();
    report_.error_id = main_.error_id;
    for (const plc::AXIS_REF* a : axes_)
      report_.axis_error |= a->NcToPlc.ErrorCode;
    report_.final_x = axes_[0]->NcToPlc.SetPos;
    report_.end_time = kernel_.time();
    return report_;
  }

  bool ok() const noexcept { return mapping_ok(report_); }

  std::pair<std::filesystem::path, std::filesystem::path> write(
      const std::filesystem::path& dir) const {
    const auto [csv, svg] = sample_common::csv_and_svg(dir, kName);
    scope_.write_csv(csv);
    static constexpr const char* kColours[] = {"#c06000", "#2e8b57", "#8a2be2"};
    nc::PlotPanel positions{"panel-position", "Drive position (SetPos)", "mm", {}};
    nc::PlotPanel requests{"panel-request", "Command-position request", "mm", {}};
    positions.series.push_back(
        {"X.SetPos", "#00008b", scope_.values(scope_.find("X", nc::Signal::kSetPos)), 1.5});
    for (std::size_t k = 0; k < 3; ++k) {
      const std::string name = kMappings[k].name;
      positions.series.push_back({name + ".SetPos", kColours[k],
                                  scope_.values(scope_.find(name, nc::Signal::kSetPos)), 1.5});
      requests.series.push_back(
          {name + ".CMDPOS", kColours[k], scope_.values(scope_.find(name + ".CMDPOS")), 1.5});
    }
    char title[256];
    std::snprintf(title, sizeof title,
                  "Forward mapping: X1 1:1 to X and to itself; CMDPOS after X +20: %.0f / %.0f / "
                  "%.0f mm",
                  report_.after_move[0], report_.after_move[1], report_.after_move[2]);
    nc::write_svg(svg, nc::svg_plot(scope_.time(), {positions, requests}, {title, 1000, 150}));
    return {csv, svg};
  }

  std::string summary() const {
    const MappingReport& r = report_;
    std::string out = std::string("Forward mapping (seed 002 4, P-AXIS-00436/00460): ") +
                      (ok() ? "ok" : "FAILED") + "\n";
    for (std::size_t k = 0; k < 3; ++k) {
      char line[256];
      std::snprintf(line, sizeof line,
                    "  %-10s 436=%d 460=%d: request %.6f mm after coupling (expected %.0f), "
                    "%.6f mm after X +20 (expected %.0f); drive %.6f mm\n",
                    kMappings[k].name, kMappings[k].p436 ? 1 : 0, kMappings[k].p460 ? 1 : 0,
                    r.at_coupling[k], kMappings[k].expected_at_coupling, r.after_move[k],
                    kMappings[k].expected_after_move, r.drive_after_move[k]);
      out += line;
    }
    if (r.error_id != 0 || r.axis_error != 0) {
      out +=
          sample_common::error_line("block/HLI", r.error_id, r.axis_error, state_name(main_.state));
    }
    return out;
  }

 private:
  void sample() noexcept {
    for (std::size_t k = 0; k < 3; ++k)
      request_[k] = kernel_.command_position_request(kMappings[k].ax_nr);
    scope_.record(kernel_.time());
  }

  void plc_cycle() noexcept {
    MappingReport& report = report_;
    std::array<plc::AXIS_REF*, 4>& axes = axes_;
    const nc::Kernel& kernel = kernel_;
    main_(axes_, kernel_.gpAx(), [&report, &axes, &kernel](Main<4>& m, GpAx gpAx) noexcept {
      static constexpr std::array<std::size_t, 3> kTargets{1, 2, 3};
      switch (m.state) {
        case State::STATE_INIT:
          if (m.powered()) {
            m.start(0, kX0, 500.0);
            for (std::size_t i : kTargets)
              m.start(i, kX10, 500.0);
            m.state = State::STATE_POSITION;
          }
          break;
        case State::STATE_POSITION:
          if (m.all_done()) m.state = State::STATE_COUPLE;
          break;
        case State::STATE_COUPLE:
          // Each X1 (logical number kMappings[k].ax_nr) 1:1 to X and to itself.
          for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t i = k + 1;
            gpAx[i]->lr_mc_control.axis_coupling.command_w.desc[0].ax_nr = 1;
            gpAx[i]->lr_mc_control.axis_coupling.command_w.desc[0].mode =
                plc::hli::HLI_AXIS_COUPLING_DIRECT;
            gpAx[i]->lr_mc_control.axis_coupling.command_w.desc[1].ax_nr = kMappings[k].ax_nr;
            gpAx[i]->lr_mc_control.axis_coupling.command_w.desc[1].mode =
                plc::hli::HLI_AXIS_COUPLING_DIRECT;
            gpAx[i]->lr_mc_control.axis_coupling.command_w.desc[2].ax_nr = 0;
            gpAx[i]->lr_mc_control.axis_coupling.command_w.desc[2].mode =
                plc::hli::HLI_AXIS_COUPLING_INACTIVE;
            gpAx[i]->lr_mc_control.axis_coupling.command_w.semaphor_rw = true;
          }
          m.state = State::STATE_COUPLED;
          break;
        case State::STATE_COUPLED:
          if (m.semaphores_reset(gpAx, kTargets)) {
            for (std::size_t k = 0; k < 3; ++k)
              report.at_coupling[k] = kernel.command_position_request(kMappings[k].ax_nr);
            m.start(0, kX0 + kXMove, 500.0);
            m.state = State::STATE_MOVE_X;
          }
          break;
        case State::STATE_MOVE_X:
          if (m.done(0)) {
            for (std::size_t k = 0; k < 3; ++k) {
              report.after_move[k] = kernel.command_position_request(kMappings[k].ax_nr);
              report.drive_after_move[k] = axes[k + 1]->NcToPlc.SetPos;
            }
            m.state = State::STATE_FINISHED;
          }
          break;
        case State::STATE_MOVE_Y2:
        case State::STATE_FINISHED:
        case State::STATE_ERROR:
          break;
      }
    });
  }

  MappingReport report_;
  std::array<double, 3> request_{};  // what the scope records of the requests
};

}  // namespace hli_coupling
