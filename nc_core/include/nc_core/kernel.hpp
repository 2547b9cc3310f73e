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
//   (kAxisInErrorState), locked (0x42EF), external setpoints enabled (0x4239), buffer mode other
//   than aborting (kBufferModeNotSupported), position not finite (kPositionNotFinite), other
//   parameter not finite (kParameterNotFinite), V <= 0 (0x4231), V above max or reference
//   velocity (0x4221), A+ / A- / J < 0 (0x422F / 0x4230 / 0x422E; 0 = axis default), direction
//   (kDirectionInvalid), target outside the enabled software limits (0x4222; MoveVelocity
//   standing on or beyond a limit and running outward: 0x4461 / 0x4460), controller or feed
//   enable for the direction missing (0x4223).
// - MoveVelocity's direction: +1 or MC_Positive_Direction (1) forward; -1 or
//   MC_Negative_Direction (3) backward; MC_Current_Direction (4) the direction of the set
//   velocity, refused (kDirectionInvalid) at standstill; anything else is refused. kReached
//   (InVelocity) once the velocity level in force (with the override, not 0) is reached; it
//   stays kReached when the override changes the level later.
// - A positioning start at standstill shorter than one encoder increment (or of length 0) does
//   not start: the command is answered kDone at once, NcToPlc.Warning = 0x4224, and nothing else
//   changes (a job still waiting for its target window keeps running) — seed 000 §2.1.
// - Halt and Stop (B4, seed 000 §2.2 "Emergency stop"): their deceleration and jerk replace the
//   running motion's (a Halt's / Stop's own when one runs; the axis defaults at standstill) only
//   when BOTH are genuinely larger; otherwise (also for 0) the running motion's are used. Both
//   need the controller enable (0x4223) and are refused on an axis in error. Halt is a motion
//   command (locked out by a Stop); a Stop may replace a Stop (and so sharpen it with larger
//   values). In the brake phase a Halt / Stop is accepted (the positioning is kAborted, the stop
//   takes CmdNo) but plans with the running values — the braking that runs goes on — and its own
//   braking counts as brake phase too, so no later stop sharpens it.
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
// - Position compensation (MC_MoveSuperImposed; B7, seed 000 §2.5): the trapezoid runs in time
//   over T = L / VP (L cut to a positioning's remaining distance), its velocity scaled every
//   cycle by min(1, |v| / VP), v the basic motion's set velocity (so override and stops act on
//   it). D refers to the direction of travel (> 0: further). It needs a running positioning or
//   MoveVelocity (0x424E otherwise); refused on encoder axes (0x4040), in error, while one runs
//   (0x4245), during Halt / Stop (0x4242), under the Stop lock (0x42EF), for bad parameters
//   (D == 0 0x4244, L 0x4270, VK / VP 0x4271, AK± 0x4272, not finite 0x4F01 / 0x4F02) and beside
//   external setpoints (0x424E). It does not take CmdNo (the basic command stays the axis's); its
//   own number is answered kActive, kDone when T has run out, kAborted when it ended early
//   (compensation stop, the basic motion's end of path, a new motion command, which starts from
//   the compensated set state), kError with the axis's code on an axis error. Warning 0x4243 from
//   the start when the largest feasible D is smaller than D, else from the cycle it ends with
//   less than D done; a new compensation clears it. NcToPlc.CompensationDistance / Length /
//   VelocityDiff: done so far, L in use, signed peak (D's sign), kept after the end; TargetPos
//   moves by the planned, then the done distance.
// - MC_AbortSuperposition: kDone at once, the closing ramp runs on; 0x4246 without compensation,
//   0x4258 in its closing ramp. MC_Halt / MC_Stop brake the basic motion and request the
//   compensation stop; the compensation ends at the latest at their end of path.
// - External setpoints (B8, seed 000 §2.6): Enable / Disable are answered kDone at once (no
//   CmdNo). Enable's checks in order: axis in error, Position not finite (0x4F01), type not 1 / 2
//   (0x4239), controller or either feed enable missing (0x4223), another type active (0x4239),
//   compensation (0x4245), Halt / Stop running (0x4242), Stop lock (0x42EF), absolute beside a
//   job (0x4239). While enabled, PTP starts are refused (0x4239). Relative: target = the
//   positioning's target (or the set position) + Position. A packet is taken while the direction
//   is ±1; the first cycle after and the disable's cycle take ExtSetPos only (v = a = 0); then
//   the set position holds. Switched off at once by an axis error, Reset, loss of the controller
//   enable, Halt and Stop (which brake from the set state reached); a relative offset stays on the
//   position. A packet with NaN / inf is not taken: axis error 0x4F02, the set state runs on for
//   that cycle and the emergency ramp starts there. Feed enables are monitored during external
//   motion too. AxisState does not show external motion (StateDWord bit 14 does).
//   AxisConfig::ext_setpoint_delay d ("delay time between velocity and position") carries each
//   taken packet ahead: p + v d + a d² / 2, v + a d.
// - Brake phase (seed 000 §2.2, §2.4): the final deceleration of a positioning's table to its
//   target — its trailing part on which |v| only falls. Override and a due new velocity do not
//   act in it; a stop in it does not sharpen it.
// - Override (B3, seed 000 §2.2): PlcToNc.Override read every cycle; above 1'000'000 it is not
//   taken (the last valid value stays; Warning 0x4238 while out of range). A change replans the
//   running positioning / MoveVelocity from its set state at level = base · override (base: the
//   level the 100 % table reached at the start, types 1 and 3; the user's V, types 2 and 4),
//   reached as fast as A+ / A- / J allow, a lower one without undershoot. Types 1 / 2 keep the
//   table when the new table would not reach the level (it never holds or touches it); 3 / 4
//   take it. A refused change is not retried. Not during Halt / Stop / error ramps, not in the
//   brake phase. Override 0: a positioning comes to rest on its path (a start at 0 waits at
//   rest), stays kActive and goes on when the override rises (from a rest always, any type); a
//   MoveVelocity goes to v = 0. NcToPlc.TargetVelo is the level in force (signed).
// - New end position (B5, MC_NewPos = kNewPos): answered kDone when accepted; the positioning
//   keeps CmdNo and ends kDone at the new target. Replanned from the set state with the user's
//   V (a level not reachable at the start is reached when the new distance allows it); a target
//   the axis cannot stop before (or has passed) gives one continuous table that reverses.
//   Checks in order: axis in error, a Halt / Stop running or the Stop lock held (0x4242),
//   position not finite (0x4F01), outside the software limits (0x4222), no positioning job
//   (0x424E: standstill, MoveVelocity), compensation running (0x4245), controller / feed enable
//   for the direction to the new target (0x4223). A re-triggered aborting MoveAbsolute gives the
//   same motion under a new command number.
// - New velocity and end position (B6, kNewPosAndVelo: EPos, VNew, APos): the same checks plus
//   VNew / APos not finite (0x4F02), VNew <= 0 (0x4231), VNew above max / reference velocity
//   (0x4221), answered kDone when accepted. The table goes to EPos with the old V at once; VNew
//   by the seed's six cases along the direction of travel (at rest: towards the target): 1
//   from APos on (the set position passing APos in that direction), 2 at once, 3 / 6 return
//   with VOld, 4 never, 5 when APos is passed on the way back. VNew not reachable (the table
//   would not hold or touch it): the level is halved towards the current speed, 8 tries, else
//   the table is kept. A due VNew waits while the table is in its brake phase (dropped when the
//   job ends braking). A new request replaces a pending VNew (cases 1 / 5) or deletes it (other
//   cases, MC_NewPos). The override applies on top.
// - Modulo start (B1, kMoveModulo, modulo factor F): the end is congruent to Position mod F; below
//   F the nearest such end from where the axis would come to rest, in the direction (1 positive,
//   3 negative, 2 shortest way — a tie goes positive —, 4 current, refused at standstill); at or
//   above F, floor(|Position| / F) extra whole turns after it (shortest way: in the direction of
//   the sign). More than 1'000'000 turns: 0x4282; other checks as MoveAbsolute.
//   ModuloSetPos / ModuloActPos lie in [0, F).
// - Coupling and homing are refused with kUnknownCommand until their issues land.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "nc_core/axis_config.hpp"
#include "nc_core/axis_snapshot.hpp"
#include "nc_core/coupling_graph.hpp"
#include "plc_interface/axis_ref.hpp"

