// The block bad-input tests' shared program and comparison (brief: "a refused command does not
// change the axis"; SPEC A4): one PLC program — MC_Power enables the axis, MC_MoveAbsolute moves
// it to 2000 mm at 1000 mm/s — run on the real kernel twice, once plain and once with a bad block
// injected at one tick; the bad block must show Error with its specific ErrorID on every call
// after the NC saw its command, and the image (Sample) must be the same at every tick as in the
// plain run, the move ending as there. Each test file keeps its blocks and its list of cases.
//
// Test code: it allocates (traces, std::function).
#pragma once

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "fb/fb.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"

namespace twin {

constexpr double kCycle = 0.001;         // s
constexpr uint64_t kRunTicks = 3'200;    // the move ends at about 2.1 s
constexpr double kMoveTarget = 2'000.0;  // mm, the seed's MoveAxis target (seed 000 §4.3)
constexpr double kMoveSpeed = 1'000.0;   // mm/s

// What the bad block shows after one call.
struct Shown {
  bool busy = false, error = false;
  uint32_t error_id = 0;
};

// The image compared between the two runs, every tick: every field of the NC→PLC image the
// kernel publishes for these blocks (bar the cycle counter), and the PLC→NC words the program
// and the bad blocks write (override, control word, external set values).
struct Sample {
  uint32_t state_dword, error_code, axis_state, warning;
  double act_pos, modulo_act_pos, act_velo, pos_diff, set_pos, modulo_set_pos, set_velo, set_acc,
      set_jerk, target_pos;
  double compensation_distance, compensation_length, compensation_velocity_diff;
  uint16_t cmd_no, cmd_state;
  uint32_t override_raw, control_dword;
  double ext_pos, ext_velo, ext_acc;
  int32_t ext_direction;
  bool operator==(const Sample&) const = default;
};

inline Sample sample(const plc::AXIS_REF& axis) {
  const plc::NCTOPLC_AXIS_REF& n = axis.NcToPlc;
  const plc::PLCTONC_AXIS_REF& p = axis.PlcToNc;
  return Sample{n.StateDWord,
                n.ErrorCode,
                n.AxisState,
                n.Warning,
                n.ActPos,
                n.ModuloActPos,
                n.ActVelo,
                n.PosDiff,
                n.SetPos,
                n.ModuloSetPos,
                n.SetVelo,
                n.SetAcc,
                n.SetJerk,
                n.TargetPos,
                n.CompensationDistance,
                n.CompensationLength,
                n.CompensationVelocityDiff,
                n.CmdNo,
                n.CmdState,
                p.Override,
                p.ControlDWord,
                p.ExtSetPos,
                p.ExtSetVelo,
                p.ExtSetAcc,
                p.ExtSetDirection};
}

// One call of an Execute block with Execute = `execute`, and what it shows.
template <class Block>
Shown call_execute(Block& block, plc::AXIS_REF& axis, bool execute = true) {
  block.Execute = execute;
  block(axis);
  return Shown{block.Busy, block.Error, block.ErrorID};
}

// One run of the program: the per-tick image samples and what the move and the bad block did.
struct Run {
  std::vector<Sample> trace;
  int64_t move_done_tick = -1;
  bool move_aborted_or_failed = false;
  std::vector<Shown> bad;  // the bad block's outputs from the injection on
};

// A bad block entering the program at `tick`: `spoil` sets its bad input (it may also spoil
// MC_Power's inputs) before MC_Power's call of that tick; `call` runs the bad block after the
// move's call, every tick from `tick` on.
struct Injection {
  uint64_t tick = 0;
  std::function<void(fb::MC_Power&)> spoil;
  std::function<Shown(fb::MC_Power&, plc::AXIS_REF&)> call;
};

// Runs the program for kRunTicks ticks on an axis with `config`, sampling the axis after each
// tick; without an injection (nullptr) it is the reference run.
inline Run run_program(const nc::AxisConfig& config, const Injection* bad) {
  nc::Kernel kernel(nc::KernelConfig{kCycle});
  plc::AXIS_REF& axis = kernel.add_axis(config);
  nc::CycleDriver driver(kernel);

  fb::MC_Power power;
  fb::MC_MoveAbsolute move;
  Run result;
  result.trace.reserve(kRunTicks);

  driver.add_task("plc", kCycle, [&] {
    const uint64_t tick = driver.ticks();
    power.Enable = true;
    power.Enable_Positive = true;
    power.Enable_Negative = true;
    if (bad != nullptr && tick == bad->tick) bad->spoil(power);
    power(axis);

    move.Position = kMoveTarget;
    move.Velocity = kMoveSpeed;
    move.Execute = tick >= 2;  // after the enables are in
    move(axis);
    if (move.Done && result.move_done_tick < 0) result.move_done_tick = static_cast<int64_t>(tick);
    if (move.CommandAborted || move.Error) result.move_aborted_or_failed = true;

    if (bad != nullptr && tick >= bad->tick) result.bad.push_back(bad->call(power, axis));
  });
  for (uint64_t i = 0; i < kRunTicks; ++i) {
    driver.tick();
    result.trace.push_back(sample(axis));
  }
  return result;
}

// The bad block: Error with `code` by the call after the NC saw the command, and it stays while
// Execute stays high; never accepted. Nothing else changed: the running move ends as in `ref`,
// and the sampled image is the same at every tick.
inline void require_refused_without_effect(const Run& bad, const Run& ref, uint32_t code) {
  REQUIRE(bad.bad.size() > 2);
  for (std::size_t i = 1; i < bad.bad.size(); ++i) {
    INFO("call " << i << " after the rising edge");
    REQUIRE(bad.bad[i].error);
    REQUIRE(bad.bad[i].error_id == code);
    REQUIRE_FALSE(bad.bad[i].busy);
  }
  REQUIRE_FALSE(bad.move_aborted_or_failed);
  REQUIRE(bad.move_done_tick == ref.move_done_tick);
  REQUIRE(bad.trace.size() == ref.trace.size());
  for (std::size_t t = 0; t < ref.trace.size(); ++t) {
    if (!(bad.trace[t] == ref.trace[t])) {
      FAIL_CHECK("NC image differs at tick " << t);
      break;
    }
  }
}

}  // namespace twin
