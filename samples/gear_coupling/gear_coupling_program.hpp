// Linear slave axes with PLC blocks (seed 000 §3.2): a master and two slaves, first as a star,
// then as a cascade (SPEC C1-C4).
//
// Star: Slave1 is coupled to the master with MC_GearIn 3/4 and Slave2 to the master with −1/2, all
// three at rest at 0 mm. The master runs 0 → 10000 mm at V 2000 mm/s, started at override 30 %
// (MC_Power.Override): Slave1 450, Slave2 −300 mm/s; at 100 %: 1500 and −1000 mm/s; at rest at
// the end: 7500 and −5000 mm.
// Re-coupling at rest: MC_GearOut takes Slave2 off the master, a second MC_GearIn couples it to
// Slave1 with −1/2 (offset −1250 mm from the positions): a cascade master → Slave1 → Slave2.
// Cascade: the master runs on to 20000 mm at 100 % (Slave1 1500, Slave2 −750 mm/s). Slave1's
// MC_GearIn instance is triggered again with 4/5 (factor change, SPEC C2): 1600 and −800 mm/s.
// MC_GearOut decouples Slave1 online (SPEC C4): it goes on as it would have as a slave, Slave2
// still following it; MC_Stop stops Slave1 (and with it Slave2) with its own dynamics while the
// master runs on; finally MC_Stop stops the master.
//
// GearCouplingSample runs the program on simulated axes (1 ms NC cycle, 1 ms PLC task, a scope
// every NC cycle). Header-only, so that tests/samples/test_gear_coupling_sample.cpp runs exactly
// what the sample program runs.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iterator>
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

inline constexpr double kStarTarget = 10000.0;  // mm, the master's end position as a star
inline constexpr double kTarget = 20000.0;      // mm, the master's end position as a cascade
inline constexpr double kVelocity = 2000.0;     // mm/s, the master's V
inline constexpr double kPlcPeriod = 0.001;     // s
// How long each phase lasts before the program goes on (s).
inline constexpr double kAtOverride30 = 3.0;
inline constexpr double kAtOverride100 = 1.5;
inline constexpr double kCascadeRunning = 1.0;
inline constexpr double kAfterFactorChange = 1.0;
inline constexpr double kAfterDecoupling = 1.0;
inline constexpr double kAfterSlaveStop = 0.5;

enum class GearState {
  STATE_INIT,             // wait for the three MC_Power's Status
  STATE_STAR_GEAR_IN,     // star: both slaves' MC_GearIn on the master, wait for InGear
  STATE_OVERRIDE_30,      // master started (0 → 10000 mm) at override 30 %
  STATE_OVERRIDE_100,     // override 100 %
  STATE_STAR_ARRIVE,      // wait until the master is at 10000 mm
  STATE_SLAVE2_GEAR_OUT,  // MC_GearOut on Slave2 at rest
  STATE_CASCADE_GEAR_IN,  // MC_GearIn Slave1 → Slave2 at rest: the cascade
  STATE_CASCADE_RUN,      // master started (→ 20000 mm) at 100 %
  STATE_FACTOR_LOW,       // Slave1's MC_GearIn: Execute falls for one cycle
  STATE_FACTOR_HIGH,      // ... and rises with 4/5
  STATE_DECOUPLE,         // MC_GearOut on Slave1 in motion
  STATE_SLAVE_STOP,       // MC_Stop on Slave1
  STATE_MASTER_STOP,      // MC_Stop on the master
  STATE_FINISHED,
  STATE_ERROR,
};