namespace nc {

class Profile;

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

  // Cycle function: one NC cycle, phase by phase over all axes (docs/architecture.md "One
  // tick"): commands, set values (masters before slaves), couplings on drive positions, position
  // control + drive + encoder, monitors and errors then group reactions, publish.
  void cycle() noexcept;

  // What axis `index` published to the other axes in the last cycle. Unchecked index.
  const AxisSnapshot& snapshot(std::size_t index) const noexcept { return snapshots_[index]; }
  // Who follows whom (empty until coupling lands).
  const CouplingGraph& couplings() const noexcept { return couplings_; }

  double cycle_time() const noexcept { return config_.cycle_time; }
  // Completed NC cycles since the kernel was made.
  uint64_t cycle_count() const noexcept { return cycles_; }
  // Seconds since start = cycle_count() · cycle_time() (a product, never a running sum).
  double time() const noexcept { return static_cast<double>(cycles_) * config_.cycle_time; }

 private:
  // Axes per block of the phase loops while nothing is coupled (see cycle()).
  static constexpr std::size_t kBlockAxes = 32;

  detail::ServoAxis& find(std::string_view name) const;
  // Phases (a) … (f) over axes [first, last) of the set-value order.
  void run_phases(std::size_t first, std::size_t last, uint64_t counter) noexcept;

  KernelConfig config_;
  std::vector<std::unique_ptr<detail::ServoAxis>> axes_;
  std::vector<AxisSnapshot> snapshots_;
  CouplingGraph couplings_;
  // One planning scratch profile for all axes (a start plans here first, so a refusal changes
  // nothing); on the heap so that its address survives a move of the Kernel.
  std::unique_ptr<Profile> scratch_;
  uint64_t cycles_ = 0;
};

}  // namespace nc
