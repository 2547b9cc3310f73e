// A two-speed axis in closed loop for tests: TwoSpeedSequencer → 12-byte image → TwoSpeedPlant →
// encoder → sequencer, one NC cycle at a time, with a recorded trace (SPEC E1-E6).
//
// Test code: the trace allocates. A no-allocation test sets `record = false` (or reserves) before
// its counted region. Needs nc_core's private headers (tests/CMakeLists.txt gives them to
// test_two_speed_* files).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "nc_core/axis_config.hpp"
#include "plc_interface/two_speed.hpp"
#include "two_speed/two_speed_plant.hpp"
#include "two_speed/two_speed_sequencer.hpp"

namespace ts {

using nc::detail::TwoSpeedEvent;
using plc::ControlByteBit;
using State = plc::TwoSpeedAxisState;

// Issue 12's example parameters: rapid 500 mm/s, creep 50 mm/s, creep distance 100 / 120 mm,
// braking distance 5 / 6 mm (+ / -), brake release delay 0.05 s, rapid-to-creep delay 0.02 s,
// brake incidence delay 0.03 / 0.04 s, creep distance for stop 20 mm, looping distance 30 mm
// (off unless a test enables it); the plant ramps 0 → 500 mm/s in 0.1 s; encoder 1e-4 mm.
inline nc::AxisConfig issue_axis() {
  nc::AxisConfig c;
  c.name = std::string("T");
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
  c.looping_distance_enabled = false;
  c.looping_distance = 30.0;
  c.two_speed_ramp_time = 0.1;
  c.encoder_increment = 1e-4;
  return c;
}

// One NC cycle as seen from outside.
struct Sample {
  int cycle = 0;
  double actual = 0.0;    // encoder position the sequencer read in this cycle
  double velocity = 0.0;  // plant velocity after the cycle
  plc::NCTOIO_DRIVE_TWO_SPEED image{};
  State state = State::kInactive;
  TwoSpeedEvent event = TwoSpeedEvent::kNone;
  plc::ErrorCode error = plc::ErrorCode::kNone;

  bool bit(ControlByteBit b) const { return plc::bit_set(image.nControlByte, b); }
  bool travel() const { return (image.nControlByte & 0x0F) != 0; }
  bool brake() const { return bit(ControlByteBit::bBreak); }
  bool operator==(const Sample&) const = default;
};

class Loop {
 public:
  explicit Loop(const nc::AxisConfig& config, double position = 0.0, double dt = 0.001)
      : sequencer(config), plant(config, position), dt_(dt) {
    sequencer.set_enabled(true);
  }

  double actual() const { return plant.position(); }
  plc::ErrorCode start(double target, double velocity) {
    return sequencer.start(target, velocity, actual());
  }
  plc::ErrorCode stop() { return sequencer.stop(actual()); }
  void set_override_percent(double percent) {
    (void)sequencer.set_override(static_cast<uint32_t>(percent * plc::kOverrideFull / 100.0));
  }

  // One NC cycle: the sequencer reads the encoder, the plant runs with the image for dt.
  const Sample& cycle() {
    last_.cycle = cycles_++;
    last_.actual = plant.position();
    const nc::detail::TwoSpeedCycle out = sequencer.step(last_.actual, dt_);
    plant.step(sequencer.image(), dt_);
    last_.velocity = plant.velocity();
    last_.image = sequencer.image();
    last_.state = out.state;
    last_.event = out.event;
    last_.error = out.error;
    if (record) trace.push_back(last_);
    return last_;
  }

  // Cycles until an event (positioning done, stop done, error) or `max_cycles`; calls `each`
  // before every cycle (to act on the axis at a chosen moment).
  const Sample& run_to_event(int max_cycles = 20000,
                             const std::function<void(Loop&)>& each = nullptr) {
    for (int i = 0; i < max_cycles; ++i) {
      if (each) each(*this);
      if (cycle().event != TwoSpeedEvent::kNone) break;
    }
    return last_;
  }
  // `cycles` NC cycles with nothing done in between (by default long enough for the plant to
  // come to rest after a positioning).
  void run_cycles(int cycles = 200) {
    for (int i = 0; i < cycles; ++i)
      cycle();
  }

  nc::detail::TwoSpeedSequencer sequencer;
  nc::detail::TwoSpeedPlant plant;
  std::vector<Sample> trace;
  bool record = true;

 private:
  double dt_;
  int cycles_ = 0;
  Sample last_;
};

// Index of the first sample at or after `from` for which `pred` holds; kNotFound when none.
inline constexpr std::size_t kNotFound = static_cast<std::size_t>(-1);
// Any trace whose samples have `state` and `image` (also the kernel rig's, tsk::Sample).
template <class Trace, class Pred>
std::size_t first(const Trace& trace, Pred pred, std::size_t from = 0) {
  for (std::size_t i = from; i < trace.size(); ++i) {
    if (pred(trace[i])) return i;
  }
  return kNotFound;
}

// The nAxisState values in order, each run of equal values once (21, 22, 23, 24, 20).
template <class Trace>
std::vector<uint32_t> state_sequence(const Trace& trace) {
  std::vector<uint32_t> out;
  for (const auto& s : trace) {
    const auto v = static_cast<uint32_t>(s.state);
    if (out.empty() || out.back() != v) out.push_back(v);
  }
  return out;
}

// Every cycle's image: both control bytes consistent, nothing in the reserved fields.
template <class Trace>
bool images_consistent(const Trace& trace) {
  for (const auto& s : trace) {
    if (!plc::control_bytes_consistent(s.image) || s.image.nReserved != 0 ||
        s.image.nOutData1 != 0 || s.image.nOutData2 != 0) {
      return false;
    }
  }
  return true;
}

}  // namespace ts
