// Linear slave axes with PLC blocks (seed 000 §3.2): a master and a cascade of two slaves.
//
// Slave1 is coupled to the master with MC_GearIn 3/4 and Slave2 to Slave1 with −1/2, all three
// at rest at 0 mm (SPEC C1, C3). The master then runs 0 → 20000 mm at V 2000 mm/s, started at
// override 30 % (MC_Power.Override): Slave1 450 mm/s, Slave2 −225 mm/s; at 100 %: 1500 and −750
// mm/s. The same MC_GearIn instance of Slave1 is then triggered again with 4/5 (factor change,
// SPEC C2): 1600 and −800 mm/s. MC_GearOut decouples Slave1 online (SPEC C4): it goes on as it
// would have as a slave, Slave2 still following it; MC_Stop stops Slave1 (and with it Slave2)
// with its own dynamics while the master runs on; finally MC_Stop stops the master.
//
// GearCouplingSample runs the program on simulated axes (1 ms NC cycle, 1 ms PLC task, a scope
// every NC cycle). Header-only, so that tests/samples/test_gear_coupling_sample.cpp runs exactly
// what the sample program runs.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "fb/mc_gear_in.hpp"
#include "fb/mc_gear_out.hpp"
#include "fb/mc_move_absolute.hpp"
#include "fb/mc_power.hpp"
#include "fb/mc_stop.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"
#include "plc_interface/axis_ref.hpp"
#include "sample_output.hpp"

namespace gear_coupling {

inline constexpr double kTarget = 20000.0;   // mm, the master's end position
inline constexpr double kVelocity = 2000.0;  // mm/s, the master's V
inline constexpr double kPlcPeriod = 0.001;  // s
// How long each phase lasts before the program goes on (s).
inline constexpr double kAtOverride30 = 3.0;
inline constexpr double kAtOverride100 = 1.5;
inline constexpr double kAfterFactorChange = 1.0;
inline constexpr double kAfterDecoupling = 1.0;
inline constexpr double kAfterSlaveStop = 0.5;

enum class GearState {
  STATE_INIT,          // wait for the three MC_Power's Status
  STATE_GEAR_IN,       // both MC_GearIn, wait for InGear
  STATE_OVERRIDE_30,   // master started at override 30 %
  STATE_OVERRIDE_100,  // override 100 %
  STATE_FACTOR_LOW,    // Slave1's MC_GearIn: Execute falls for one cycle
  STATE_FACTOR_HIGH,   // ... and rises with 4/5
  STATE_DECOUPLE,      // MC_GearOut on Slave1 in motion
  STATE_SLAVE_STOP,    // MC_Stop on Slave1
  STATE_MASTER_STOP,   // MC_Stop on the master
  STATE_FINISHED,
  STATE_ERROR,
};

inline const char* state_name(GearState state) noexcept {
  switch (state) {
    case GearState::STATE_INIT:
      return "STATE_INIT";
    case GearState::STATE_GEAR_IN:
      return "STATE_GEAR_IN";
    case GearState::STATE_OVERRIDE_30:
      return "STATE_OVERRIDE_30";
    case GearState::STATE_OVERRIDE_100:
      return "STATE_OVERRIDE_100";
    case GearState::STATE_FACTOR_LOW:
      return "STATE_FACTOR_LOW";
    case GearState::STATE_FACTOR_HIGH:
      return "STATE_FACTOR_HIGH";
    case GearState::STATE_DECOUPLE:
      return "STATE_DECOUPLE";
    case GearState::STATE_SLAVE_STOP:
      return "STATE_SLAVE_STOP";
    case GearState::STATE_MASTER_STOP:
      return "STATE_MASTER_STOP";
    case GearState::STATE_FINISHED:
      return "STATE_FINISHED";
    case GearState::STATE_ERROR:
      return "STATE_ERROR";
  }
  return "?";
}

// PROGRAM MAIN, one call per PLC cycle. A cycle function.
struct Main {
  fb::MC_Power PowerMaster, PowerSlave1, PowerSlave2;
  fb::MC_GearIn Gear1, Gear2;
  fb::MC_MoveAbsolute Move;
  fb::MC_GearOut GearOut1;
  fb::MC_Stop StopSlave1, StopMaster;
  GearState state = GearState::STATE_INIT;
  uint32_t error_id = 0;
  long cycles_in_state = 0;  // PLC cycles since the state was entered

