// A cyclic slave with PLC blocks (seed 000 §3.3, SPEC C6): the slave's coupling factor follows a
// PLC signal — here a simulated tension sensor — and the NC smooths it within AccBound.
//
// Master and Slave are coupled at rest with MC_GearInDyn (GearRatio 1.0, AccBound 9000 mm/s²,
// above the stability bound max|factor| 1.7 × A 5000 = 8500). The master runs at 1000 mm/s
// (MC_MoveVelocity). The PLC signal: 1.0 for 1 s, a step to 1.5 (the NC reaches it in
// 0.5 × 1000 / 9000 s, InGear again then), held 1 s, then 1.5 + 0.2 · sin(2π · 1 Hz · t) for 1.75 s
// (down to 1.3), written into GearRatio at every PLC call. Then Enable falls: the slave decouples
// in motion and goes on as a master at the factor in force × 1000 mm/s (SPEC C4); MC_Stop stops the
// slave, then the master.
//
// CyclicGearSample runs the program on simulated axes (1 ms NC cycle, 1 ms PLC task, a scope
// every NC cycle). Header-only, so that tests/samples/test_cyclic_gear_sample.cpp runs exactly
// what the sample program runs.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "fb/mc_gear_in_dyn.hpp"
#include "fb/mc_move_velocity.hpp"
#include "fb/mc_power.hpp"
#include "fb/mc_stop.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"
#include "plc_interface/axis_ref.hpp"
#include "sample_output.hpp"

namespace cyclic_gear {

inline constexpr double kVelocity = 1000.0;  // mm/s, the master's
inline constexpr double kAccBound = 9000.0;  // mm/s², MC_GearInDyn.Acceleration
inline constexpr double kPlcPeriod = 0.001;  // s
inline constexpr double kPi = 3.14159265358979323846;
// The PLC signal's phases (s from the master's start).
inline constexpr double kStepAt = 1.0;
inline constexpr double kSineFrom = 2.0;
inline constexpr double kSineUntil = 3.75;  // the sine's low: 1.3
inline constexpr double kAfterDecoupling = 0.5;

// The factor the PLC signal asks for, `t` s after the master's start.
inline double signal(double t) noexcept {
  if (t < kStepAt) return 1.0;
  if (t < kSineFrom) return 1.5;
  return 1.5 + 0.2 * std::sin(2.0 * kPi * 1.0 * (t - kSineFrom));
}

enum class CyclicState {
  STATE_INIT,         // wait for both MC_Power's Status
  STATE_GEAR_IN,      // MC_GearInDyn Enable, wait for InGear
  STATE_RUN,          // master at 1000 mm/s, GearRatio = the signal
  STATE_DECOUPLE,     // Enable falls: the slave decouples in motion
  STATE_SLAVE_STOP,   // MC_Stop on the slave
  STATE_MASTER_STOP,  // MC_Stop on the master
  STATE_FINISHED,
  STATE_ERROR,
};

inline const char* state_name(CyclicState state) noexcept {
  switch (state) {
    case CyclicState::STATE_INIT:
      return "STATE_INIT";
    case CyclicState::STATE_GEAR_IN:
      return "STATE_GEAR_IN";
    case CyclicState::STATE_RUN:
      return "STATE_RUN";
    case CyclicState::STATE_DECOUPLE:
      return "STATE_DECOUPLE";
    case CyclicState::STATE_SLAVE_STOP:
      return "STATE_SLAVE_STOP";
    case CyclicState::STATE_MASTER_STOP:
      return "STATE_MASTER_STOP";
    case CyclicState::STATE_FINISHED:
      return "STATE_FINISHED";
    case CyclicState::STATE_ERROR:
      return "STATE_ERROR";
  }
  return "?";
}

// PROGRAM MAIN, one call per PLC cycle. A cycle function.
struct Main {
  fb::MC_Power PowerMaster, PowerSlave;
  fb::MC_GearInDyn Gear;
  fb::MC_MoveVelocity Move;
  fb::MC_Stop StopSlave, StopMaster;
  CyclicState state = CyclicState::STATE_INIT;
  uint32_t error_id = 0;
  long cycles_in_state = 0;  // PLC cycles since the state was entered
  long run_cycles = 0;       // PLC cycles since the master's start