inline const char* state_name(GearState state) noexcept {
  switch (state) {
    case GearState::STATE_INIT:
      return "STATE_INIT";
    case GearState::STATE_STAR_GEAR_IN:
      return "STATE_STAR_GEAR_IN";
    case GearState::STATE_OVERRIDE_30:
      return "STATE_OVERRIDE_30";
    case GearState::STATE_OVERRIDE_100:
      return "STATE_OVERRIDE_100";
    case GearState::STATE_STAR_ARRIVE:
      return "STATE_STAR_ARRIVE";
    case GearState::STATE_SLAVE2_GEAR_OUT:
      return "STATE_SLAVE2_GEAR_OUT";
    case GearState::STATE_CASCADE_GEAR_IN:
      return "STATE_CASCADE_GEAR_IN";
    case GearState::STATE_CASCADE_RUN:
      return "STATE_CASCADE_RUN";
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
  fb::MC_GearIn Gear1;         // master → Slave1 (3/4, then 4/5)
  fb::MC_GearIn GearStar2;     // master → Slave2 (−1/2), the star
  fb::MC_GearIn GearCascade2;  // Slave1 → Slave2 (−1/2), the cascade
  fb::MC_MoveAbsolute MoveStar, MoveCascade;
  fb::MC_GearOut GearOut1, GearOut2;
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
          state = GearState::STATE_STAR_GEAR_IN;
        }
        break;
      case GearState::STATE_STAR_GEAR_IN:
        Gear1.RatioNumerator = 3.0;
        Gear1.RatioDenominator = 4;
        GearStar2.RatioNumerator = -1.0;
        GearStar2.RatioDenominator = 2;
        Gear1.Execute = GearStar2.Execute = true;
        if (Gear1.InGear && GearStar2.InGear) state = GearState::STATE_OVERRIDE_30;
        break;
      case GearState::STATE_OVERRIDE_30:
        PowerMaster.Override = 30.0;
        MoveStar.Execute = true;
        if (elapsed(kAtOverride30)) state = GearState::STATE_OVERRIDE_100;
        break;
      case GearState::STATE_OVERRIDE_100:
        PowerMaster.Override = 100.0;
        if (elapsed(kAtOverride100)) state = GearState::STATE_STAR_ARRIVE;
        break;
      case GearState::STATE_STAR_ARRIVE:
        if (MoveStar.Done) state = GearState::STATE_SLAVE2_GEAR_OUT;
        break;
      case GearState::STATE_SLAVE2_GEAR_OUT:
        GearOut2.Execute = true;  // at rest: Slave2 becomes a single axis holding −5000 mm
        if (GearOut2.Done) state = GearState::STATE_CASCADE_GEAR_IN;
        break;
      case GearState::STATE_CASCADE_GEAR_IN:
        GearCascade2.RatioNumerator = -1.0;
        GearCascade2.RatioDenominator = 2;
        GearCascade2.Execute = true;
        if (GearCascade2.InGear) state = GearState::STATE_CASCADE_RUN;
        break;
      case GearState::STATE_CASCADE_RUN:
        MoveCascade.Execute = true;
        if (elapsed(kCascadeRunning)) state = GearState::STATE_FACTOR_LOW;
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
    GearStar2(master, slave2);
    GearCascade2(slave1, slave2);
    MoveStar.Position = kStarTarget;
    MoveCascade.Position = kTarget;
    MoveStar.Velocity = MoveCascade.Velocity = kVelocity;
    MoveStar(master);
    MoveCascade(master);
    GearOut1(slave1);
    GearOut2(slave2);
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
    for (const fb::MC_Power* p : {&PowerMaster, &PowerSlave1, &PowerSlave2})
      if (p->Error) return p->ErrorID;
    for (const fb::MC_GearIn* g : {&Gear1, &GearStar2, &GearCascade2})
      if (g->Error) return g->ErrorID;
    for (const fb::MC_MoveAbsolute* m : {&MoveStar, &MoveCascade})
      if (m->Error) return m->ErrorID;
    for (const fb::MC_GearOut* g : {&GearOut1, &GearOut2})
      if (g->Error) return g->ErrorID;
    if (StopSlave1.Error) return StopSlave1.ErrorID;
    if (StopMaster.Error) return StopMaster.ErrorID;
    return 0;
  }
};

