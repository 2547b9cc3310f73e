// Error propagation with PLC blocks (seed 000 §3.1 "Advanced NC error handling for coupled axes",
// SPEC C7 DELAYED): the user's own error reaction inside the propagation delay.
//
// A master with two slaves coupled at rest: Faulty (MC_GearIn 1/1) and Healthy (1/2). The master
// runs 0 → 20000 mm at 1000 mm/s. Faulty's drive saturates at 900 mm/s, so once the master
// cruises its following error grows by 100 mm/s and after 5 mm for 20 ms it raises 0x4550.
// Faulty is configured DELAYED with 0.5 s: only Faulty reacts (it leaves the coupling and stops on
// its emergency ramp), showing StateDWord bits 31 (Error) and 6 (ErrorPropagationDelayed). The
// PLC sees bit 6, waits 0.2 s (its decision time) and decouples Healthy with MC_GearOut in
// motion: Healthy goes on as a master at 500 mm/s. When the delay has run out the group reaction
// stops what is left of the group — the master, on its emergency ramp, with Faulty's code — and
// bit 6 is reset; Healthy is not touched, and the PLC halts it with MC_Halt. Finally MC_Reset on
// the master and Faulty, and MC_GearOut takes Faulty's link (kept until then) out of the group.
//
// ErrorPropagationSample runs the program on simulated axes (1 ms NC cycle, 1 ms PLC task, a
// scope every NC cycle). Header-only, so that tests/samples/test_error_propagation_sample.cpp
// runs exactly what the sample program runs.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "fb/mc_gear_in.hpp"
#include "fb/mc_gear_out.hpp"
#include "fb/mc_halt.hpp"
#include "fb/mc_move_absolute.hpp"
#include "fb/mc_power.hpp"
#include "fb/mc_reset.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"
#include "plc_interface/axis_ref.hpp"
#include "sample_output.hpp"

namespace error_propagation {

inline constexpr double kTarget = 20000.0;        // mm, the master's end position
inline constexpr double kVelocity = 1000.0;       // mm/s, the master's V
inline constexpr double kFaultyDriveMax = 900.0;  // mm/s, where Faulty's drive saturates
inline constexpr double kDelay = 0.5;             // s, Faulty's error_propagation_delay
inline constexpr double kDecisionTime = 0.2;      // s, bit 6 seen → MC_GearOut of Healthy
inline constexpr double kPlcPeriod = 0.001;       // s

enum class PropagationState {
  STATE_INIT,              // wait for the three MC_Power's Status
  STATE_GEAR_IN,           // both slaves' MC_GearIn on the master, wait for InGear
  STATE_RUN,               // master started; wait for Faulty's bit 6 (ErrorPropagationDelayed)
  STATE_DECIDE,            // the PLC's decision time
  STATE_DECOUPLE_HEALTHY,  // MC_GearOut on Healthy, in motion
  STATE_WAIT_GROUP,        // until the group reaction reaches the master
  STATE_HALT_HEALTHY,      // MC_Halt on Healthy; and the master at rest
  STATE_RESET,             // MC_Reset of the master and Faulty
  STATE_RELEASE_FAULTY,    // MC_GearOut on Faulty: its link leaves the group
  STATE_FINISHED,
  STATE_ERROR,
};

inline const char* state_name(PropagationState state) noexcept {
  switch (state) {
    case PropagationState::STATE_INIT:
      return "STATE_INIT";
    case PropagationState::STATE_GEAR_IN:
      return "STATE_GEAR_IN";
    case PropagationState::STATE_RUN:
      return "STATE_RUN";
    case PropagationState::STATE_DECIDE:
      return "STATE_DECIDE";
    case PropagationState::STATE_DECOUPLE_HEALTHY:
      return "STATE_DECOUPLE_HEALTHY";
    case PropagationState::STATE_WAIT_GROUP:
      return "STATE_WAIT_GROUP";
    case PropagationState::STATE_HALT_HEALTHY:
      return "STATE_HALT_HEALTHY";
    case PropagationState::STATE_RESET:
      return "STATE_RESET";
    case PropagationState::STATE_RELEASE_FAULTY:
      return "STATE_RELEASE_FAULTY";
    case PropagationState::STATE_FINISHED:
      return "STATE_FINISHED";
    case PropagationState::STATE_ERROR:
      return "STATE_ERROR";
  }
  return "?";
}

inline bool state_bit(const plc::AXIS_REF& axis, plc::StateBit bit) noexcept {
  return plc::test_bit(axis.NcToPlc.StateDWord, bit);
}

// PROGRAM MAIN, one call per PLC cycle. A cycle function. The axis errors are expected here
// (Faulty's own, the master's by the group reaction); a program error is a refused block of the
// error reaction (MC_GearOut, MC_Halt, MC_Reset) or a coupling that does not engage.
struct Main {
  fb::MC_Power PowerMaster, PowerFaulty, PowerHealthy;
  fb::MC_GearIn GearFaulty, GearHealthy;
  fb::MC_MoveAbsolute Move;
  fb::MC_GearOut GearOutHealthy, GearOutFaulty;
  fb::MC_Halt HaltHealthy;
  fb::MC_Reset ResetMaster, ResetFaulty;
  PropagationState state = PropagationState::STATE_INIT;
  uint32_t error_id = 0;
  long cycles_in_state = 0;  // PLC cycles since the state was entered

