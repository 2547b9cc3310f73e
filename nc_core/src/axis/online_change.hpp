// The online functions of a running motion job (SPEC B3, B5, B6; seed 000 §2.2-2.4): the
// override read every cycle and applied to the running table, a new end position (MC_NewPos), a
// new velocity with its activation (MC_NewPosAndVelo), and the positioning and velocity starts
// that plan with the override in force. The rules are in override.cpp and online_change.cpp.
//
// A view on one axis's AxisCore for one call (it owns nothing; the override and the pending
// activation live in the MasterJob). Cycle functions: noexcept, no allocation; every table is
// planned into the kernel's scratch profile first, so a refusal leaves the running one.
#pragma once

#include <cstdint>

#include "axis/axis_core.hpp"
#include "plc_interface/command.hpp"

namespace nc::detail {

class OnlineChange : public AxisPart {
 public:
  using AxisPart::AxisPart;

  // Phase a, first: PlcToNc.Override into the job; above 1'000'000 it is not taken (warning
  // 0x4238). Inline: it runs in every cycle.
  void read_override() noexcept {
    const uint32_t value = s_.channel_.ref().PlcToNc.Override;
    if (value > plc::kOverrideFull) {
      // Not a percentage: not taken. The last valid value stays in force, the warning says why.
      s_.channel_.warnings.warn(Warning::kOverrideNotAllowed);
      return;
    }
    s_.channel_.warnings.clear(Warning::kOverrideNotAllowed);
    s_.job_.online.set_override(value);
  }
  // Phase a, last: the override and a due new velocity act on the running job (inline: it runs
  // in every cycle of a motion job).
  void run_online_functions() noexcept {
    // Only a running motion job: no override while a stop (Halt, Stop, error ramp) is active.
    if (!s_.channel_.controller_enabled() || s_.channel_.has_error() || !s_.job_.is_motion()) {
      return;
    }
    bool replanned = false;
    Activation& activation = s_.job_.online.activation();
    if (s_.job_.kind() == JobKind::kPosition && activation.armed) {
      const bool due = activation.immediate ||
                       (activation.direction * (s_.set_.p - activation.position) >= 0.0 &&
                        activation.direction * s_.set_.v > 0.0);
      if (due && !s_.job_.in_brake_phase(s_.cycle_time_)) {
        s_.note_event();
        activation.armed = false;
        replanned = activate_velocity(activation.velocity);
      }
    }
    if (!replanned && s_.job_.online.override_value() != s_.job_.online.handled_override()) {
      s_.note_event();
      apply_override();
    }
  }
  // A positioning / velocity job planned from set_ with the override in force, then accept().
  ErrorCode start_positioning(uint16_t number, double target, const Limits& limits) noexcept;
  ErrorCode start_continuous(uint16_t number, double velocity, const Limits& limits) noexcept;
  ErrorCode new_position(const plc::Command& command) noexcept;
  ErrorCode new_position_and_velocity(const plc::Command& command) noexcept;

 private:
  // The velocity level the override gives: the user's V (types 2, 4) or the level reduced at the
  // start (types 1, 3), times the override.
  double override_level(double user_velocity, double reduced_velocity,
                        uint32_t override_value) const noexcept;
  // The override changed: the running table is replanned (or kept, seed 000 §2.2).
  void apply_override() noexcept;
  // Into scratch_: to `target` at path velocity `level`, or for level 0 a rest on the path
  // (`final` false). False when the planner refuses.
  bool plan_table(const KinematicState& from, double target, const Limits& limits, double level,
                  bool& final) noexcept;
  // A Halt or Stop runs or MC_Stop's lock is held: new-position functions are refused.
  bool stop_active() const noexcept;
  // The refusals common to both (axis error, stop, target, job, compensation, feed enable).
  ErrorCode check_new_target(double target) const noexcept;
  // Replans the running positioning to `target` with user velocity `velocity` (override
  // applied), from the basic motion's state.
  bool retarget(double target, double velocity) noexcept;
  // Seed 000 §2.4 "New velocity": VNew for the running positioning, reduced iteratively when
  // not reachable; false (table kept) when nothing fits.
  bool activate_velocity(double velocity) noexcept;
  // Installs scratch_ into the running job (planned from basic_state()), keeping the
  // superpositions on top.
  void install_table(double target, bool final, double level) noexcept;
};

}  // namespace nc::detail