// The three axes (master, Slave1, Slave2) at one moment, as the PLC saw them, and the InGear of
// the three MC_GearIn (master → Slave1, master → Slave2, Slave1 → Slave2).
struct Snapshot {
  double pos[3] = {0.0, 0.0, 0.0};    // NcToPlc.SetPos, mm
  double velo[3] = {0.0, 0.0, 0.0};   // NcToPlc.SetVelo, mm/s
  uint32_t couple[3] = {99, 99, 99};  // NcToPlc.CoupleState
  bool in_gear[3] = {false, false, false};
};

// Checks a slave's set position against factor × its master's set position + offset at every
// coupled cycle, bit for bit. The offset is the kernel's: taken when the coupling (or a new
// factor) appears, from the positions of the cycle before (SPEC C1, C2).
struct FollowCheck {
  bool coupled = false;
  double ratio = 0.0;
  double offset = 0.0;
  long checked = 0;     // coupled cycles compared
  long mismatches = 0;  // of those, cycles off the formula
};

// What the run showed, for the summary and the test.
struct Report {
  bool finished = false;
  uint32_t error_id = 0;
  uint32_t axis_errors = 0;  // or-ed NcToPlc.ErrorCode of the three axes
  Snapshot star_coupled;     // at the end of each phase
  Snapshot at_override_30;
  Snapshot at_override_100;
  Snapshot star_arrived;
  Snapshot slave2_decoupled;
  Snapshot cascade_coupled;
  Snapshot cascade_running;
  Snapshot after_factor_change;
  Snapshot after_decoupling;
  Snapshot after_slave_stop;
  Snapshot end;                     // after the master's stop and the settle time
  double star_offsets[2] = {0, 0};  // Slave1, Slave2 on the master
  double cascade_offset = 0.0;      // Slave2 on Slave1
  FollowCheck follow[2];            // Slave1, Slave2
  double end_time = 0.0;
};

struct Options {
  double nc_cycle = 0.001;   // s; the PLC task runs with it (kPlcPeriod)
  double timeout = 30.0;     // s of simulated time
  double settle_time = 0.2;  // s recorded after the master's stop
};