  void operator()(plc::AXIS_REF& master, plc::AXIS_REF& slave) noexcept {
    for (fb::MC_Power* p : {&PowerMaster, &PowerSlave})
      p->Enable = p->Enable_Positive = p->Enable_Negative = true;
    const CyclicState before = state;
    switch (state) {
      case CyclicState::STATE_INIT:
        if (PowerMaster.Status && PowerSlave.Status) state = CyclicState::STATE_GEAR_IN;
        break;
      case CyclicState::STATE_GEAR_IN:
        Gear.Enable = true;
        Gear.GearRatio = signal(0.0);
        Gear.Acceleration = kAccBound;
        if (Gear.InGear) state = CyclicState::STATE_RUN;
        break;
      case CyclicState::STATE_RUN:
        Move.Execute = true;
        Gear.GearRatio = signal(static_cast<double>(run_cycles) * kPlcPeriod);
        ++run_cycles;
        if (elapsed(kSineUntil)) state = CyclicState::STATE_DECOUPLE;
        break;
      case CyclicState::STATE_DECOUPLE:
        Gear.Enable = false;
        if (!Gear.Busy && elapsed(kAfterDecoupling)) state = CyclicState::STATE_SLAVE_STOP;
        break;
      case CyclicState::STATE_SLAVE_STOP:
        StopSlave.Execute = true;
        if (StopSlave.Done) state = CyclicState::STATE_MASTER_STOP;
        break;
      case CyclicState::STATE_MASTER_STOP:
        StopMaster.Execute = true;
        if (StopMaster.Done) state = CyclicState::STATE_FINISHED;
        break;
      case CyclicState::STATE_FINISHED:
      case CyclicState::STATE_ERROR:
        break;
    }
    cycles_in_state = state == before ? cycles_in_state + 1 : 0;

    PowerMaster(master);
    PowerSlave(slave);
    Gear(master, slave);
    Move.Velocity = kVelocity;
    Move.Direction = fb::MC_Positive_Direction;
    Move(master);
    StopSlave(slave);
    StopMaster(master);
    if (const uint32_t id = first_error(); id != 0) {
      error_id = id;
      state = CyclicState::STATE_ERROR;
    }
  }

 private:
  bool elapsed(double seconds) const noexcept {
    return static_cast<double>(cycles_in_state) * kPlcPeriod >= seconds;
  }
  uint32_t first_error() const noexcept {
    for (const fb::MC_Power* p : {&PowerMaster, &PowerSlave})
      if (p->Error) return p->ErrorID;
    if (Gear.Error) return Gear.ErrorID;
    if (Move.Error) return Move.ErrorID;
    if (StopSlave.Error) return StopSlave.ErrorID;
    if (StopMaster.Error) return StopMaster.ErrorID;
    return 0;
  }
};

// What the run showed, for the summary and the test.
struct Report {
  bool finished = false;
  uint32_t error_id = 0;
  uint32_t axis_errors = 0;    // or-ed NcToPlc.ErrorCode of both axes
  uint32_t warnings = 0;       // or-ed NcToPlc.Warning of the slave
  double max_slave_acc = 0.0;  // largest |slave SetAcc| while coupled, mm/s²
  double max_jump = 0.0;       // largest |slave step − factor × master step| while coupled, mm
  long step_cycles = 0;        // NC cycles from the step until the factor in force was 1.5
  bool step_in_gear = false;   // InGear once the factor in force was 1.5 after the step
  double max_lag = 0.0;        // largest |factor in force − GearRatio| in the sine's 2nd second
  long coupled_cycles = 0;
  double factor_at_decoupling = 0.0;   // the factor in force when the slave was decoupled
  double velo_after_decoupling = 0.0;  // slave SetVelo 0.5 s after (a master now)
  uint32_t couple_after_decoupling = 99;
  double end_velo[2] = {0.0, 0.0};
  double end_time = 0.0;
};

struct Options {
  double nc_cycle = 0.001;   // s; the PLC task runs with it (kPlcPeriod)
  double timeout = 20.0;     // s of simulated time
  double settle_time = 0.2;  // s recorded after the master's stop
};

class CyclicGearSample {
 public:
  static constexpr const char* kNames[2] = {"Master", "Slave"};

