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

}  // namespace kt