inline nc::AxisConfig sample_axis_config(const char* name) {
  return sample_common::lagging_axis(name, 5.0);
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
    for (int i = 0; i < 3; ++i) {
      scope_.add_motion_signals(*axes_[i], kNames[i]);
      scope_.add_signal(*axes_[i], kNames[i], nc::Signal::kCoupleState);
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
    report_.end = snapshot();
    report_.end_time = kernel_.time();
    return report_;
  }

  // The seed's velocities in each phase (to 1e-6 mm/s), the positions at the star's end, the
  // CoupleState of each axis in each topology, both slaves on their formula at every coupled
  // cycle, no error.
  bool ok() const noexcept {
    const auto near = [](double a, double b) { return std::fabs(a - b) <= 1e-6; };
    const auto velo = [&](const Snapshot& s, double m, double s1, double s2) {
      return near(s.velo[0], m) && near(s.velo[1], s1) && near(s.velo[2], s2);
    };
    const auto couple = [](const Snapshot& s, uint32_t m, uint32_t s1, uint32_t s2) {
      return s.couple[0] == m && s.couple[1] == s1 && s.couple[2] == s2;
    };
    const Report& r = report_;
    return r.finished && r.error_id == 0 && r.axis_errors == 0 && couple(r.star_coupled, 1, 3, 3) &&
           velo(r.at_override_30, 600.0, 450.0, -300.0) &&
           velo(r.at_override_100, 2000.0, 1500.0, -1000.0) &&
           r.star_arrived.pos[0] == kStarTarget && r.star_arrived.pos[1] == 7500.0 &&
           r.star_arrived.pos[2] == -5000.0 && couple(r.slave2_decoupled, 1, 3, 0) &&
           couple(r.cascade_coupled, 1, 2, 3) && r.cascade_offset == -1250.0 &&
           velo(r.cascade_running, 2000.0, 1500.0, -750.0) &&
           velo(r.after_factor_change, 2000.0, 1600.0, -800.0) &&
           couple(r.after_decoupling, 0, 1, 3) &&
           velo(r.after_decoupling, 2000.0, 1600.0, -800.0) && r.after_slave_stop.velo[1] == 0.0 &&
           r.after_slave_stop.velo[2] == 0.0 && near(r.after_slave_stop.velo[0], 2000.0) &&
           r.follow[0].mismatches == 0 && r.follow[1].mismatches == 0 && r.follow[0].checked > 0 &&
           r.follow[1].checked > 0;
  }

  // After-run: <dir>/gear_coupling.csv and .svg (set position, velocity, acceleration and
  // CoupleState of all three axes).
  std::pair<std::filesystem::path, std::filesystem::path> write(
      const std::filesystem::path& dir) const {
    const auto [csv, svg] = sample_common::csv_and_svg(dir, "gear_coupling");
    scope_.write_csv(csv);
    const char* const colours[3] = {"#00008b", "#8b0000", "#006400"};
    const sample_common::AxisPanel kinds[] = {
        {"panel-position", "Set position", "mm", nc::Signal::kSetPos},
        {"panel-velocity", "Set velocity", "mm/s", nc::Signal::kSetVelo},
        {"panel-acceleration", "Set acceleration", "mm/s²", nc::Signal::kSetAcc},
        {"panel-couple-state", "CoupleState", "", nc::Signal::kCoupleState}};
    const std::vector<nc::PlotPanel> panels =
        sample_common::axis_panels(scope_, kNames, colours, kinds);
    nc::write_svg(svg, nc::svg_plot(scope_.time(), panels,
                                    {"Gear coupling: star (Slave1 3/4, Slave2 -1/2 of the master; "
                                     "override 30 % / 100 %), then cascade (Slave2 -1/2 of "
                                     "Slave1; factor 4/5, decoupling, stops)",
                                     1000, 150}));
    return {csv, svg};
  }

  std::string summary() const {
    const Report& r = report_;
    std::string out = std::string("Gear coupling (seed 000 3.2): ") + (ok() ? "ok" : "FAILED") +
                      "\n  phase end              set velocity (mm/s)            CoupleState\n";
    const struct {
      const char* name;
      const Snapshot& s;
    } rows[] = {{"star coupled", r.star_coupled},
                {"star, override 30 %", r.at_override_30},
                {"star, override 100 %", r.at_override_100},
                {"star, at 10000 mm", r.star_arrived},
                {"Slave2 decoupled", r.slave2_decoupled},
                {"cascade coupled", r.cascade_coupled},
                {"cascade running", r.cascade_running},
                {"factor 4/5", r.after_factor_change},
                {"Slave1 decoupled", r.after_decoupling},
                {"Slave1 stopped", r.after_slave_stop},
                {"end", r.end}};
    char line[200];
    for (const auto& row : rows) {
      std::snprintf(line, sizeof line, "  %-21s %9.3f %9.3f %9.3f    %u %u %u\n", row.name,
                    row.s.velo[0], row.s.velo[1], row.s.velo[2],
                    static_cast<unsigned>(row.s.couple[0]), static_cast<unsigned>(row.s.couple[1]),
                    static_cast<unsigned>(row.s.couple[2]));
      out += line;
    }
    std::snprintf(line, sizeof line,
                  "  end: master %.3f, Slave1 %.3f, Slave2 %.3f mm; simulated %.3f s\n"
                  "  off factor x master + offset: Slave1 %ld of %ld cycles, Slave2 %ld of %ld\n",
                  r.end.pos[0], r.end.pos[1], r.end.pos[2], r.end_time, r.follow[0].mismatches,
                  r.follow[0].checked, r.follow[1].mismatches, r.follow[1].checked);
    out += line;
    if (r.error_id != 0 || r.axis_errors != 0) {
      out += sample_common::error_line("block", r.error_id, r.axis_errors, state_name(main_.state));
    }
    return out;
  }

  const nc::Scope& scope() const noexcept { return scope_; }
  const Report& report() const noexcept { return report_; }

 private:
  void sample() noexcept { scope_.record(kernel_.time()); }

  Snapshot snapshot() const noexcept {
    Snapshot s;
    for (int i = 0; i < 3; ++i) {
      s.pos[i] = axes_[i]->NcToPlc.SetPos;
      s.velo[i] = axes_[i]->NcToPlc.SetVelo;
      s.couple[i] = axes_[i]->NcToPlc.CoupleState;
    }
    s.in_gear[0] = main_.Gear1.InGear;
    s.in_gear[1] = main_.GearStar2.InGear;
    s.in_gear[2] = main_.GearCascade2.InGear;
    return s;
  }

  // Slave `i` (1 or 2) against its master in the image the PLC reads now; `before` holds the set
  // positions of the image before. Slave2's master is Slave1 when Slave1 is a master (CoupleState
  // 1 or 2), otherwise the master axis.
  void check_follow(int i, const double (&before)[3]) noexcept {
    FollowCheck& f = report_.follow[i - 1];
    const plc::NCTOPLC_AXIS_REF& slave = axes_[i]->NcToPlc;
    if (slave.CoupleState != static_cast<uint32_t>(plc::CoupleState::kSlave)) {
      f.coupled = false;
      return;
    }
    const uint32_t s1 = slave1_.NcToPlc.CoupleState;
    const int m = i == 2 && (s1 == 1 || s1 == 2) ? 1 : 0;
    if (!f.coupled || slave.GearRatio != f.ratio) {
      f.coupled = true;
      f.ratio = slave.GearRatio;
      f.offset = before[i] - f.ratio * before[m];
    }
    ++f.checked;
    if (slave.SetPos != f.ratio * axes_[m]->NcToPlc.SetPos + f.offset) ++f.mismatches;
  }

  void plc_cycle() noexcept {
    const GearState before = main_.state;
    check_follow(1, last_pos_);
    check_follow(2, last_pos_);
    for (int i = 0; i < 3; ++i)
      last_pos_[i] = axes_[i]->NcToPlc.SetPos;
    report_.axis_errors |=
        master_.NcToPlc.ErrorCode | slave1_.NcToPlc.ErrorCode | slave2_.NcToPlc.ErrorCode;
    main_(master_, slave1_, slave2_);
    if (main_.state == before) return;
    Snapshot* const ends[] = {
        nullptr,                       // STATE_INIT
        &report_.star_coupled,         // STATE_STAR_GEAR_IN
        &report_.at_override_30,       // STATE_OVERRIDE_30
        &report_.at_override_100,      // STATE_OVERRIDE_100
        &report_.star_arrived,         // STATE_STAR_ARRIVE
        &report_.slave2_decoupled,     // STATE_SLAVE2_GEAR_OUT
        &report_.cascade_coupled,      // STATE_CASCADE_GEAR_IN
        &report_.cascade_running,      // STATE_CASCADE_RUN
        nullptr,                       // STATE_FACTOR_LOW
        &report_.after_factor_change,  // STATE_FACTOR_HIGH
        &report_.after_decoupling,     // STATE_DECOUPLE
        &report_.after_slave_stop,     // STATE_SLAVE_STOP
    };
    const auto phase = static_cast<std::size_t>(before);  // the phase that just ended
    if (phase < std::size(ends) && ends[phase] != nullptr) *ends[phase] = snapshot();
    if (before == GearState::STATE_STAR_GEAR_IN) {
      report_.star_offsets[0] = report_.follow[0].offset;
      report_.star_offsets[1] = report_.follow[1].offset;
    }
    if (before == GearState::STATE_CASCADE_GEAR_IN)
      report_.cascade_offset = report_.follow[1].offset;
  }

  nc::Kernel kernel_;
  plc::AXIS_REF& master_;
  plc::AXIS_REF& slave1_;
  plc::AXIS_REF& slave2_;
  const plc::AXIS_REF* axes_[3] = {&master_, &slave1_, &slave2_};
  nc::CycleDriver driver_;
  nc::Scope scope_;
  Options options_;
  Main main_;
  Report report_;
  double last_pos_[3] = {0.0, 0.0, 0.0};  // set positions of the image the PLC read last
};

}  // namespace gear_coupling