  void operator()(plc::AXIS_REF& master, plc::AXIS_REF& faulty, plc::AXIS_REF& healthy) noexcept {
    for (fb::MC_Power* p : {&PowerMaster, &PowerFaulty, &PowerHealthy})
      p->Enable = p->Enable_Positive = p->Enable_Negative = true;
    const PropagationState before = state;
    switch (state) {
      case PropagationState::STATE_INIT:
        if (PowerMaster.Status && PowerFaulty.Status && PowerHealthy.Status) {
          state = PropagationState::STATE_GEAR_IN;
        }
        break;
      case PropagationState::STATE_GEAR_IN:
        GearFaulty.RatioNumerator = 1.0;
        GearFaulty.RatioDenominator = 1;
        GearHealthy.RatioNumerator = 1.0;
        GearHealthy.RatioDenominator = 2;
        GearFaulty.Execute = GearHealthy.Execute = true;
        if (GearFaulty.InGear && GearHealthy.InGear) state = PropagationState::STATE_RUN;
        break;
      case PropagationState::STATE_RUN:
        Move.Execute = true;
        if (state_bit(faulty, plc::kStateErrorPropagationDelayed)) {
          state = PropagationState::STATE_DECIDE;
        }
        break;
      case PropagationState::STATE_DECIDE:
        if (elapsed(kDecisionTime)) state = PropagationState::STATE_DECOUPLE_HEALTHY;
        break;
      case PropagationState::STATE_DECOUPLE_HEALTHY:
        GearOutHealthy.Execute = true;
        if (GearOutHealthy.Done) state = PropagationState::STATE_WAIT_GROUP;
        break;
      case PropagationState::STATE_WAIT_GROUP:
        if (state_bit(master, plc::kStateError)) state = PropagationState::STATE_HALT_HEALTHY;
        break;
      case PropagationState::STATE_HALT_HEALTHY:
        HaltHealthy.Execute = true;
        if (HaltHealthy.Done && master.NcToPlc.SetVelo == 0.0) {
          state = PropagationState::STATE_RESET;
        }
        break;
      case PropagationState::STATE_RESET:
        ResetMaster.Execute = ResetFaulty.Execute = true;
        if (ResetMaster.Done && ResetFaulty.Done) state = PropagationState::STATE_RELEASE_FAULTY;
        break;
      case PropagationState::STATE_RELEASE_FAULTY:
        GearOutFaulty.Execute = true;
        if (GearOutFaulty.Done) state = PropagationState::STATE_FINISHED;
        break;
      case PropagationState::STATE_FINISHED:
      case PropagationState::STATE_ERROR:
        break;
    }
    cycles_in_state = state == before ? cycles_in_state + 1 : 0;

    PowerMaster(master);
    PowerFaulty(faulty);
    PowerHealthy(healthy);
    GearFaulty(master, faulty);
    GearHealthy(master, healthy);
    Move.Position = kTarget;
    Move.Velocity = kVelocity;
    Move(master);
    GearOutHealthy(healthy);
    GearOutFaulty(faulty);
    HaltHealthy(healthy);
    ResetMaster(master);
    ResetFaulty(faulty);
    if (const uint32_t id = first_error(); id != 0) {
      error_id = id;
      state = PropagationState::STATE_ERROR;
    }
  }

