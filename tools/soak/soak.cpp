// ncsdk_soak (issue 16, item 3): random valid commands on 64 axes for 1e8 axis-cycles, with the
// invariants of the fuzz targets on at every cycle (tests/fuzz/axis_watch.hpp, block_rules.hpp,
// no allocation in the PLC calls and the NC cycle). Each PLC cycle gives every axis, with a small
// probability, a new command through its blocks: absolute / relative moves, continuous motion,
// halt, stop (released later), new end position, override changes — all with valid inputs — and
// now and then a fault (a feed enable lost for a few cycles, a drive that saturates on some axes
// so that fast moves lag into the following-error limit); an axis in error is reset.
// Reports cycles run, commands posted and answered, errors raised by kind (axis errors and block
// ErrorIDs) and the worst and mean time of the NC cycle and of the whole tick.
//
//   ncsdk_soak [--axis-cycles N] [--axes N] [--seed S]
// Exit status 0 when every invariant held, 1 when an axis invariant broke (each kind is counted
// and its first occurrences printed); a broken block rule or an allocation aborts at once.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "allocation_count.hpp"
#include "axis_watch.hpp"
#include "block_rules.hpp"
#include "fail.hpp"
#include "fb/fb.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/kernel.hpp"

namespace {

using Clock = std::chrono::steady_clock;

// CPU time of this thread: the NC cycle's own cost, without the time other processes took.
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

struct Options {
  uint64_t axis_cycles = 100'000'000;
  std::size_t axes = 64;
  uint64_t seed = 16;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const uint64_t value = std::strtoull(argv[i + 1], nullptr, 10);
    if (key == "--axis-cycles") {
      o.axis_cycles = value;
    } else if (key == "--axes") {
      o.axes = std::max<uint64_t>(1, value);
    } else if (key == "--seed") {
      o.seed = value;
    } else {
      std::fprintf(stderr, "usage: ncsdk_soak [--axis-cycles N] [--axes N] [--seed S]\n");
      std::exit(2);
    }
  }
  return o;
}

// The blocks of one axis.
struct AxisProgram {
  fb::MC_Power power;
  fb::MC_Reset reset;
  fb::MC_MoveAbsolute absolute;
  fb::MC_MoveRelative relative;
  fb::MC_MoveVelocity velocity;
  fb::MC_Halt halt;
  fb::MC_Stop stop;
  fb::MC_SetOverride set_override;
  fb::MC_NewPos new_pos;
  fb::MC_ReadAxisError axis_error;
  int feed_fault_cycles = 0;  // > 0: a feed enable is off for this many more cycles
  bool fault_plus = true;
  std::array<bool, 7> shown_error{};  // the Execute blocks' Error at the last count
  // The last commands given (printed when an invariant breaks, to reproduce it).
  struct Given {
    uint64_t tick = 0;
    const char* what = "";
    double x[5] = {};
  };
  std::array<Given, 8> history{};
  std::size_t next = 0;
  void log(uint64_t tick, const char* what, double x0 = 0, double x1 = 0, double x2 = 0,
           double x3 = 0, double x4 = 0) {
    history[next % history.size()] = Given{tick, what, {x0, x1, x2, x3, x4}};
    ++next;
  }
};

// Errors by kind: axis errors (NcToPlc.ErrorCode as it appears) and block ErrorIDs (a refusal
// shown by a block, counted once per result).
struct Tally {
  std::map<uint32_t, uint64_t> axis_errors;
  std::map<uint32_t, uint64_t> block_errors;
};

// Counts a block's Error when it appears (outside the allocation-checked region: the map grows).
template <class Block>
void count(const Block& block, bool& shown, Tally& tally) {
  if (block.Error && !shown) ++tally.block_errors[block.ErrorID];
  shown = block.Error;
}

class Soak {
 public:
  explicit Soak(const Options& o) : rng_(o.seed), kernel_(nc::KernelConfig{0.001}) {
    programs_.resize(o.axes);
    axes_.reserve(o.axes);
    watches_.reserve(o.axes);
    for (std::size_t i = 0; i < o.axes; ++i) {
      nc::AxisConfig c;
      c.name = "axis" + std::to_string(i);
      if (i % 4 == 1) {
        c.drive_model = nc::DriveModel::kFirstOrderLag;
        c.drive_time_constant = 0.005;
        c.drive_dead_time = 0.001;
      }
      if (i % 8 == 3) {
        c.drive_max_velocity = 1'500.0;  // fast moves lag into the following-error limit
        c.following_error_limit = 2.0;
      }
      if (i % 8 == 5) {
        c.sw_limit_min_enabled = c.sw_limit_max_enabled = true;
        c.sw_limit_min = -2'000.0;
        c.sw_limit_max = 2'000.0;
      }
      c.override_type = 1 + static_cast<int>(i % 4);
      configs_.push_back(c);
      axes_.push_back(&kernel_.add_axis(c));
      watches_.emplace_back(c, kernel_.cycle_time());
      AxisProgram& a = programs_[i];
      a.power.Enable = a.power.Enable_Positive = a.power.Enable_Negative = true;
      a.axis_error.Enable = true;
    }
    if (const char* trace = std::getenv("SOAK_TRACE")) {
      unsigned long long axis = 0;
      unsigned long long from = 0;
      if (std::sscanf(trace, "%llu,%llu", &axis, &from) == 2) {
        trace_axis_ = static_cast<std::size_t>(axis);
        trace_from_ = from;
      }
    }
  }

