// A PLC for HLI tests on the real kernel: one nc::Kernel, and per axis an MC_Power, an
// MC_MoveAbsolute, an MC_Reset and an fb::HLI_AxisCoupling (on gpAx[i]), all called every tick
// before the NC cycle, as the cycle driver runs them. Axes carry the seed's Dynamics 1.1
// parameters (kernel_harness.hpp); the logical numbers (AxisConfig::id) are given.
//
// Test code: set-up allocates; tick() itself allocates nothing (the no-allocation test uses it).
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>
#include <vector>

#include "fb/fb.hpp"
#include "kernel_harness.hpp"
#include "nc_core/kernel.hpp"
#include "plc_interface/hli.hpp"

namespace hlik {

namespace h = plc::hli;
using List = std::initializer_list<h::HLI_AX_COUPLING_DESC>;

inline nc::AxisConfig axis(int id, std::string name) {
  nc::AxisConfig c = kt::seed_axis(std::move(name));
  c.id = id;
  return c;
}

struct Rig {
  nc::Kernel kernel;
  std::vector<plc::AXIS_REF*> axes;
  std::vector<fb::MC_Power> power;
  std::vector<fb::MC_MoveAbsolute> move;
  std::vector<fb::MC_Reset> reset;
  std::vector<fb::HLI_AxisCoupling> coupling;

  explicit Rig(const std::vector<nc::AxisConfig>& configs) {
    for (const nc::AxisConfig& c : configs)
      axes.push_back(&kernel.add_axis(c));
    power.resize(axes.size());
    move.resize(axes.size());
    reset.resize(axes.size());
    coupling.resize(axes.size());
    for (fb::MC_Power& p : power) {
      p.Enable = true;
      p.Enable_Positive = true;
      p.Enable_Negative = true;
    }
    tick();
  }

  void tick() noexcept {
    const auto gpAx = kernel.gpAx();
    for (std::size_t i = 0; i < axes.size(); ++i) {
      power[i](*axes[i]);
      move[i](*axes[i]);
      reset[i](*axes[i]);
      coupling[i](gpAx[i]);
    }
    kernel.cycle();
  }
  void ticks(int n) noexcept {
    for (int k = 0; k < n; ++k)
      tick();
  }

  uint32_t last_coupling_error = 0;  // ErrorID of the last couple()

  // Sets axis i's list with an Execute edge; ticks until Done or Error. True when taken.
  bool couple(std::size_t i, List list) {
    fb::HLI_AxisCoupling& c = coupling[i];
    c.desc = {};
    std::size_t k = 0;
    for (const h::HLI_AX_COUPLING_DESC& d : list)
      c.desc[k++] = d;
    c.Execute = true;
    for (int n = 0; n < 10 && !c.Done && !c.Error; ++n)
      tick();
    const bool done = c.Done;
    last_coupling_error = c.ErrorID;
    c.Execute = false;
    tick();
    return done;
  }

  // Starts MC_MoveAbsolute on axis i (rising edge in the next tick).
  void start_move(std::size_t i, double position, double velocity = 2200.0) {
    fb::MC_MoveAbsolute& m = move[i];
    m.Execute = false;
    tick();
    m.Position = position;
    m.Velocity = velocity;
    m.Execute = true;
  }
  // Ticks until axis i's move is Done (true) or ends otherwise / `limit` ticks pass (false).
  bool finish_move(std::size_t i, int limit = 20000) {
    fb::MC_MoveAbsolute& m = move[i];
    for (int n = 0; n < limit; ++n) {
      tick();
      if (m.Done) break;
      if (m.Error || m.CommandAborted) break;
    }
    const bool done = m.Done;
    m.Execute = false;
    tick();
    return done;
  }
  bool move_to(std::size_t i, double position, double velocity = 2200.0) {
    start_move(i, position, velocity);
    return finish_move(i);
  }

  // Seed example 2 in motion: Y2 (index 1) coupled DIRECT to axis 1 and to itself, axis 1 moving
  // to 900 mm and Y2's program to `y2_target` at `y2_velocity`, `n` ticks on. True when taken.
  bool run_example_2(double y2_target, double y2_velocity, int n) {
    if (!couple(1,
                {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}, {8, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}})) {
      return false;
    }
    start_move(0, 900.0);
    start_move(1, y2_target, y2_velocity);
    ticks(n);
    return true;
  }

  // MC_Reset on axis i; true when Done.
  bool reset_axis(std::size_t i) {
    reset[i].Execute = true;
    for (int n = 0; n < 10 && !reset[i].Done && !reset[i].Error; ++n)
      tick();
    const bool done = reset[i].Done;
    reset[i].Execute = false;
    tick();
    return done;
  }

  double set_pos(std::size_t i) const { return axes[i]->NcToPlc.SetPos; }
  uint32_t error(std::size_t i) const { return axes[i]->NcToPlc.ErrorCode; }
};

}  // namespace hlik
