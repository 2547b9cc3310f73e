// A scripted PLC for kernel tests: one Kernel, commands posted straight into the mailboxes (no
// function blocks), cycle-by-cycle access to the NC→PLC image.
//
// Test code: it allocates freely (it records traces), so never use it inside a counted
// no-allocation region.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "nc_core/axis_config.hpp"
#include "nc_core/kernel.hpp"
#include "plc_interface/axis_ref.hpp"
#include "plc_interface/command.hpp"
#include "plc_interface/error_code.hpp"

namespace kt {

// An axis with the seed's Dynamics 1.1 parameters (seed 000 §2.1): A+ = A- = 5000 mm/s²,
// J = 50000 mm/s³, Vmax = Vref = 2200 mm/s, ideal drive, encoder increment 1e-4 mm.
inline nc::AxisConfig seed_axis(std::string name = "X") {
  nc::AxisConfig c;
  c.name = std::move(name);
  c.max_velocity = 2200.0;
  c.ref_velocity = 2200.0;
  c.acceleration = 5000.0;
  c.deceleration = 5000.0;
  c.jerk = 50000.0;
  return c;
}

inline plc::Command move_absolute(double position, double velocity, double acceleration = 0.0,
                                  double deceleration = 0.0, double jerk = 0.0) {
  plc::Command c;
  c.type = plc::CommandType::kMoveAbsolute;
  c.position = position;
  c.velocity = velocity;
  c.acceleration = acceleration;
  c.deceleration = deceleration;
  c.jerk = jerk;
  return c;
}

inline plc::Command move_relative(double distance, double velocity) {
  plc::Command c = move_absolute(distance, velocity);
  c.type = plc::CommandType::kMoveRelative;
  return c;
}

// direction: +1 / -1, or the MC_Direction values 1 / 3.
inline plc::Command move_velocity(double velocity, int32_t direction, double acceleration = 0.0,
                                  double deceleration = 0.0, double jerk = 0.0) {
  plc::Command c;
  c.type = plc::CommandType::kMoveVelocity;
  c.velocity = velocity;
  c.direction = direction;
  c.acceleration = acceleration;
  c.deceleration = deceleration;
  c.jerk = jerk;
  return c;
}

inline plc::Command simple(plc::CommandType type, double deceleration = 0.0, double jerk = 0.0) {
  plc::Command c;
  c.type = type;
  c.deceleration = deceleration;
  c.jerk = jerk;
  return c;
}

inline uint32_t id(plc::ErrorCode code) {
  return plc::to_id(code);
}

// Controller enable and both feed enables, as MC_Power writes them.
inline void set_enables(plc::AXIS_REF& axis, bool enable, bool plus = true, bool minus = true) {
  uint32_t w = axis.PlcToNc.ControlDWord;
  w = plc::with_bit(w, plc::kControlEnable, enable);
  w = plc::with_bit(w, plc::kControlFeedEnablePlus, plus);
  w = plc::with_bit(w, plc::kControlFeedEnableMinus, minus);
  axis.PlcToNc.ControlDWord = w;
}

inline bool bit(const plc::AXIS_REF& axis, plc::StateBit b) {
  return plc::test_bit(axis.NcToPlc.StateDWord, b);
}

inline plc::AxisState axis_state(const plc::AXIS_REF& axis) {
  return static_cast<plc::AxisState>(axis.NcToPlc.AxisState);
}

// One kernel with one axis (more can be added), enabled unless asked otherwise.
struct Harness {
  nc::Kernel kernel;
  plc::AXIS_REF* x;

  explicit Harness(const nc::AxisConfig& config = seed_axis(), double cycle_time = 0.001,
                   bool enabled = true)
      : kernel(nc::KernelConfig{cycle_time}), x(&kernel.add_axis(config)) {
    set_enables(*x, enabled);
    kernel.cycle();
  }