  void run(uint64_t cycles) {
    const Clock::time_point start = Clock::now();
    for (uint64_t k = 0; k < cycles; ++k)
      tick();
    seconds_ = std::chrono::duration<double>(Clock::now() - start).count();
  }

  void report(const Options& o) const {
    long posted = 0;
    long answered = 0;
    for (const auto& w : watches_) {
      posted += w.commands_posted();
      answered += w.commands_answered();
    }
    const double axis_cycles = static_cast<double>(ticks_) * static_cast<double>(axes_.size());
    std::printf("ncsdk_soak: seed %llu, %zu axes, %llu NC cycles = %.0f axis-cycles in %.1f s\n",
                static_cast<unsigned long long>(o.seed), axes_.size(),
                static_cast<unsigned long long>(ticks_), axis_cycles, seconds_);
    std::printf("commands posted %ld, answered %ld (every one within 2 NC cycles)\n", posted,
                answered);
    std::printf(
        "NC cycle (%zu axes), wall clock: worst %.1f us, mean %.2f us (%.1f ns per axis-cycle)\n",
        axes_.size(), worst_nc_ * 1e6, total_nc_ / static_cast<double>(ticks_) * 1e6,
        total_nc_ / axis_cycles * 1e9);
    std::printf(
        "NC cycle, thread CPU time (without preemption): worst %.1f us, mean %.2f us "
        "(%.1f ns per axis-cycle)\n",
        worst_nc_cpu_ * 1e6, total_nc_cpu_ / static_cast<double>(ticks_) * 1e6,
        total_nc_cpu_ / axis_cycles * 1e9);
    std::printf("whole tick (PLC calls + NC cycle + checks): worst %.1f us, mean %.2f us\n",
                worst_tick_ * 1e6, seconds_ / static_cast<double>(ticks_) * 1e6);
    std::printf("axis errors raised, by kind:");
    for (const auto& [code, n] : tally_.axis_errors)
      std::printf(" 0x%X x%llu", code, static_cast<unsigned long long>(n));
    std::printf("\nblock errors shown, by ErrorID:");
    for (const auto& [code, n] : tally_.block_errors)
      std::printf(" 0x%X x%llu", code, static_cast<unsigned long long>(n));
    std::printf("\nallocations in the cycle: 0; block output rules held at every call\n");
    if (broken_.empty()) std::printf("axis invariants: every one held at every cycle\n");
    for (const auto& [what, n] : broken_) {
      std::printf("axis invariant broken: %s, %llu times (%llu axis-cycles)\n", what.c_str(),
                  static_cast<unsigned long long>(break_events_.at(what)),
                  static_cast<unsigned long long>(n));
    }
  }

  bool held() const { return broken_.empty(); }

 private:
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  // 0 (the axis default) or a valid value around it.
  double dynamics(double typical) { return chance(0.5) ? 0.0 : typical * uniform(0.5, 3.0); }

