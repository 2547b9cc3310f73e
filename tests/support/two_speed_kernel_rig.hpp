// A two-speed axis in the kernel, driven end to end through function blocks and AXIS_REF (SPEC
// E1-E6): one PLC call of the blocks, then one NC cycle, with a recorded trace of what the NC
// published and Kernel::two_speed_output().
//
// Test code: the trace allocates. A no-allocation test sets `record = false` before its counted
// region. The axis is issue 12's (two_speed_loop.hpp: ts::issue_axis).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "fb/fb.hpp"
#include "nc_core/kernel.hpp"
#include "plc_interface/two_speed.hpp"
#include "two_speed_loop.hpp"

namespace tsk {

using State = plc::TwoSpeedAxisState;
using C = plc::ControlByteBit;

// One NC cycle as the PLC sees it.
struct Sample {
  int cycle = 0;
  double read = 0.0;    // the encoder value the NC read at the start of this cycle
  double actual = 0.0;  // NcToPlc.ActPos after it
  plc::NCTOIO_DRIVE_TWO_SPEED image{};
  State state = State::kInactive;  // NcToPlc.AxisState = nAxisState
  uint32_t state_word = 0;
  uint32_t error = 0;

  bool bit(C b) const { return plc::bit_set(image.nControlByte, b); }
  bool travel() const { return (image.nControlByte & 0x0F) != 0; }
  bool brake() const { return bit(C::bBreak); }
  bool operator==(const Sample&) const = default;
};

struct Rig {
  nc::Kernel kernel;
  plc::AXIS_REF& axis;
  fb::MC_Power power;
  fb::MC_MoveAbsolute move;
  fb::MC_MoveRelative relative;
  fb::MC_Stop stop;
  fb::MC_Halt halt;
  fb::MC_Reset reset;
  fb::MC_SetOverride override_block;
  std::vector<Sample> trace;
  bool record = true;
  // Called in the PLC task before the blocks, each cycle (to act at a chosen moment).
  std::function<void(Rig&)> each;

  explicit Rig(const nc::AxisConfig& config = ts::issue_axis())
      : kernel(nc::KernelConfig{0.001}), axis(kernel.add_axis(config)) {
    power.Enable = true;
    power.Enable_Positive = true;
    power.Enable_Negative = true;
    cycle();  // enabled: nAxisState 0 until the first start
  }

  const plc::NCTOIO_DRIVE_TWO_SPEED& image() const { return kernel.two_speed_output("T"); }
  double actual() const { return axis.NcToPlc.ActPos; }
  State state() const { return static_cast<State>(axis.NcToPlc.AxisState); }

  // One PLC task call of every block, then one NC cycle.
  const Sample& cycle() {
    if (each) each(*this);
    power(axis);
    move(axis);
    relative(axis);
    stop(axis);
    halt(axis);
    reset(axis);
    override_block(axis);
    Sample s;
    s.cycle = static_cast<int>(kernel.cycle_count());
    s.read = axis.NcToPlc.ActPos;
    kernel.cycle();
    s.actual = axis.NcToPlc.ActPos;
    s.image = image();
    s.state = static_cast<State>(axis.NcToPlc.AxisState);
    s.state_word = axis.NcToPlc.StateDWord;
    s.error = axis.NcToPlc.ErrorCode;
    last = s;
    if (record) trace.push_back(s);
    return last;
  }
  void cycles(int n) {
    for (int i = 0; i < n; ++i)
      cycle();
  }
  // Cycles until pred() holds after a cycle; the number run, or -1 after `limit`.
  int cycles_until(const std::function<bool()>& pred, int limit = 20000) {
    for (int i = 1; i <= limit; ++i) {
      cycle();
      if (pred()) return i;
    }
    return -1;
  }

  // MC_MoveAbsolute to `target` at `velocity`, run until its brake is on and the block shows
  // Done; false when it does not end in time. The trace starts with the start's cycle (T0).
  bool position_to(double target, double velocity = 2000.0) {
    move.Execute = false;
    cycle();
    trace.clear();
    move.Position = target;
    move.Velocity = velocity;
    move.Execute = true;
    return cycles_until([this] { return move.Done || move.Error; }) > 0 && move.Done;
  }

  Sample last;
};

// ts::first, ts::state_sequence and ts::images_consistent (two_speed_loop.hpp) read a trace of
// these samples too.

}  // namespace tsk