 private:
  bool elapsed(double seconds) const noexcept {
    return static_cast<double>(cycles_in_state) * kPlcPeriod >= seconds;
  }
  uint32_t first_error() const noexcept {
    for (const fb::MC_GearOut* g : {&GearOutHealthy, &GearOutFaulty})
      if (g->Error) return g->ErrorID;
    if (HaltHealthy.Error) return HaltHealthy.ErrorID;
    for (const fb::MC_Reset* r : {&ResetMaster, &ResetFaulty})
      if (r->Error) return r->ErrorID;
    if (state == PropagationState::STATE_GEAR_IN) {
      for (const fb::MC_GearIn* g : {&GearFaulty, &GearHealthy})
        if (g->Error) return g->ErrorID;
    }
    return 0;
  }
};

// What the run showed, for the summary and the test. Times in NC cycles since the start.
struct Report {
  bool finished = false;
  uint32_t error_id = 0;
  long faulty_error_cycle = -1;     // first cycle with Faulty's bit 31
  bool bits_together = false;       // bit 6 set in that same cycle
  uint32_t faulty_code = 0;         // Faulty's ErrorCode then
  long delayed_bit_off_cycle = -1;  // first cycle after it without bit 6
  long master_error_cycle = -1;     // first cycle with the master's bit 31 (the group reaction)
  uint32_t master_code = 0;
  long healthy_decoupled_cycle = -1;      // first cycle with Healthy's CoupleState 0
  double master_velo_before_group = 0.0;  // master SetVelo in the cycle before the reaction
  double healthy_velo_at_group = 0.0;     // Healthy's SetVelo in the cycle of the reaction
  uint32_t healthy_errors = 0;            // or-ed Healthy ErrorCode over the run
  double healthy_end_velo = -1.0;
  double master_end_velo = -1.0;
  uint32_t end_errors = 0;                // or-ed ErrorCode of all three at the end
  uint32_t end_couple[3] = {99, 99, 99};  // CoupleState at the end
  double end_time = 0.0;
};

struct Options {
  double nc_cycle = 0.001;   // s; the PLC task runs with it (kPlcPeriod)
  double timeout = 20.0;     // s of simulated time
  double settle_time = 0.2;  // s recorded after the end
};

inline nc::AxisConfig sample_axis_config(const char* name) {
  nc::AxisConfig config;
  config.name = name;
  sample_common::use_lagging_drive(config, 5.0);
  return config;
}

inline nc::AxisConfig faulty_axis_config() {
  nc::AxisConfig config = sample_axis_config("Faulty");
  config.drive_max_velocity = kFaultyDriveMax;
  config.error_propagation_mode = nc::ErrorPropagation::kDelayed;
  config.error_propagation_delay = kDelay;
  return config;
}

class ErrorPropagationSample {
 public:
  static constexpr const char* kNames[3] = {"Master", "Faulty", "Healthy"};

  explicit ErrorPropagationSample(const Options& options = {})
      : kernel_(nc::KernelConfig{options.nc_cycle}),
        master_(kernel_.add_axis(sample_axis_config(kNames[0]))),
        faulty_(kernel_.add_axis(faulty_axis_config())),
        healthy_(kernel_.add_axis(sample_axis_config(kNames[2]))),
        driver_(kernel_),
        scope_(sample_common::scope_capacity(options)),
        options_(options) {
    for (int i = 0; i < 3; ++i) {
      scope_.add_signal(*axes_[i], kNames[i], nc::Signal::kSetPos);
      scope_.add_signal(*axes_[i], kNames[i], nc::Signal::kSetVelo);
      scope_.add_signal(*axes_[i], kNames[i], nc::Signal::kCoupleState);
      scope_.add_variable(&error_bit_[i], std::string(kNames[i]) + ".Error", "");
      scope_.add_variable(&delayed_bit_[i], std::string(kNames[i]) + ".ErrorPropagationDelayed",
                          "");
    }
    driver_.add_task("Scope", options.nc_cycle, [this] { sample(); });
    driver_.add_task("PlcTask", options.nc_cycle, [this] { plc_cycle(); });
  }

  ErrorPropagationSample(const ErrorPropagationSample&) = delete;
  ErrorPropagationSample& operator=(const ErrorPropagationSample&) = delete;