  // Maybe a new command for axis i (inputs are set; the Execute edge comes from the toggle).
  void program(std::size_t i) {
    AxisProgram& a = programs_[i];
    const plc::AXIS_REF& axis = *axes_[i];
    const nc::AxisConfig& c = configs_[i];
    fuzz::AxisWatch& w = watches_[i];
    // Execute is high for one call only: every command starts on a fresh rising edge.
    for (bool* e : {&a.reset.Execute, &a.absolute.Execute, &a.relative.Execute, &a.velocity.Execute,
                    &a.halt.Execute, &a.new_pos.Execute}) {
      *e = false;
    }
    if (a.feed_fault_cycles > 0 && --a.feed_fault_cycles == 0) {
      a.power.Enable_Positive = a.power.Enable_Negative = true;
    }
    if (axis.NcToPlc.ErrorCode != 0) {
      if (!a.reset.Busy && chance(0.05)) a.reset.Execute = true;
      return;
    }
    if (a.stop.Execute) {
      if (a.stop.Done && chance(0.05)) a.stop.Execute = false;  // release the lock
      return;
    }
    if (!chance(0.01)) return;
    const double v_max = std::min(c.max_velocity, c.ref_velocity);
    const double u = uniform(0.0, 1.0);
    if (u < 0.30) {
      if (a.absolute.Busy) return;  // a rising edge while Busy starts nothing
      a.absolute.Position = uniform(-1'800.0, 1'800.0);
      a.absolute.Velocity = uniform(1.0, v_max);
      a.absolute.Acceleration = dynamics(c.acceleration);
      a.absolute.Deceleration = dynamics(c.deceleration);
      a.absolute.Jerk = dynamics(c.jerk);
      w.allow_dynamics(a.absolute.Acceleration, a.absolute.Deceleration);
      a.absolute.Execute = true;
      a.log(ticks_, "MC_MoveAbsolute Position Velocity Acceleration Deceleration Jerk",
            a.absolute.Position, a.absolute.Velocity, a.absolute.Acceleration,
            a.absolute.Deceleration, a.absolute.Jerk);
    } else if (u < 0.45) {
      if (a.relative.Busy) return;  // a rising edge while Busy starts nothing
      a.relative.Distance = uniform(-500.0, 500.0);
      a.relative.Velocity = uniform(1.0, v_max);
      a.relative.Execute = true;
      a.log(ticks_, "MC_MoveRelative Distance Velocity", a.relative.Distance, a.relative.Velocity);
    } else if (u < 0.60) {
      if (a.velocity.Busy) return;  // a rising edge while Busy starts nothing
      a.velocity.Velocity = uniform(1.0, v_max);
      a.velocity.Direction = chance(0.5) ? fb::MC_Positive_Direction : fb::MC_Negative_Direction;
      a.velocity.Acceleration = dynamics(c.acceleration);
      w.allow_dynamics(a.velocity.Acceleration, 0.0);
      a.velocity.Execute = true;
      a.log(ticks_, "MC_MoveVelocity Velocity Direction Acceleration", a.velocity.Velocity,
            a.velocity.Direction, a.velocity.Acceleration);
    } else if (u < 0.72) {
      if (a.halt.Busy) return;  // a rising edge while Busy starts nothing
      a.halt.Deceleration = dynamics(c.deceleration);
      a.halt.Jerk = dynamics(c.jerk);
      w.allow_dynamics(0.0, a.halt.Deceleration);
      a.halt.Execute = true;
      a.log(ticks_, "MC_Halt Deceleration Jerk", a.halt.Deceleration, a.halt.Jerk);
    } else if (u < 0.80) {
      if (a.new_pos.Busy) return;  // a rising edge while Busy starts nothing
      a.new_pos.NewPos = uniform(-1'800.0, 1'800.0);
      a.new_pos.Execute = true;
      a.log(ticks_, "MC_NewPos NewPos", a.new_pos.NewPos);
    } else if (u < 0.92) {
      a.set_override.Enable = true;
      a.set_override.VelFactor = chance(0.1) ? 0.0 : uniform(0.0, 1.0);
      a.log(ticks_, "MC_SetOverride VelFactor", a.set_override.VelFactor);
    } else if (u < 0.97) {
      if (a.stop.Busy) return;  // a rising edge while Busy starts nothing
      a.stop.Deceleration = dynamics(c.emergency_deceleration);
      a.stop.Jerk = dynamics(c.emergency_jerk);
      w.allow_dynamics(0.0, a.stop.Deceleration);
      a.stop.Execute = true;
      a.log(ticks_, "MC_Stop Deceleration Jerk", a.stop.Deceleration, a.stop.Jerk);
    } else {
      // Fault: a feed enable lost for 5 … 50 cycles.
      a.fault_plus = chance(0.5);
      (a.fault_plus ? a.power.Enable_Positive : a.power.Enable_Negative) = false;
      a.feed_fault_cycles = 5 + static_cast<int>(uniform(0.0, 45.0));
      a.log(ticks_, "feed enable lost (1 plus, 0 minus), cycles", a.fault_plus,
            a.feed_fault_cycles);
    }
  }

