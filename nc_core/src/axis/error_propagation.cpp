// Error propagation in a master/slave group (SPEC C7) and coupling to actual values (SPEC C8),
// seed 000 §3.1; the rules and the decisions are in docs/behaviour.md "Error propagation and
// actual-value coupling". The group reaction itself is the kernel's (Kernel::react_in_groups);
// this file is what one axis knows: its own mode and delay, its local reaction, bit 6, and what
// its slaves follow.
#include "axis/servo_axis.hpp"

#include <cmath>

namespace nc::detail {

using plc::CommandState;

void ServoAxis::begin_error_propagation() noexcept {
  const bool in_group = slave_link_.coupled || slave_link_.detached || slave_count_ > 0;
  const bool delayed = config_.error_propagation_mode == ErrorPropagation::kDelayed && in_group &&
                       config_.kind != AxisKind::kTwoSpeed;
  const uint64_t cycles =
      delayed ? delay_cycles(config_.error_propagation_delay, cycle_time_) : uint64_t{0};
  propagation_.start(cycles);
  if (cycles == 0 || !slave_link_.coupled) return;
  // The local reaction of a slave: it leaves its master's coupling and stops on its own
  // emergency ramp (raise_error() goes on as for a master); its own slaves keep following it.
  slave_link_.coupled = false;
  slave_link_.detached = true;
}

bool ServoAxis::group_reaction_due() noexcept {
  return propagation_.step(error_event_);
}

bool ServoAxis::follows_by_hand() const noexcept {
  // Only the head of a group: a master that is no slave (nor a slave that left on an error).
  // (No slaves first: that is the steady cycle's answer.)
  if (slave_count_ == 0 || slave_link_.coupled || slave_link_.detached) return false;
  if (!config_.couple_slave_to_actual_values || config_.kind != AxisKind::kContinuous) return false;
  if (channel_.controller_enabled() || channel_.has_error()) return false;
  return by_hand_ || group_ready_;
}

bool ServoAxis::update_by_hand() noexcept {
  if (!follows_by_hand()) {
    end_by_hand();
    return false;
  }
  if (!by_hand_) {
    by_hand_ = true;
    // The master's own command ends without an error: the group follows its actual values now.
    if (job_.active() && channel_.runs(job_.number())) {
      channel_.answer_current(CommandState::kAborted);
    }
    job_.clear();
    buffer_.drop(channel_, CommandState::kAborted);
  }
  return true;
}

bool ServoAxis::drives_slaves_by_actual() const noexcept {
  if (slave_count_ == 0 || !config_.couple_slave_to_actual_values) return false;
  if (config_.kind == AxisKind::kTwoSpeed) return false;
  if (by_hand_) return true;  // case 2
  // Case 1: the axis's own error in DELAYED mode, until MC_Reset.
  return config_.error_propagation_mode == ErrorPropagation::kDelayed && channel_.has_error();
}

void ServoAxis::publish_for_slaves(AxisSnapshot& snapshot) noexcept {
  if (!drives_slaves_by_actual()) {
    actual_filter_.end();
    return;
  }
  // From where the slaves stood in the last cycle, towards the actual position measured then.
  if (!actual_filter_.active) actual_filter_.begin(previous_set_position_);
  actual_filter_.step(drive_.measured_position() - drive_offset_, cycle_time_,
                      config_.actual_value_filter_time, config_.actual_value_velocity_window);
  snapshot.set_position = actual_filter_.out.p;
  snapshot.set_velocity = actual_filter_.out.v;
  snapshot.set_acceleration = actual_filter_.out.a;
  snapshot.set_jerk = 0.0;
}

ErrorCode ServoAxis::push_by_hand(double velocity) noexcept {
  if (!std::isfinite(velocity)) return ErrorCode::kParameterNotFinite;
  if (config_.kind != AxisKind::kContinuous) return ErrorCode::kAxisKindNotAllowed;
  if (std::abs(velocity) > config_.max_velocity) return ErrorCode::kVelocityNotAllowed;
  if (channel_.controller_enabled()) return ErrorCode::kPushByHandControllerEnabled;
  hand_velocity_ = velocity;
  return ErrorCode::kNone;
}

}  // namespace nc::detail