  void operator()(plc::AXIS_REF& master, plc::AXIS_REF& slave1, plc::AXIS_REF& slave2) noexcept {
    for (fb::MC_Power* p : {&PowerMaster, &PowerSlave1, &PowerSlave2})
      p->Enable = p->Enable_Positive = p->Enable_Negative = true;
    const GearState before = state;
    switch (state) {
      case GearState::STATE_INIT:
        if (PowerMaster.Status && PowerSlave1.Status && PowerSlave2.Status) {
          state = GearState::STATE_GEAR_IN;
        }
        break;
      case GearState::STATE_GEAR_IN:
        Gear1.RatioNumerator = 3.0;
        Gear1.RatioDenominator = 4;
        Gear2.RatioNumerator = -1.0;
        Gear2.RatioDenominator = 2;
        Gear1.Execute = Gear2.Execute = true;
        if (Gear1.InGear && Gear2.InGear) state = GearState::STATE_OVERRIDE_30;
        break;
      case GearState::STATE_OVERRIDE_30:
        PowerMaster.Override = 30.0;
        Move.Execute = true;
        if (elapsed(kAtOverride30)) state = GearState::STATE_OVERRIDE_100;
        break;
      case GearState::STATE_OVERRIDE_100:
        PowerMaster.Override = 100.0;
        if (elapsed(kAtOverride100)) state = GearState::STATE_FACTOR_LOW;
        break;
      case GearState::STATE_FACTOR_LOW:
        Gear1.Execute = false;  // the coupling stays: a falling Execute never ends it
        state = GearState::STATE_FACTOR_HIGH;
        break;
      case GearState::STATE_FACTOR_HIGH:
        Gear1.RatioNumerator = 4.0;
        Gear1.RatioDenominator = 5;
        Gear1.Execute = true;  // a new rising edge while InGear: the factor change
        if (Gear1.InGear && elapsed(kAfterFactorChange)) state = GearState::STATE_DECOUPLE;
        break;
      case GearState::STATE_DECOUPLE:
        GearOut1.Execute = true;
        if (GearOut1.Done && elapsed(kAfterDecoupling)) state = GearState::STATE_SLAVE_STOP;
        break;
      case GearState::STATE_SLAVE_STOP:
        StopSlave1.Execute = true;
        if (StopSlave1.Done && elapsed(kAfterSlaveStop)) state = GearState::STATE_MASTER_STOP;
        break;
      case GearState::STATE_MASTER_STOP:
        StopMaster.Execute = true;
        if (StopMaster.Done) state = GearState::STATE_FINISHED;
        break;
      case GearState::STATE_FINISHED:
      case GearState::STATE_ERROR:
        break;
    }
    cycles_in_state = state == before ? cycles_in_state + 1 : 0;

    PowerMaster(master);
    PowerSlave1(slave1);
    PowerSlave2(slave2);
    Gear1(master, slave1);
    Gear2(slave1, slave2);
    Move.Position = kTarget;
    Move.Velocity = kVelocity;
    Move(master);
    GearOut1(slave1);
    StopSlave1(slave1);
    StopMaster(master);
    if (const uint32_t id = first_error(); id != 0) {
      error_id = id;
      state = GearState::STATE_ERROR;
    }
  }

 private:
  bool elapsed(double seconds) const noexcept {
    return static_cast<double>(cycles_in_state) * kPlcPeriod >= seconds;
  }
  uint32_t first_error() const noexcept {
    if (PowerMaster.Error) return PowerMaster.ErrorID;
    if (PowerSlave1.Error) return PowerSlave1.ErrorID;
    if (PowerSlave2.Error) return PowerSlave2.ErrorID;
    if (Gear1.Error) return Gear1.ErrorID;
    if (Gear2.Error) return Gear2.ErrorID;
    if (Move.Error) return Move.ErrorID;
    if (GearOut1.Error) return GearOut1.ErrorID;
    if (StopSlave1.Error) return StopSlave1.ErrorID;
    if (StopMaster.Error) return StopMaster.ErrorID;
    return 0;
  }
};

// Set velocities (mm/s) at one moment: master, Slave1, Slave2.
struct Velocities {
  double master = 0.0;
  double slave1 = 0.0;
  double slave2 = 0.0;
};

// What the run showed, for the summary and the test.
struct Report {
  bool finished = false;
  uint32_t error_id = 0;
  uint32_t axis_errors = 0;   // or-ed NcToPlc.ErrorCode of the three axes
  Velocities at_override_30;  // at the end of each phase
  Velocities at_override_100;
  Velocities after_factor_change;
  Velocities after_decoupling;
  Velocities after_slave_stop;
  uint32_t slave1_couple_state_after_decoupling = 99;
  long cascade_mismatches = 0;    // cycles where Slave2.SetPos != -0.5 × Slave1.SetPos
  long following_mismatches = 0;  // coupled cycles where Slave1.SetPos != factor × master
  double final_pos[3] = {0.0, 0.0, 0.0};
  double end_time = 0.0;
};

struct Options {
  double nc_cycle = 0.001;   // s; the PLC task runs with it (kPlcPeriod)
  double timeout = 20.0;     // s of simulated time
  double settle_time = 0.2;  // s recorded after the master's stop
};

inline nc::AxisConfig sample_axis_config(const char* name) {
  nc::AxisConfig config;
  config.name = name;
  sample_common::use_lagging_drive(config, 5.0);
  return config;
}

class GearCouplingSample {
 public:
  static constexpr const char* kNames[3] = {"Master", "Slave1", "Slave2"};