  void tick() {
    for (std::size_t i = 0; i < axes_.size(); ++i)
      program(i);  // the random choices (outside the measured, allocation-checked region)
    const Clock::time_point t0 = Clock::now();
    double nc_seconds = 0.0;
    double nc_cpu = 0.0;
    {
      const fuzz::AllocationRegion region;
      for (std::size_t i = 0; i < axes_.size(); ++i) {
        AxisProgram& a = programs_[i];
        plc::AXIS_REF& axis = *axes_[i];
        a.power(axis);
        fuzz::call_checked(a.reset, axis);
        fuzz::call_checked(a.absolute, axis);
        fuzz::call_checked(a.relative, axis);
        fuzz::call_checked(a.velocity, axis);
        fuzz::call_checked(a.halt, axis);
        fuzz::call_checked(a.stop, axis);
        a.set_override(axis);
        fuzz::call_checked(a.new_pos, axis);
        a.axis_error(axis);
        watches_[i].posted(axis);
      }
      const Clock::time_point n0 = Clock::now();
      const double c0 = thread_cpu_seconds();
      kernel_.cycle();
      nc_cpu = thread_cpu_seconds() - c0;
      nc_seconds = std::chrono::duration<double>(Clock::now() - n0).count();
      if (region.allocations() != 0) fuzz::fail("allocation in the PLC calls or the NC cycle");
    }
    for (std::size_t i = 0; i < axes_.size(); ++i) {
      const plc::AXIS_REF& axis = *axes_[i];
      AxisProgram& a = programs_[i];
      count(a.reset, a.shown_error[0], tally_);
      count(a.absolute, a.shown_error[1], tally_);
      count(a.relative, a.shown_error[2], tally_);
      count(a.velocity, a.shown_error[3], tally_);
      count(a.halt, a.shown_error[4], tally_);
      count(a.stop, a.shown_error[5], tally_);
      count(a.new_pos, a.shown_error[6], tally_);
      const char* broken = watches_[i].check(axis);
      if (broken != nullptr && !in_break_[i]) ++break_events_[broken];
      in_break_[i] = broken != nullptr;
      if (broken != nullptr) {
        // A soak measures: a broken axis invariant is counted (the first ones printed with the
        // axis's last commands, to reproduce them) and the run goes on; the exit status says it.
        if (++broken_[broken] <= 3) {
          std::fprintf(stderr,
                       "axis %zu, NC cycle %llu: %s: SetVelo %.17g SetAcc %.17g ErrorCode 0x%X\n",
                       i, static_cast<unsigned long long>(ticks_), broken, axis.NcToPlc.SetVelo,
                       axis.NcToPlc.SetAcc, axis.NcToPlc.ErrorCode);
          for (std::size_t k = 0; k < a.history.size(); ++k) {
            const auto& g = a.history[(a.next + k) % a.history.size()];
            if (g.what[0] == '\0') continue;
            std::fprintf(stderr, "  NC cycle %llu: %s %.17g %.17g %.17g %.17g %.17g\n",
                         static_cast<unsigned long long>(g.tick), g.what, g.x[0], g.x[1], g.x[2],
                         g.x[3], g.x[4]);
          }
        }
      }
      if (trace_axis_ == i && ticks_ >= trace_from_) {
        const plc::NCTOPLC_AXIS_REF& n = axis.NcToPlc;
        std::fprintf(stderr,
                     "[%llu] p %.9g v %.9g a %.9g j %.9g cmd %u/%u target %.9g override %u\n",
                     static_cast<unsigned long long>(ticks_), n.SetPos, n.SetVelo, n.SetAcc,
                     n.SetJerk, n.CmdNo, n.CmdState, n.TargetPos, axis.PlcToNc.Override);
      }
      const uint32_t code = axis.NcToPlc.ErrorCode;
      if (code != 0 && code != last_error_[i]) ++tally_.axis_errors[code];
      last_error_[i] = code;
    }
    const double tick_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    worst_nc_ = std::max(worst_nc_, nc_seconds);
    worst_nc_cpu_ = std::max(worst_nc_cpu_, nc_cpu);
    total_nc_cpu_ += nc_cpu;
    worst_tick_ = std::max(worst_tick_, tick_seconds);
    total_nc_ += nc_seconds;
    ++ticks_;
  }

  std::mt19937_64 rng_;
  nc::Kernel kernel_;
  std::vector<nc::AxisConfig> configs_;
  std::vector<plc::AXIS_REF*> axes_;
  std::vector<AxisProgram> programs_;
  std::vector<fuzz::AxisWatch> watches_;
  std::vector<uint32_t> last_error_ = std::vector<uint32_t>(1024, 0);
  Tally tally_;
  std::map<std::string, uint64_t> broken_;        // axis-cycles with an invariant broken, by kind
  std::map<std::string, uint64_t> break_events_;  // times it broke (runs of such cycles)
  std::vector<bool> in_break_ = std::vector<bool>(1024, false);
  uint64_t ticks_ = 0;
  // SOAK_TRACE="AXIS,FROM": print that axis's image every NC cycle from cycle FROM on.
  std::size_t trace_axis_ = static_cast<std::size_t>(-1);
  uint64_t trace_from_ = 0;
  double worst_nc_ = 0.0;
  double worst_tick_ = 0.0;
  double worst_nc_cpu_ = 0.0;
  double total_nc_cpu_ = 0.0;
  double total_nc_ = 0.0;
  double seconds_ = 0.0;
};

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  Soak soak(options);
  const uint64_t cycles = (options.axis_cycles + options.axes - 1) / options.axes;
  soak.run(cycles);
  soak.report(options);
  return soak.held() ? 0 : 1;
}