  const Report& run() {
    report_.finished = sample_common::run_to_state(
        driver_, main_.state, PropagationState::STATE_FINISHED, PropagationState::STATE_ERROR,
        options_.timeout, options_.settle_time);
    sample();
    Report& r = report_;
    r.error_id = main_.error_id;
    r.healthy_end_velo = healthy_.NcToPlc.SetVelo;
    r.master_end_velo = master_.NcToPlc.SetVelo;
    for (int i = 0; i < 3; ++i) {
      r.end_errors |= axes_[i]->NcToPlc.ErrorCode;
      r.end_couple[i] = axes_[i]->NcToPlc.CoupleState;
    }
    r.end_time = kernel_.time();
    return report_;
  }

  // The delay to the cycle: the group reaction round(0.5 s / 1 ms) = 500 cycles after the cycle
  // in which Faulty's bit 31 first showed (with bit 6 in the same cycle), bit 6 off from then on;
  // Faulty's code 0x4550 on the master; Healthy decoupled before it and never in error, still at
  // 500 mm/s when the master is stopped; at the end everything at rest, no error, Faulty single.
  bool ok() const noexcept {
    const Report& r = report_;
    const long delay_cycles = std::lround(kDelay / options_.nc_cycle);
    return r.finished && r.error_id == 0 && r.faulty_error_cycle > 0 && r.bits_together &&
           r.faulty_code == plc::to_id(plc::ErrorCode::kFollowingErrorPosition) &&
           r.master_error_cycle - r.faulty_error_cycle == delay_cycles &&
           r.delayed_bit_off_cycle == r.master_error_cycle && r.master_code == r.faulty_code &&
           r.healthy_decoupled_cycle > r.faulty_error_cycle &&
           r.healthy_decoupled_cycle < r.master_error_cycle &&
           std::fabs(r.master_velo_before_group - kVelocity) <= 1e-6 &&
           std::fabs(r.healthy_velo_at_group - 0.5 * kVelocity) <= 1e-6 && r.healthy_errors == 0 &&
           r.healthy_end_velo == 0.0 && r.master_end_velo == 0.0 && r.end_errors == 0 &&
           r.end_couple[0] == 0 && r.end_couple[1] == 0 && r.end_couple[2] == 0;
  }

  // After-run: <dir>/error_propagation.csv and .svg (set position and velocity, CoupleState, and
  // the Error and ErrorPropagationDelayed bits of all three axes).
  std::pair<std::filesystem::path, std::filesystem::path> write(
      const std::filesystem::path& dir) const {
    const auto [csv, svg] = sample_common::csv_and_svg(dir, "error_propagation");
    scope_.write_csv(csv);
    const char* colours[3] = {"#00008b", "#8b0000", "#006400"};
    std::vector<nc::PlotPanel> panels;
    const auto axis_panel = [&](const char* id, const char* title, const char* unit,
                                nc::Signal signal) {
      nc::PlotPanel panel{id, title, unit, {}};
      for (int i = 0; i < 3; ++i) {
        panel.series.push_back(
            {kNames[i], colours[i], scope_.values(scope_.find(kNames[i], signal)), 1.5});
      }
      panels.push_back(std::move(panel));
    };
    const auto bit_panel = [&](const char* id, const char* title, const char* suffix) {
      nc::PlotPanel panel{id, title, "", {}};
      for (int i = 0; i < 3; ++i) {
        const std::string name = std::string(kNames[i]) + suffix;
        panel.series.push_back({kNames[i], colours[i], scope_.values(scope_.find(name)), 1.5});
      }
      panels.push_back(std::move(panel));
    };
    axis_panel("panel-position", "Set position", "mm", nc::Signal::kSetPos);
    axis_panel("panel-velocity", "Set velocity", "mm/s", nc::Signal::kSetVelo);
    bit_panel("panel-error", "StateDWord bit 31 Error", ".Error");
    bit_panel("panel-delayed", "StateDWord bit 6 ErrorPropagationDelayed",
              ".ErrorPropagationDelayed");
    axis_panel("panel-couple-state", "CoupleState", "", nc::Signal::kCoupleState);
    nc::write_svg(svg, nc::svg_plot(scope_.time(), panels,
                                    {"Error propagation DELAYED 0.5 s: Faulty's following error "
                                     "stops only Faulty; the PLC decouples Healthy after 0.2 s; "
                                     "the group reaction stops the master",
                                     1000, 150}));
    return {csv, svg};
  }

