// One axis's part in the errors of its master/slave group (SPEC C7, C8; seed 000 §3.1; the rules
// in docs/behaviour.md "Error propagation and actual-value coupling"): the countdown to its group
// reaction, the group's reaction reaching it, case 2 of C8 (the group follows a head master
// pushed by hand), the filtered actual values its slaves follow, when losing the controller
// enable is an axis error, and MC_Reset. The group reaction itself is the kernel's.
//
// A view on one axis's AxisCore for one call (the state is AxisCore's propagation_, by_hand_,
// group_ready_, hand_velocity_, actual_filter_). Cycle functions: noexcept, no allocation.
#pragma once

#include "axis/axis_core.hpp"
#include "nc_core/axis_snapshot.hpp"

namespace nc::detail {

class GroupErrors : public AxisPart {
 public:
  using AxisPart::AxisPart;

  // From raise_error() for the axis's own error: starts the countdown to the group reaction
  // (0 cycles unless DELAYED in a group); a DELAYED slave leaves its master's coupling at once
  // (its link stays in the graph, SlaveLink::detached, until MC_GearOut).
  void begin_error_propagation() noexcept;
  // The monitor phase: the group reaction of this axis's error is due in this cycle.
  bool group_reaction_due() noexcept { return s_.propagation_.step(s_.error_event_); }
  // The group reaction (SPEC C7 INSTANTANEOUS) reaches this axis with the faulty axis's code; the
  // first error stays. A slave goes on following (its head master's emergency ramp brings it
  // down); a master stops on its emergency ramp.
  void group_error(ErrorCode code) noexcept { s_.raise_error(code, false); }
  // MC_Reset: the error and the warnings are cleared, a pending group reaction is cancelled, and
  // an axis without a job holds where it stands.
  void reset_error() noexcept;

  // Kernel, after the group reactions of a cycle with couplings: `ready` = this axis heads a
  // group in which no axis has an error and every axis has its controller enable (the
  // precondition of case 2). An uncoupled axis sets it for itself in its monitor phase.
  void set_group_ready(bool ready) noexcept { s_.group_ready_ = ready; }
  // The controller enable is missing in this cycle (`lost`: it was there in the last one): true
  // when that is the axis error 0x4260, i.e. a command runs (a job, a homing, or the coupling of
  // a slave). The one place that decides it (issue 10 item 4).
  bool enable_loss_is_error(bool lost) const noexcept;
  // The enables' check, first: enters case 2 when follows_by_hand() holds (a running job ends
  // CommandAborted) and leaves it when it no longer does (the push by hand ends). True while
  // in case 2: the lost controller enable is no error.
  bool update_by_hand() noexcept;
  // Not (or no longer) in case 2; a push by hand ends with the controller enable.
  void end_by_hand() noexcept {
    s_.by_hand_ = false;
    if (s_.channel_.controller_enabled()) s_.hand_velocity_ = 0.0;
  }
  // Kernel::push_by_hand: the drive of this disabled continuous axis moves at `velocity` (mm/s)
  // from the next cycle on, until the controller enable returns or another velocity is given.
  ErrorCode push_by_hand(double velocity) noexcept;
  // The set values phase of a coupled slave, before its sample: its master's drive has gone off
  // under it (K26): the master has no controller enable in this cycle and had set values
  // in motion, and does not drive its slaves by filtered actual values (C8). The slave then leaves
  // the coupling as a C7 DELAYED slave leaves it on its own error (SlaveLink::detached, until
  // MC_GearOut) and stops on its own emergency ramp from its set state, with 0x4260 unless it
  // already has an error. Without its own controller enable the slave stays (its drive is off).
  void leave_master_without_drive(const AxisSnapshot& master) noexcept;
  // The set values phase: the snapshot's set values for the slaves, from the filtered actual
  // position of the previous cycle while the slaves follow this axis's actual values (C8).
  void publish_for_slaves(AxisSnapshot& snapshot) noexcept;

 private:
  // Case 2 of C8: this head master's controller enable is off in a group that had no error and
  // every axis enabled when it went, and couple_slave_to_actual_values is set.
  bool follows_by_hand() const noexcept;
  // C8: the slaves of this axis follow its filtered actual values in this cycle.
  bool drives_slaves_by_actual() const noexcept;
};

}  // namespace nc::detail
