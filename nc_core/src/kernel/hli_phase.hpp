// Phase (c) of the NC cycle: the HLI coupling stage (SPEC D3–D5, seed 002) run over the kernel's
// axes. It owns the stage (nc::hli::HliStage) and the per-axis arrays the stage reads and writes,
// all sized in add_axis, so run() allocates nothing.
//
// The stage is "engaged" while it can make any drive position d differ from the program position
// q: a list in force, a stopped target braking, an offset left by a list switched off, or a
// semaphore set by the PLC. Only then does the kernel run phase (c) (and the whole kernel as one
// block, since the stage needs every axis's q); otherwise d = q and phase (c) costs one flag read
// per axis and cycle (the semaphores), nothing before the units were handed out (gpAx()).
//
// Safety (docs/behaviour.md "HLI axis coupling", "A target's own error"): before the stage runs,
// a target that is in axis error or has lost its controller enable loses its list (the stage
// brakes its drive, HliStage::stop); a new list on such an axis, or on one with external
// setpoint generation enabled, is refused. Each axis is told its HLI role (CoupleState).
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "hli/hli_stage.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/axis_snapshot.hpp"
#include "plc_interface/axis_ref.hpp"
#include "plc_interface/error_code.hpp"
#include "plc_interface/hli.hpp"

namespace nc::detail {

class ServoAxis;

class HliPhase {
 public:
  explicit HliPhase(double cycle_time) : stage_(cycle_time) {}

  // Set-up: the axis with its effective configuration (id assigned); index = axes so far.
  plc::hli::HLI_AX& add_axis(const AxisConfig& effective);

  // The only way to the control units: from the first call on, begin_cycle() reads them.
  std::span<plc::hli::HLI_AX* const> gpAx() const noexcept {
    handed_out_ = true;
    return stage_.gpAx();
  }
  // D5; NaN for an unknown logical axis number. While the stage is idle its drive values are not
  // kept up to date: every axis has d = q then, its published NcToPlc.SetPos.
  double command_position_request(int ax_nr,
                                  std::span<const std::unique_ptr<ServoAxis>> axes) const noexcept;

  // Cycle, before phase (a): whether phase (c) runs in this cycle (see above).
  bool begin_cycle() noexcept;
  bool engaged() const noexcept { return engaged_; }
  // Cycle, phase (c), over all axes: q from the snapshots of phase (b), d into each axis.
  void run(std::span<const std::unique_ptr<ServoAxis>> axes,
           std::span<const AxisSnapshot> snapshots) noexcept;

 private:
  // Why a new list on the axis is refused now (kNone: it is not), see above.
  static plc::ErrorCode refusal(const ServoAxis& axis) noexcept;
  plc::CoupleState role(std::size_t axis) const noexcept;

  hli::HliStage stage_;
  std::vector<double> q_, qv_, qa_, d_, dv_, da_;
  std::unique_ptr<bool[]> referenced_;
  std::vector<plc::ErrorCode> stop_;
  std::vector<plc::ErrorCode> refusal_;
  std::vector<plc::ErrorCode> pending_;  // axis errors raised on the axis with this cycle's d
  std::vector<uint32_t> errors_seen_;    // AxisCore::errors_raised_ at the last phase (c)
  bool engaged_ = false;
  // gpAx() was called: only then can a semaphore be set (nobody else reaches the units).
  mutable bool handed_out_ = false;
};

}  // namespace nc::detail