  explicit GearCouplingSample(const Options& options = {})
      : kernel_(nc::KernelConfig{options.nc_cycle}),
        master_(kernel_.add_axis(sample_axis_config(kNames[0]))),
        slave1_(kernel_.add_axis(sample_axis_config(kNames[1]))),
        slave2_(kernel_.add_axis(sample_axis_config(kNames[2]))),
        driver_(kernel_),
        scope_(sample_common::scope_capacity(options)),
        options_(options) {
    const plc::AXIS_REF* axes[3] = {&master_, &slave1_, &slave2_};
    for (int i = 0; i < 3; ++i) {
      scope_.add_motion_signals(*axes[i], kNames[i]);
      scope_.add_signal(*axes[i], kNames[i], nc::Signal::kCoupleState);
    }
    driver_.add_task("Scope", options.nc_cycle, [this] { sample(); });
    driver_.add_task("PlcTask", options.nc_cycle, [this] { plc_cycle(); });
  }

  GearCouplingSample(const GearCouplingSample&) = delete;
  GearCouplingSample& operator=(const GearCouplingSample&) = delete;

  const Report& run() {
    report_.finished =
        sample_common::run_to_state(driver_, main_.state, GearState::STATE_FINISHED,
                                    GearState::STATE_ERROR, options_.timeout, options_.settle_time);
    sample();
    report_.error_id = main_.error_id;
    report_.final_pos[0] = master_.NcToPlc.SetPos;
    report_.final_pos[1] = slave1_.NcToPlc.SetPos;
    report_.final_pos[2] = slave2_.NcToPlc.SetPos;
    report_.end_time = kernel_.time();
    return report_;
  }

  // The seed's velocities in each phase (to 1e-6 mm/s), Slave1 a master (CoupleState 1, of
  // Slave2) after decoupling, the cascade exact at every cycle, no error.
  bool ok() const noexcept {
    const auto near = [](double a, double b) { return std::fabs(a - b) <= 1e-6; };
    const Report& r = report_;
    return r.finished && r.error_id == 0 && r.axis_errors == 0 &&
           near(r.at_override_30.slave1, 450.0) && near(r.at_override_30.slave2, -225.0) &&
           near(r.at_override_100.slave1, 1500.0) && near(r.at_override_100.slave2, -750.0) &&
           near(r.after_factor_change.slave1, 1600.0) &&
           near(r.after_factor_change.slave2, -800.0) && near(r.after_decoupling.slave1, 1600.0) &&
           near(r.after_decoupling.master, 2000.0) && r.after_slave_stop.slave1 == 0.0 &&
           r.after_slave_stop.slave2 == 0.0 && near(r.after_slave_stop.master, 2000.0) &&
           r.slave1_couple_state_after_decoupling == 1 && r.cascade_mismatches == 0 &&
           r.following_mismatches == 0;
  }

  // After-run: <dir>/gear_coupling.csv and .svg (set position and velocity of all three axes).
  std::pair<std::filesystem::path, std::filesystem::path> write(
      const std::filesystem::path& dir) const {
    const auto [csv, svg] = sample_common::csv_and_svg(dir, "gear_coupling");
    scope_.write_csv(csv);
    const char* colours[3] = {"#00008b", "#8b0000", "#006400"};
    const struct {
      const char* id;
      const char* title;
      const char* unit;
      nc::Signal signal;
    } kinds[] = {{"panel-position", "Set position", "mm", nc::Signal::kSetPos},
                 {"panel-velocity", "Set velocity", "mm/s", nc::Signal::kSetVelo},
                 {"panel-acceleration", "Set acceleration", "mm/s²", nc::Signal::kSetAcc},
                 {"panel-couple-state", "CoupleState", "", nc::Signal::kCoupleState}};
    std::vector<nc::PlotPanel> panels;
    for (const auto& k : kinds) {
      nc::PlotPanel panel{k.id, k.title, k.unit, {}};
      for (int i = 0; i < 3; ++i) {
        panel.series.push_back(
            {kNames[i], colours[i], scope_.values(scope_.find(kNames[i], k.signal)), 1.5});
      }
      panels.push_back(std::move(panel));
    }
    nc::write_svg(svg, nc::svg_plot(scope_.time(), panels,
                                    {"Gear coupling: master, Slave1 (3/4 then 4/5), Slave2 (-1/2 "
                                     "of Slave1); override 30 % / 100 %, decoupling, stops",
                                     1000, 150}));
    return {csv, svg};
  }