  std::string summary() const {
    const Report& r = report_;
    const double t = options_.nc_cycle;
    char line[512];
    std::snprintf(
        line, sizeof line,
        "Error propagation (seed 000 3.1, DELAYED %.1f s): %s\n"
        "  Faulty error 0x%X at %.3f s (bits 31 and 6 together: %s)\n"
        "  Healthy decoupled at %.3f s, at %.3f mm/s when the group reacted\n"
        "  group reaction on the master (0x%X) at %.3f s = %ld cycles later; bit 6 off at %.3f s\n"
        "  end: master %.3f, Faulty %.3f, Healthy %.3f mm; CoupleState %u %u %u; simulated "
        "%.3f s\n",
        kDelay, ok() ? "ok" : "FAILED", static_cast<unsigned>(r.faulty_code),
        static_cast<double>(r.faulty_error_cycle) * t, r.bits_together ? "yes" : "no",
        static_cast<double>(r.healthy_decoupled_cycle) * t, r.healthy_velo_at_group,
        static_cast<unsigned>(r.master_code), static_cast<double>(r.master_error_cycle) * t,
        r.master_error_cycle - r.faulty_error_cycle,
        static_cast<double>(r.delayed_bit_off_cycle) * t, master_.NcToPlc.SetPos,
        faulty_.NcToPlc.SetPos, healthy_.NcToPlc.SetPos, static_cast<unsigned>(r.end_couple[0]),
        static_cast<unsigned>(r.end_couple[1]), static_cast<unsigned>(r.end_couple[2]), r.end_time);
    std::string out = line;
    if (r.error_id != 0) {
      out += sample_common::error_line("block", r.error_id, r.end_errors, state_name(main_.state));
    }
    return out;
  }

  const nc::Scope& scope() const noexcept { return scope_; }
  const Report& report() const noexcept { return report_; }

 private:
  // The scope task, every NC cycle: the bits as 0 / 1, then the recording; and what the report
  // needs, by cycle.
  void sample() noexcept {
    for (int i = 0; i < 3; ++i) {
      error_bit_[i] = state_bit(*axes_[i], plc::kStateError) ? 1.0 : 0.0;
      delayed_bit_[i] = state_bit(*axes_[i], plc::kStateErrorPropagationDelayed) ? 1.0 : 0.0;
    }
    scope_.record(kernel_.time());
    const auto cycle = static_cast<long>(kernel_.cycle_count());
    Report& r = report_;
    if (r.faulty_error_cycle < 0 && error_bit_[1] != 0.0) {
      r.faulty_error_cycle = cycle;
      r.bits_together = delayed_bit_[1] != 0.0;
      r.faulty_code = faulty_.NcToPlc.ErrorCode;
    }
    if (r.faulty_error_cycle >= 0 && r.delayed_bit_off_cycle < 0 && delayed_bit_[1] == 0.0) {
      r.delayed_bit_off_cycle = cycle;
    }
    if (r.master_error_cycle < 0) {
      if (error_bit_[0] != 0.0) {
        r.master_error_cycle = cycle;
        r.master_code = master_.NcToPlc.ErrorCode;
        r.healthy_velo_at_group = healthy_.NcToPlc.SetVelo;
      } else {
        r.master_velo_before_group = master_.NcToPlc.SetVelo;
      }
    }
    if (r.faulty_error_cycle >= 0 && r.healthy_decoupled_cycle < 0 &&
        healthy_.NcToPlc.CoupleState == 0U) {
      r.healthy_decoupled_cycle = cycle;
    }
    r.healthy_errors |= healthy_.NcToPlc.ErrorCode;
  }

  void plc_cycle() noexcept { main_(master_, faulty_, healthy_); }

  nc::Kernel kernel_;
  plc::AXIS_REF& master_;
  plc::AXIS_REF& faulty_;
  plc::AXIS_REF& healthy_;
  const plc::AXIS_REF* axes_[3] = {&master_, &faulty_, &healthy_};
  nc::CycleDriver driver_;
  nc::Scope scope_;
  Options options_;
  Main main_;
  Report report_;
  double error_bit_[3] = {0.0, 0.0, 0.0};    // StateDWord bit 31 as 0 / 1, for the scope
  double delayed_bit_[3] = {0.0, 0.0, 0.0};  // bit 6
};

}  // namespace error_propagation