  explicit CyclicGearSample(const Options& options = {})
      : kernel_(nc::KernelConfig{options.nc_cycle}),
        master_(kernel_.add_axis(sample_common::lagging_axis(kNames[0], 5.0))),
        slave_(kernel_.add_axis(sample_common::lagging_axis(kNames[1], 5.0))),
        driver_(kernel_),
        scope_(sample_common::scope_capacity(options)),
        options_(options) {
    for (int i = 0; i < 2; ++i)
      scope_.add_motion_signals(*axes_[i], kNames[i]);
    scope_.add_variable(&slave_.NcToPlc.GearRatio, "Slave.GearRatio", "");
    scope_.add_variable(&slave_.PlcToNc.GearRatio1, "Slave.GearRatio1", "");
    driver_.add_task("Scope", options.nc_cycle, [this] { sample(); });
    driver_.add_task("PlcTask", options.nc_cycle, [this] { plc_cycle(); });
  }

  CyclicGearSample(const CyclicGearSample&) = delete;
  CyclicGearSample& operator=(const CyclicGearSample&) = delete;

  const Report& run() {
    report_.finished = sample_common::run_to_state(
        driver_, main_.state, CyclicState::STATE_FINISHED, CyclicState::STATE_ERROR,
        options_.timeout, options_.settle_time);
    sample();
    report_.error_id = main_.error_id;
    report_.end_velo[0] = master_.NcToPlc.SetVelo;
    report_.end_velo[1] = slave_.NcToPlc.SetVelo;
    report_.end_time = kernel_.time();
    return report_;
  }

  // Within AccBound while coupled, the position continuous, the step reached in 0.5 × 1000 /
  // 9000 s (56 cycles) with InGear, the sine followed (lag below 1e-9 in its second second), the
  // slave decoupled in motion at the factor in force × 1000 mm/s, no warning, no error.
  bool ok() const noexcept {
    const Report& r = report_;
    return r.finished && r.error_id == 0 && r.axis_errors == 0 && r.warnings == 0 &&
           r.coupled_cycles > 3700 && r.max_slave_acc <= kAccBound && r.max_jump < 1e-9 &&
           r.step_cycles >= 55 && r.step_cycles <= 57 && r.step_in_gear && r.max_lag < 1e-9 &&
           r.couple_after_decoupling == 0 &&
           std::fabs(r.velo_after_decoupling - r.factor_at_decoupling * kVelocity) < 1e-6 &&
           r.end_velo[0] == 0.0 && r.end_velo[1] == 0.0;
  }

  // After-run: <dir>/cyclic_gear.csv and .svg (set position, velocity, acceleration of both axes
  // and the slave's commanded factor and factor in force).
  std::pair<std::filesystem::path, std::filesystem::path> write(
      const std::filesystem::path& dir) const {
    const auto [csv, svg] = sample_common::csv_and_svg(dir, "cyclic_gear");
    scope_.write_csv(csv);
    const char* const colours[2] = {"#00008b", "#8b0000"};
    const sample_common::AxisPanel kinds[] = {
        {"panel-position", "Set position", "mm", nc::Signal::kSetPos},
        {"panel-velocity", "Set velocity", "mm/s", nc::Signal::kSetVelo},
        {"panel-acceleration", "Set acceleration", "mm/s²", nc::Signal::kSetAcc}};
    std::vector<nc::PlotPanel> panels = sample_common::axis_panels(scope_, kNames, colours, kinds);
    nc::PlotPanel factor{"panel-factor", "Slave factor", "", {}};
    factor.series.push_back(
        {"GearRatio1 (PLC)", "#808080", scope_.values(scope_.find("Slave.GearRatio1")), 1.0});
    factor.series.push_back(
        {"GearRatio (in force)", "#8b0000", scope_.values(scope_.find("Slave.GearRatio")), 1.5});
    panels.push_back(std::move(factor));
    nc::write_svg(svg, nc::svg_plot(scope_.time(), panels,
                                    {"Cyclic slave: factor from a PLC signal (step 1.0 -> 1.5, "
                                     "sine ±0.2 at 1 Hz), AccBound 9000 mm/s², then decoupled",
                                     1000, 150}));
    return {csv, svg};
  }

