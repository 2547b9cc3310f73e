// The NC kernel: the axes of one controller and the fixed NC cycle that moves them (SPEC A1).
//
// The kernel owns its axes. The PLC side sees each axis only through the plc::AXIS_REF returned
// by add_axis()/axis(): it writes PlcToNc, posts commands into the mailbox and reads NcToPlc.
// One call of cycle() is one NC cycle (ARCHITECTURE "One tick", step 2):
//   a. every axis drains its mailbox: validate → act (plan a job) → answer the command number;
//   b. the master job samples its profile at t = k·T since the job's start (never a running sum,
//      so the end of a profile is hit exactly and runs are bit-for-bit repeatable);
//   d. position controller (Kv, velocity feed-forward) + drive model + encoder → actual values;
//   e. monitors: following error, target window, position range, software limits;
//   f. NcToPlc is published.
//
// Two kinds of functions, as STYLE.md says. Set-up functions (constructor, from_json, add_axis,
// axis, config) may allocate and throw nc::ConfigError. cycle() is the cycle function: noexcept,
// no allocation, no locks, no I/O — all memory is reserved when an axis is added.
//
// Choices (documented here because users see their effects):
// - Homed (StateDWord bit 1) is set from the start: there is no homing yet.
// - Operational (bit 0) = controller enable present and the axis not in error.
// - AxisState, in this priority: ErrorStop (error), Disabled (no controller enable), Stopping
//   (MC_Stop running or its lock held, or an error ramp still running after a reset),
//   DiscreteMotion (positioning or halt until done), ContinuousMotion (MoveVelocity), Standstill.
// - A start (absolute, relative, velocity) begins from the axis's current SET state (p, v, a),
//   so an aborting command blends without a jump (seed 000 §2.1; TwinCAT does the same).
//   MoveRelative adds its distance to the current set position.
// - Validation order of a start (the first broken rule gives the code): axis in error
//   (kAxisInErrorState), locked (0x42EF), buffer mode other than aborting
//   (kBufferModeNotSupported), position not finite (kPositionNotFinite), other parameter not finite
//   (kParameterNotFinite), V <= 0 (0x4231), V above max or reference velocity (0x4221), A+ / A- / J
//   < 0 (0x422F / 0x4230 / 0x422E; 0 = axis default), direction (kDirectionInvalid), target outside
//   the enabled software limits (0x4222; MoveVelocity standing on or beyond a limit and running
//   outward: 0x4461 / 0x4460), controller or feed enable for the direction missing (0x4223).
// - MoveVelocity's direction: +1 or MC_Positive_Direction (1) forward; -1 or
//   MC_Negative_Direction (3) backward; anything else (MC_Current_Direction, …) is refused.
// - A positioning start at standstill shorter than one encoder increment (or of length 0) does
//   not start: the command is answered kDone at once, NcToPlc.Warning = 0x4224, and nothing else
//   changes (a job still waiting for its target window keeps running) — seed 000 §2.1.
// - Halt and Stop: deceleration / jerk 0 = those of the running motion, or the axis defaults at
//   standstill. Both need the controller enable (0x4223) and are refused on an axis in error.
//   Halt is a motion command (locked out by a Stop); a Stop may replace a Stop.
// - Job ends: positioning kDone when set-value generation has ended and InTargetPosition (or the
//   target window is off); Halt/Stop kDone when the set velocity is 0; MoveVelocity kReached.
// - Axis errors (A6): following error 0x4550; set position passing an enabled software limit
//   outward during a job 0x4463 / 0x4462; feed enable removed in the direction of travel 0x4358 /
//   0x4357 — each stops on the emergency ramp. Controller enable removed during a job: 0x4356
//   and, the drive being off, no ramp. The first error is kept until Reset.
// - Without controller enable the drive is off and the set position follows the actual one.
// - Reset clears the axis error (and the warning) and cancels the MC_Stop lock (as Tc2_MC2
//   documents for MC_Reset). When the set values
//   are at rest the set position is moved to the actual position (the axis holds where it
//   stands, with no following error left); an error ramp still running finishes first.
// - Window and filter times count samples, each worth one NC cycle: the following error is
//   raised once it has been above the limit for more samples than fit in the filter time;
//   InTargetPosition once the window has held for window-time's worth of samples (at least 1).
// - Override (PlcToNc.Override) is read into the job every cycle but not yet applied (issue 4).
//   Modulo starts, online changes, compensation, coupling, external setpoints and homing are
//   refused with kUnknownCommand until their issues land.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "nc_core/axis_config.hpp"
#include "plc_interface/axis_ref.hpp"

namespace nc {

namespace detail {
class ServoAxis;
}  // namespace detail

class Kernel {
 public:
  // Set-up: validates `config` (throws ConfigError).
  explicit Kernel(KernelConfig config = {});
  ~Kernel();
  Kernel(Kernel&&) noexcept;
  Kernel& operator=(Kernel&&) noexcept;
  Kernel(const Kernel&) = delete;
  Kernel& operator=(const Kernel&) = delete;

  // Set-up: {"kernel": {...}, "axes": [...]} (see config.hpp); throws ConfigError naming the
  // JSON pointer and the rule.
  static Kernel from_json(const nlohmann::json& document);

  // Set-up: validates the configuration, rejects a duplicate name or id (ConfigError), reserves
  // all the axis's memory. The reference stays valid for the kernel's life (also across moves
  // of the Kernel object). An id of 0 is replaced by index + 1.
  plc::AXIS_REF& add_axis(const AxisConfig& config);

  // Set-up: the axis with this name; ConfigError when there is none.
  plc::AXIS_REF& axis(std::string_view name);
  const plc::AXIS_REF& axis(std::string_view name) const;
  // By index (0 … axis_count()-1, the order of add_axis; NcToPlc.AxisIndex). Unchecked.
  plc::AXIS_REF& axis(std::size_t index) noexcept;
  std::size_t axis_count() const noexcept { return axes_.size(); }
  // The configuration as the axis uses it (id filled in).
  const AxisConfig& config(std::string_view name) const;
  const KernelConfig& kernel_config() const noexcept { return config_; }

  // Cycle function: one NC cycle for every axis.
  void cycle() noexcept;

  double cycle_time() const noexcept { return config_.cycle_time; }
  // Completed NC cycles since the kernel was made.
  uint64_t cycle_count() const noexcept { return cycles_; }
  // Seconds since start = cycle_count() · cycle_time() (a product, never a running sum).
  double time() const noexcept { return static_cast<double>(cycles_) * config_.cycle_time; }

 private:
  detail::ServoAxis& find(std::string_view name) const;

  KernelConfig config_;
  std::vector<std::unique_ptr<detail::ServoAxis>> axes_;
  uint64_t cycles_ = 0;
};

}  // namespace nc