  uint16_t post(const plc::Command& c) { return x->Mailbox.post(c); }
  plc::CommandAnswer answer(uint16_t number) const { return x->Mailbox.answer(number); }
  plc::CommandState state_of(uint16_t number) const { return answer(number).state; }
  void cycles(int n) {
    for (int i = 0; i < n; ++i)
      kernel.cycle();
  }
  // Cycles until pred() holds (checked after each cycle); returns the number of cycles run, or
  // -1 when `limit` cycles passed without it.
  template <class Pred>
  int cycles_until(Pred pred, int limit = 100000) {
    for (int i = 1; i <= limit; ++i) {
      kernel.cycle();
      if (pred()) return i;
    }
    return -1;
  }
};

// Set and actual values of one cycle, for traces.
struct Sample {
  double set_pos, set_velo, set_acc, set_jerk, act_pos, act_velo, pos_diff;
  uint32_t state_word, error_code, axis_state;
  uint16_t cmd_no, cmd_state;
};

inline Sample sample(const plc::AXIS_REF& axis) {
  const auto& o = axis.NcToPlc;
  return Sample{o.SetPos,  o.SetVelo,    o.SetAcc,    o.SetJerk,   o.ActPos, o.ActVelo,
                o.PosDiff, o.StateDWord, o.ErrorCode, o.AxisState, o.CmdNo,  o.CmdState};
}

// Bitwise equality of two NC→PLC images (doubles compared by their bits, so -0.0 != 0.0 and a
// NaN would be noticed).
inline bool same_image(const plc::NCTOPLC_AXIS_REF& a, const plc::NCTOPLC_AXIS_REF& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// --- superpositions (B7, B8) ---

// MC_MoveSuperImposed's command (seed 000 §2.5 start parameters).
inline plc::Command move_superimposed(double distance, double velocity_diff, double acceleration,
                                      double deceleration, double process_velocity, double length) {
  plc::Command c;
  c.type = plc::CommandType::kMoveSuperImposed;
  c.position = distance;
  c.velocity = velocity_diff;
  c.acceleration = acceleration;
  c.deceleration = deceleration;
  c.process_velocity = process_velocity;
  c.length = length;
  return c;
}

// MC_ExtSetPointGenEnable's command; position_type 1 absolute, 2 relative.
inline plc::Command ext_enable(double position, int32_t position_type) {
  plc::Command c;
  c.type = plc::CommandType::kExtSetPointGenEnable;
  c.position = position;
  c.mode = position_type;
  return c;
}

// What MC_ExtSetPointGenFeed writes.
inline void feed(plc::AXIS_REF& axis, double position, double velocity, double acceleration,
                 int32_t direction) {
  axis.PlcToNc.ExtSetPos = position;
  axis.PlcToNc.ExtSetVelo = velocity;
  axis.PlcToNc.ExtSetAcc = acceleration;
  axis.PlcToNc.ExtSetDirection = direction;
}

// --- online functions (B1, B3-B6) ---

// The online functions' commands, with the fields plc_interface/command.hpp names.
inline plc::Command new_pos(double position) {
  plc::Command c;
  c.type = plc::CommandType::kNewPos;
  c.position = position;
  return c;
}

inline plc::Command new_pos_and_velo(double end_position, double velocity,
                                     double activation_position) {
  plc::Command c;
  c.type = plc::CommandType::kNewPosAndVelo;
  c.position = end_position;
  c.velocity = velocity;
  c.activation_position = activation_position;
  return c;
}

// direction: the MC_Direction value (1 positive, 2 shortest way, 3 negative, 4 current).
inline plc::Command move_modulo(double position, double velocity, int32_t direction) {
  plc::Command c = move_absolute(position, velocity);
  c.type = plc::CommandType::kMoveModulo;
  c.direction = direction;
  return c;
}

// Override in percent, written as MC_Power / MC_SetOverride write it (1'000'000 = 100 %).
inline void set_override(plc::AXIS_REF& axis, double percent) {
  axis.PlcToNc.Override = static_cast<uint32_t>(std::lround(percent * 10'000.0));
}

// The limits of seed 000 §2.1 checked on the published set values of every cycle (SPEC B2, path
// relative): |v| <= V; |a| <= A+ while |v| grows and <= A- while it shrinks; |SetJerk| <= J.
// Between two cycles the set values must also be continuous as those limits allow: the change
// of a at most J·T, of v at most max(A+, A-)·T, of p at most V·T — a replan that jumps shows
// here even when each sample is inside the bounds. Tolerance: relative 1e-9 plus 1e-9 absolute.
struct LimitChecker {
  double cycle_time = 0.001;
  double velocity = 0.0;      // V
  double acceleration = 0.0;  // A+
  double deceleration = 0.0;  // A-
  double jerk = 0.0;          // J
  long cycles = 0;
  long violations = 0;
  std::string first;  // the first violation, for the test's message

  // The seed axis (kt::seed_axis) moving at up to `v`.
  static LimitChecker seed(double v, double cycle_time = 0.001) {
    LimitChecker c;
    c.cycle_time = cycle_time;
    c.velocity = v;
    c.acceleration = 5000.0;
    c.deceleration = 5000.0;
    c.jerk = 50000.0;
    return c;
  }

  void check(const plc::AXIS_REF& axis) {
    const auto& o = axis.NcToPlc;
    ++cycles;
    const double v = o.SetVelo;
    const double a = o.SetAcc;
    auto over = [](double value, double bound) {
      return std::fabs(value) > bound * (1.0 + 1e-9) + 1e-9;
    };
    const double a_bound = v * a > 0.0   ? acceleration
                           : v * a < 0.0 ? deceleration
                                         : std::fmax(acceleration, deceleration);
    if (over(v, velocity)) fail("|v|", v, velocity);
    if (over(a, a_bound)) fail("|a|", a, a_bound);
    if (over(o.SetJerk, jerk)) fail("|jerk|", o.SetJerk, jerk);
    if (has_previous_) {
      if (over(a - a_, jerk * cycle_time)) fail("|da| per cycle", a - a_, jerk * cycle_time);
      const double dv_bound = std::fmax(acceleration, deceleration) * cycle_time;
      if (over(v - v_, dv_bound)) fail("|dv| per cycle", v - v_, dv_bound);
      if (over(o.SetPos - p_, velocity * cycle_time)) {
        fail("|dp| per cycle", o.SetPos - p_, velocity * cycle_time);
      }
    }
    has_previous_ = true;
    p_ = o.SetPos;
    v_ = v;
    a_ = a;
  }

  bool ok() const { return violations == 0; }

 private:
  void fail(const char* what, double value, double bound) {
    if (violations++ == 0) {
      first = std::string(what) + " = " + std::to_string(value) + " > " + std::to_string(bound) +
              " at cycle " + std::to_string(cycles);
    }
  }
  bool has_previous_ = false;
  double p_ = 0.0, v_ = 0.0, a_ = 0.0;
};

// Runs `n` cycles, checking each.
inline void checked_cycles(Harness& h, LimitChecker& checker, int n) {
  for (int i = 0; i < n; ++i) {
    h.kernel.cycle();
    checker.check(*h.x);
  }
}

// Cycles, checking each, until pred() holds; the number of cycles run, or -1 after `limit`.
template <class Pred>
int checked_cycles_until(Harness& h, LimitChecker& checker, Pred pred, int limit = 100000) {
  for (int i = 1; i <= limit; ++i) {
    h.kernel.cycle();
    checker.check(*h.x);
    if (pred()) return i;
  }
  return -1;
}

// Two identical kernels side by side: a command goes to the probe only, and the NC→PLC images
// must stay bit-identical — a refused command disturbs nothing (SPEC B2).
struct TwinKernels {
  Harness probe;
  Harness reference;

  explicit TwinKernels(const nc::AxisConfig& config = seed_axis())
      : probe(config), reference(config) {}

  // Posts to both; the number (the same in both while every post goes to both).
  uint16_t both(const plc::Command& c) {
    reference.post(c);
    return probe.post(c);
  }
  void cycles(int n) {
    for (int i = 0; i < n; ++i) {
      probe.kernel.cycle();
      reference.kernel.cycle();
    }
  }
  // The same enables on both (see set_enables).
  void enables(bool enable, bool plus, bool minus) {
    set_enables(*probe.x, enable, plus, minus);
    set_enables(*reference.x, enable, plus, minus);
  }
  bool same() const { return same_image(probe.x->NcToPlc, reference.x->NcToPlc); }
};

}  // namespace kt