  std::string summary() const {
    const Report& r = report_;
    char text[700];
    std::snprintf(
        text, sizeof text,
        "Cyclic slave (seed 000 3.3): %s\n"
        "  max |slave acceleration| %.3f mm/s2 (AccBound %.0f), max position jump %.3g mm\n"
        "  step 1.0 -> 1.5 reached in %ld cycles (InGear %s), lag in the sine %.3g\n"
        "  decoupled at factor %.6f: slave %.6f mm/s, CoupleState %u\n"
        "  end: master %.3f, slave %.3f mm/s; simulated %.3f s\n",
        ok() ? "ok" : "FAILED", r.max_slave_acc, kAccBound, r.max_jump, r.step_cycles,
        r.step_in_gear ? "yes" : "no", r.max_lag, r.factor_at_decoupling, r.velo_after_decoupling,
        static_cast<unsigned>(r.couple_after_decoupling), r.end_velo[0], r.end_velo[1], r.end_time);
    std::string out = text;
    if (r.error_id != 0 || r.axis_errors != 0) {
      out += sample_common::error_line("block", r.error_id, r.axis_errors, state_name(main_.state));
    }
    return out;
  }

  const nc::Scope& scope() const noexcept { return scope_; }
  const Report& report() const noexcept { return report_; }

 private:
  void sample() noexcept { scope_.record(kernel_.time()); }

  // What the PLC reads now, against the image it read last.
  void observe() noexcept {
    const plc::NCTOPLC_AXIS_REF& s = slave_.NcToPlc;
    const plc::NCTOPLC_AXIS_REF& m = master_.NcToPlc;
    report_.axis_errors |= m.ErrorCode | s.ErrorCode;
    report_.warnings |= s.Warning;
    const bool coupled = s.CoupleState == static_cast<uint32_t>(plc::CoupleState::kSlave);
    if (coupled && was_coupled_) {
      ++report_.coupled_cycles;
      sample_common::track_max(report_.max_slave_acc, s.SetAcc);
      sample_common::track_max(report_.max_jump,
                               (s.SetPos - last_slave_) - s.GearRatio * (m.SetPos - last_master_));
    }
    const double t = static_cast<double>(main_.run_cycles) * kPlcPeriod;
    if (main_.state == CyclicState::STATE_RUN && t > kStepAt && t <= kSineFrom &&
        report_.step_cycles == 0) {
      ++step_counter_;
      if (s.GearRatio == 1.5) {
        report_.step_cycles = step_counter_;
        report_.step_in_gear = true;  // checked on the block in the next call
      }
    }
    if (coupled) last_factor_ = s.GearRatio;
    if (main_.state == CyclicState::STATE_RUN && t > kSineFrom + 1.0) {
      sample_common::track_max(report_.max_lag, s.GearRatio - main_.Gear.GearRatio);
    }
    was_coupled_ = coupled;
    last_slave_ = s.SetPos;
    last_master_ = m.SetPos;
  }

  void plc_cycle() noexcept {
    observe();
    const CyclicState before = main_.state;
    main_(master_, slave_);
    if (report_.step_in_gear && !step_checked_) {
      report_.step_in_gear = main_.Gear.InGear;
      step_checked_ = true;
    }
    if (before == CyclicState::STATE_DECOUPLE && main_.state != before) {
      report_.factor_at_decoupling = last_factor_;
      report_.velo_after_decoupling = slave_.NcToPlc.SetVelo;
      report_.couple_after_decoupling = slave_.NcToPlc.CoupleState;
    }
  }

  nc::Kernel kernel_;
  plc::AXIS_REF& master_;
  plc::AXIS_REF& slave_;
  const plc::AXIS_REF* axes_[2] = {&master_, &slave_};
  nc::CycleDriver driver_;
  nc::Scope scope_;
  Options options_;
  Main main_;
  Report report_;
  bool was_coupled_ = false;
  double last_slave_ = 0.0;
  double last_master_ = 0.0;
  long step_counter_ = 0;
  double last_factor_ = 0.0;  // the factor in force the last time the slave was coupled
  bool step_checked_ = false;
};

}  // namespace cyclic_gear
