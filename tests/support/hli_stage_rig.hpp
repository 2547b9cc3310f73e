// A test rig for the HLI coupling stage on its own (nc_core/src/hli/hli_stage.hpp): it plays the
// kernel's part — per-axis program positions, velocities and accelerations in, drive values and
// stop codes out — so that the stage's rules can be checked with the seed's numbers before the
// kernel calls it. Program motion here is a constant-velocity ramp ending exactly at its target.
// Only the test_hli_stage_* files may include it (they alone see nc_core's private headers).
#pragma once

#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <vector>

#include "hli/hli_stage.hpp"
#include "plc_interface/error_code.hpp"
#include "plc_interface/hli.hpp"

namespace hlitest {

namespace h = plc::hli;

inline constexpr double kT = 0.001;  // s, NC cycle

struct Rig {
  nc::hli::HliStage stage{kT};
  std::vector<double> q, qv, qa, d, dv, da;
  std::unique_ptr<bool[]> referenced;  // std::vector<bool> has no span
  std::vector<plc::ErrorCode> stop;
  std::vector<plc::ErrorCode> refusal;  // the kernel's reasons per axis; empty: none

  // Axes with the given logical numbers (ax_nr), in this order; `setup` is the template.
  explicit Rig(std::initializer_list<int> ax_nrs, nc::hli::AxisSetup setup = {}) {
    std::vector<nc::hli::AxisSetup> setups;
    for (const int nr : ax_nrs) {
      setup.ax_nr = nr;
      setups.push_back(setup);
    }
    init(setups);
  }
  // Axes with their own set-up each.
  explicit Rig(const std::vector<nc::hli::AxisSetup>& setups) { init(setups); }

  void init(const std::vector<nc::hli::AxisSetup>& setups) {
    stage.reserve(setups.size());
    for (const nc::hli::AxisSetup& s : setups)
      stage.add_axis(s);
    const std::size_t n = setups.size();
    q.assign(n, 0.0);
    qv.assign(n, 0.0);
    qa.assign(n, 0.0);
    d.assign(n, 0.0);
    dv.assign(n, 0.0);
    da.assign(n, 0.0);
    referenced = std::make_unique<bool[]>(n);
    stop.assign(n, plc::ErrorCode::kNone);
  }

  std::size_t n() const { return q.size(); }

  h::HLI_AX_COUPLING& unit(std::size_t axis) {
    return stage.gpAx()[axis]->lr_mc_control.axis_coupling;
  }

  int32_t active_rev_r(std::size_t axis) { return stage.gpAx()[axis]->lr_state.active_rev_r; }

  // Writes a list (entries up to the first INACTIVE) and sets the semaphore, as a PLC does.
  void command(std::size_t target, std::initializer_list<h::HLI_AX_COUPLING_DESC> list) {
    h::HLI_AX_COUPLING_COMMAND& c = unit(target).command_w;
    c.desc = {};
    std::size_t i = 0;
    for (const h::HLI_AX_COUPLING_DESC& e : list)
      c.desc[i++] = e;
    c.semaphor_rw = true;
  }

  bool cycle() {
    return stage.cycle(nc::hli::Inputs{q, qv, qa, {referenced.get(), n()}, refusal},
                       nc::hli::Outputs{d, dv, da, stop});
  }

  void cycles(int count) {
    for (int i = 0; i < count; ++i)
      cycle();
  }

  // Moves axis `axis`'s program by `distance` at `velocity` (> 0), one cycle after another, and
  // ends exactly at the target with velocity 0; returns the number of cycles run.
  int move(std::size_t axis, double distance, double velocity) {
    const double target = q[axis] + distance;
    const double step = std::copysign(velocity * kT, distance);
    int count = 0;
    while (std::abs(target - q[axis]) > std::abs(step)) {
      q[axis] += step;
      qv[axis] = std::copysign(velocity, distance);
      cycle();
      ++count;
    }
    q[axis] = target;
    qv[axis] = 0.0;
    cycle();
    return count + 1;
  }
};

inline h::HLI_AX_COUPLING_DESC direct(int ax_nr) {
  return {ax_nr, h::HLI_AXIS_COUPLING_DIRECT, 0, 0};
}
inline h::HLI_AX_COUPLING_DESC mirror(int ax_nr) {
  return {ax_nr, h::HLI_AXIS_COUPLING_MIRROR, 0, 0};
}
inline h::HLI_AX_COUPLING_DESC zero(int ax_nr) {
  return {ax_nr, h::HLI_AXIS_COUPLING_ZERO, 0, 0};
}
inline h::HLI_AX_COUPLING_DESC fract(int ax_nr, int16_t num, int16_t denom) {
  return {ax_nr, h::HLI_AXIS_COUPLING_FRACT, num, denom};
}
inline h::HLI_AX_COUPLING_DESC inactive() {
  return {0, h::HLI_AXIS_COUPLING_INACTIVE, 0, 0};
}

}  // namespace hlitest