  std::string summary() const {
    const Report& r = report_;
    char text[1400];
    std::snprintf(
        text, sizeof text,
        "Gear coupling (seed 000 3.2): %s\n"
        "  override 30 %%:        master %.3f, Slave1 %.3f, Slave2 %.3f mm/s\n"
        "  override 100 %%:       master %.3f, Slave1 %.3f, Slave2 %.3f mm/s\n"
        "  factor 4/5:           master %.3f, Slave1 %.3f, Slave2 %.3f mm/s\n"
        "  decoupled (Slave1):   master %.3f, Slave1 %.3f, Slave2 %.3f mm/s, CoupleState %u\n"
        "  Slave1 stopped:       master %.3f, Slave1 %.3f, Slave2 %.3f mm/s\n"
        "  end: master %.3f, Slave1 %.3f, Slave2 %.3f mm; simulated %.3f s\n"
        "  cascade off the formula in %ld cycles, Slave1 off its factor in %ld cycles\n",
        ok() ? "ok" : "FAILED", r.at_override_30.master, r.at_override_30.slave1,
        r.at_override_30.slave2, r.at_override_100.master, r.at_override_100.slave1,
        r.at_override_100.slave2, r.after_factor_change.master, r.after_factor_change.slave1,
        r.after_factor_change.slave2, r.after_decoupling.master, r.after_decoupling.slave1,
        r.after_decoupling.slave2, static_cast<unsigned>(r.slave1_couple_state_after_decoupling),
        r.after_slave_stop.master, r.after_slave_stop.slave1, r.after_slave_stop.slave2,
        r.final_pos[0], r.final_pos[1], r.final_pos[2], r.end_time, r.cascade_mismatches,
        r.following_mismatches);
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

  Velocities velocities() const noexcept {
    return {master_.NcToPlc.SetVelo, slave1_.NcToPlc.SetVelo, slave2_.NcToPlc.SetVelo};
  }

  void plc_cycle() noexcept {
    const GearState before = main_.state;
    // The NC image of the cycle before this PLC call: the cascade and the coupling factor.
    if (slave2_.NcToPlc.SetPos != -0.5 * slave1_.NcToPlc.SetPos) ++report_.cascade_mismatches;
    if (slave1_.NcToPlc.CoupleState == 3 && slave1_.NcToPlc.GearRatio == 0.75 &&
        slave1_.NcToPlc.SetPos != 0.75 * master_.NcToPlc.SetPos) {
      ++report_.following_mismatches;
    }
    report_.axis_errors |=
        master_.NcToPlc.ErrorCode | slave1_.NcToPlc.ErrorCode | slave2_.NcToPlc.ErrorCode;
    main_(master_, slave1_, slave2_);
    if (main_.state == before) return;
    switch (before) {  // the phase that just ended
      case GearState::STATE_OVERRIDE_30:
        report_.at_override_30 = velocities();
        break;
      case GearState::STATE_OVERRIDE_100:
        report_.at_override_100 = velocities();
        break;
      case GearState::STATE_FACTOR_HIGH:
        report_.after_factor_change = velocities();
        break;
      case GearState::STATE_DECOUPLE:
        report_.after_decoupling = velocities();
        report_.slave1_couple_state_after_decoupling = slave1_.NcToPlc.CoupleState;
        break;
      case GearState::STATE_SLAVE_STOP:
        report_.after_slave_stop = velocities();
        break;
      default:
        break;
    }
  }

  nc::Kernel kernel_;
  plc::AXIS_REF& master_;
  plc::AXIS_REF& slave1_;
  plc::AXIS_REF& slave2_;
  nc::CycleDriver driver_;
  nc::Scope scope_;
  Options options_;
  Main main_;
  Report report_;
};

}  // namespace gear_coupling
