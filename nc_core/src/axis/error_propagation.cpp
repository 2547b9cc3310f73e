// Error propagation in a master/slave group (SPEC C7) and coupling to actual values (SPEC C8),
// seed 000 §3.1; the rules and the decisions are in docs/behaviour.md "Error propagation and
// actual-value coupling". The group reaction itself is the kernel's (Kernel::react_in_groups);
// this file is what one axis knows: its own mode and delay, its local reaction, bit 6, and what
// its slaves follow.
#include "axis/group_errors.hpp"

#include <cmath>

namespace nc::detail {

using plc::CommandState;

void GroupErrors::begin_error_propagation() noexcept {
  const bool in_group = s_.slave_link_.coupled || s_.slave_link_.detached || s_.slave_count_ > 0;
  const bool delayed = s_.config_.error_propagation_mode == ErrorPropagation::kDelayed &&
                       in_group && s_.config_.kind != AxisKind::kTwoSpeed;
  const uint64_t cycles =
      delayed ? delay_cycles(s_.config_.error_propagation_delay, s_.cycle_time_) : uint64_t{0};
  s_.propagation_.start(cycles);
  if (cycles == 0 || !s_.slave_link_.coupled) return;
  // The local reaction of a slave: it leaves its master's coupling and stops on its own
  // emergency ramp (raise_error() goes on as for a master); its own slaves keep following it.
  s_.slave_link_.coupled = false;
  s_.slave_link_.detached = true;
}

bool GroupErrors::follows_by_hand() const noexcept {
  // Only the head of a group: a master that is no slave (nor a slave that left on an error).
  // (No slaves first: that is the steady cycle's answer.)
  if (s_.slave_count_ == 0 || s_.slave_link_.coupled || s_.slave_link_.detached) return false;
  if (!s_.config_.couple_slave_to_actual_values || s_.config_.kind != AxisKind::kContinuous) {
    return false;
  }
  if (s_.channel_.controller_enabled() || s_.channel_.has_error()) return false;
  return s_.by_hand_ || s_.group_ready_;
}

bool GroupErrors::update_by_hand() noexcept {
  if (!follows_by_hand()) {
    end_by_hand();
    return false;
  }
  if (!s_.by_hand_) {
    s_.by_hand_ = true;
    // The master's own command ends without an error: the group follows its actual values now.
    if (s_.job_.active() && s_.channel_.runs(s_.job_.number())) {
      s_.channel_.answer_current(CommandState::kAborted);
    }
    s_.job_.clear();
    s_.buffer_.drop(s_.buffer_waiting_, s_.channel_, CommandState::kAborted);
  }
  return true;
}

bool GroupErrors::drives_slaves_by_actual() const noexcept {
  if (s_.slave_count_ == 0 || !s_.config_.couple_slave_to_actual_values) return false;
  if (s_.config_.kind == AxisKind::kTwoSpeed) return false;
  if (s_.by_hand_) return true;  // case 2
  // Case 1: the axis's own error in DELAYED mode, until MC_Reset.
  return s_.config_.error_propagation_mode == ErrorPropagation::kDelayed && s_.channel_.has_error();
}

void GroupErrors::publish_for_slaves(AxisSnapshot& snapshot) noexcept {
  if (!drives_slaves_by_actual()) {
    s_.actual_filter_.end();
    snapshot.slaves_follow_actual = false;
    return;
  }
  // From where the slaves stood in the last cycle, towards the actual position measured then.
  if (!s_.actual_filter_.active) s_.actual_filter_.begin(s_.previous_set_position_);
  s_.actual_filter_.step(s_.drive_.measured_position() - s_.drive_offset_, s_.cycle_time_,
                         s_.config_.actual_value_filter_time,
                         s_.config_.actual_value_velocity_window);
  // For the slaves only: the axis's own set values, which the HLI stage reads, stay (finding
  // K14: as the set values they became an HLI phase's q and so the axis's own drive command).
  snapshot.slaves_follow_actual = true;
  snapshot.filtered_position = s_.actual_filter_.out.p;
  snapshot.filtered_velocity = s_.actual_filter_.out.v;
  snapshot.filtered_acceleration = s_.actual_filter_.out.a;
}

void GroupErrors::leave_master_without_drive(const AxisSnapshot& master) noexcept {
  // The master's snapshot shows the set values of the last cycle in the first cycle without its
  // enable (its set position follows its actual one from phase (d) on): that cycle decides.
  const bool master_moving = master.set_velocity != 0.0 || master.set_acceleration != 0.0;
  if (master.controller_enabled || master.slaves_follow_actual || !master_moving ||
      !s_.channel_.controller_enabled()) {
    return;
  }
  s_.slave_link_.coupled = false;
  s_.slave_link_.detached = true;
  s_.note_event();  // CoupleState's source, the group's image
  if (s_.channel_.has_error()) {
    s_.start_error_ramp(s_.running_motion());  // it followed its master's error ramp so far
  } else {
    s_.raise_error(ErrorCode::kControllerEnableLost);
  }
}

ErrorCode GroupErrors::push_by_hand(double velocity) noexcept {
  if (!std::isfinite(velocity)) return ErrorCode::kParameterNotFinite;
  if (s_.config_.kind != AxisKind::kContinuous) return ErrorCode::kAxisKindNotAllowed;
  if (std::abs(velocity) > s_.config_.max_velocity) return ErrorCode::kVelocityNotAllowed;
  if (s_.channel_.controller_enabled()) return ErrorCode::kPushByHandControllerEnabled;
  s_.hand_velocity_ = velocity;
  s_.note_event();
  return ErrorCode::kNone;
}

void GroupErrors::reset_error() noexcept {
  s_.channel_.warnings.clear_all();
  if (!s_.channel_.has_error()) return;
  s_.channel_.clear_error();
  s_.propagation_.cancel();  // C7: a reset before the delay has run out: no group reaction
  if (!s_.job_.active() && !s_.slave_link_.coupled) {
    // The axis holds where it stands: no following error is carried over into the next start.
    s_.set_ = KinematicState{s_.drive_.measured_position() - s_.drive_offset_, 0.0, 0.0};
    // The drive position d steps to the actual one too: no feed-forward kick from that step.
    s_.previous_drive_position_ = s_.drive_.measured_position();
    s_.set_jerk_ = 0.0;
    s_.target_ = s_.set_.p;
    s_.monitors_.reset_windows();
  }
}

}  // namespace nc::detail
