// The superpositions of one axis: position compensation (seed 000 §2.5, SPEC B7) and external
// setpoint generation (seed 000 §2.6, seed 001, SPEC B8) — their commands and their share of
// step b of the NC cycle. The basic motion (the master job) gives base_; this file adds the rest.
#include <cmath>

#include "axis/servo_axis.hpp"

namespace nc::detail {

namespace {

using plc::CommandState;
using Type = ExternalSetpoint::Type;

bool is_stop(JobKind kind) noexcept {
  return kind == JobKind::kHalt || kind == JobKind::kStop || kind == JobKind::kEmergencyStop;
}

}  // namespace

// ---------------------------------------------------------------- commands

ErrorCode ServoAxis::start_compensation(const plc::Command& command) noexcept {
  // Seed 000 §2.5 general notes 8, 4, 5 and the start parameters, in this order.
  if (config_.kind == AxisKind::kEncoder) return ErrorCode::kAxisKindNotAllowed;
  if (channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (compensation_.running()) return ErrorCode::kCompensationActive;  // no iteration
  if (is_stop(job_.kind())) return ErrorCode::kStopAlreadyActive;
  if (locked_) return ErrorCode::kMotionCommandsLocked;
  const ErrorCode parameters =
      Compensation::check(command.position, command.length, command.process_velocity,
                          command.velocity, command.acceleration, command.deceleration);
  if (parameters != ErrorCode::kNone) return parameters;
  // A compensation superimposes a running basic motion; none beside external generation.
  if (external_.enabled()) return ErrorCode::kFunctionNotAllowed;
  if (!job_.is_motion() || job_.generation_ended()) return ErrorCode::kFunctionNotAllowed;

  // The direction of travel, to which D refers.
  double direction = base_.v;
  if (direction == 0.0) {
    direction =
        job_.kind() == JobKind::kPosition ? job_.target() - base_.p : job_.target_velocity();
  }
  direction = direction < 0.0 ? -1.0 : 1.0;
  // Seed 000 §2.5 note 5: the remaining distance replaces a longer L.
  double length = command.length;
  if (job_.kind() == JobKind::kPosition) {
    const double remaining = std::abs(job_.target() - base_.p);
    if (!(remaining > 0.0)) return ErrorCode::kFunctionNotAllowed;
    length = std::fmin(length, remaining);
  }
  // Planned into a copy first: a refusal leaves the published values of the last one alone.
  Compensation planned_compensation = compensation_;
  const ErrorCode planned = planned_compensation.start(
      command.number, command.position, length, command.process_velocity, command.velocity,
      command.acceleration, command.deceleration, direction, std::abs(base_.v), cycle_time_);
  if (planned != ErrorCode::kNone) return planned;
  if (job_.kind() == JobKind::kPosition) {
    // Seed 000 §2.1 notes 4, 5: the compensated end must lie inside the software limits too.
    const double end = job_.target() + held_ + planned_compensation.planned_offset();
    if (monitors_.below_min(end) || monitors_.above_max(end)) {
      return ErrorCode::kTargetPositionNotAllowed;
    }
  }
  compensation_ = planned_compensation;
  channel_.answer(command.number, CommandState::kActive);
  channel_.clear_warning(Warning::kCompensationIncomplete);  // a former compensation's warning
  if (compensation_.planned_incomplete()) channel_.warn(Warning::kCompensationIncomplete);
  return ErrorCode::kNone;
}

ErrorCode ServoAxis::stop_compensation(const plc::Command& command) noexcept {
  const ErrorCode code = compensation_.request_stop();
  if (code != ErrorCode::kNone) return code;
  channel_.answer(command.number, CommandState::kDone);
  return ErrorCode::kNone;
}

ErrorCode ServoAxis::enable_external(const plc::Command& command) noexcept {
  // Seed 000 §2.6 "Activation": no axis error, controller and feed enables, not coupled (there
  // is no coupling yet); the start type must match one already active.
  if (channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (!std::isfinite(command.position)) return ErrorCode::kPositionNotFinite;
  if (command.mode != static_cast<int32_t>(Type::kAbsolute) &&
      command.mode != static_cast<int32_t>(Type::kRelative)) {
    return ErrorCode::kStartTypeNotAllowed;
  }
  const Type type = static_cast<Type>(command.mode);
  if (!channel_.controller_enabled() || !channel_.feed_enabled(1.0) ||
      !channel_.feed_enabled(-1.0)) {
    return ErrorCode::kNoControllerOrFeedEnable;
  }
  if (external_.taking() && external_.type() != type) return ErrorCode::kStartTypeNotAllowed;
  if (compensation_.running()) return ErrorCode::kCompensationActive;
  if (is_stop(job_.kind())) return ErrorCode::kStopAlreadyActive;
  if (locked_) return ErrorCode::kMotionCommandsLocked;
  // Beside an internal motion only the relative type: two absolute sources cannot coexist.
  if (type == Type::kAbsolute && job_.active()) return ErrorCode::kStartTypeNotAllowed;

  double target = command.position;
  if (type == Type::kAbsolute) {
    if (!external_.taking()) {
      base_ = set_;  // the external set values take over from here
      held_ = 0.0;
    }
    external_.enable(type, set_, target, config_.ext_setpoint_delay);
  } else {
    // Relative: the target refers to the internal generator's target (or position).
    const double reference =
        job_.kind() == JobKind::kPosition ? job_.target() + held_ : basic_state().p;
    target += reference;
    external_.enable(type, KinematicState{}, target, config_.ext_setpoint_delay);
  }
  target_ = target;
  monitors_.reset_windows();
  channel_.answer(command.number, CommandState::kDone);
  return ErrorCode::kNone;
}

ErrorCode ServoAxis::disable_external(const plc::Command& command) noexcept {
  external_.disable();  // disabling what is not enabled is not an error: nothing to do
  channel_.answer(command.number, CommandState::kDone);
  return ErrorCode::kNone;
}

// ---------------------------------------------------------------- the cycle

void ServoAxis::superimpose() noexcept {
  KinematicState total = base_;
  total.p += held_;

  if (compensation_.running()) {
    const KinematicState extra = compensation_.advance(base_.v, base_.a, cycle_time_);
    total.p += extra.p;
    total.v += extra.v;
    total.a += extra.a;
    // Done when its time T is over; ended early by a compensation stop or when the basic
    // motion's path ends first (seed 000 §2.5 notes 6 and 7).
    if (compensation_.time_over()) {
      end_compensation(compensation_.stop_requested() ? CommandState::kAborted
                                                      : CommandState::kDone);
    } else if (!job_.active() || job_.generation_ended()) {
      end_compensation(CommandState::kAborted);
    }
  }
  if ((compensation_.running() || held_ != 0.0) && job_.active() &&
      job_.kind() != JobKind::kVelocity && !external_.taking()) {
    // The superimposed distance moves the job's end (TargetPos, target window).
    target_ =
        job_.target() + held_ + (compensation_.running() ? compensation_.planned_offset() : 0.0);
  }

  bool not_finite = false;
  if (external_.taking()) {
    const ExternalSetpoint::Step step = external_.take(channel_.ref().PlcToNc, cycle_time_);
    not_finite = step.not_finite;
    if (external_.type() == Type::kAbsolute) {
      total = step.state;
      set_jerk_ = 0.0;
      if (step.finished) {
        base_ = KinematicState{total.p, 0.0, 0.0};
        held_ = 0.0;
      }
    } else {
      total.p += step.state.p;
      total.v += step.state.v;
      total.a += step.state.a;
      if (step.finished) held_ += step.state.p;
    }
  }
  set_ = total;
  // A packet with NaN or inf is not taken; the axis must not run on it (SPEC B8).
  if (not_finite) raise_error(ErrorCode::kParameterNotFinite);
}

KinematicState ServoAxis::basic_state() const noexcept {
  if (external_.taking() && external_.type() == Type::kAbsolute) return set_;
  KinematicState state = base_;
  state.p += held_;
  return state;
}

KinematicState ServoAxis::stop_start_state() const noexcept {
  KinematicState state = set_;
  if (compensation_.running()) {
    const KinematicState& extra = compensation_.state();
    state.p -= extra.p;
    state.v -= extra.v;
    state.a -= extra.a;
  }
  return state;
}

void ServoAxis::end_compensation(plc::CommandState state, uint32_t code) noexcept {
  held_ += compensation_.finish();
  channel_.answer(compensation_.number(), state, code);
  if (compensation_.incomplete()) channel_.warn(Warning::kCompensationIncomplete);
}

void ServoAxis::fold_superpositions(plc::CommandState state, ErrorCode code) noexcept {
  if (compensation_.running()) {
    // Its offset so far is in set_, where the new job starts: nothing to hold.
    compensation_.finish();
    channel_.answer(compensation_.number(), state, plc::to_id(code));
    if (compensation_.incomplete()) channel_.warn(Warning::kCompensationIncomplete);
  }
  external_.abort();
  held_ = 0.0;
  base_ = set_;
}

void ServoAxis::rebase_superpositions() noexcept {
  held_ = 0.0;
}

void ServoAxis::superpositions_on_new_job(JobKind kind) noexcept {
  if (kind == JobKind::kHalt || kind == JobKind::kStop) {
    // Planned from stop_start_state(): the held offset and the external offset are in the new
    // job. A stop requests the compensation stop at the same time (seed 000 §2.5).
    external_.abort();
    held_ = 0.0;
    if (compensation_.running()) (void)compensation_.request_stop();  // braking: goes on
    return;
  }
  fold_superpositions(CommandState::kAborted);
}

void ServoAxis::end_external_generation() noexcept {
  if (!external_.taking()) return;
  if (external_.type() == Type::kRelative) {
    held_ += external_.state().p;
  } else {
    base_ = KinematicState{set_.p, 0.0, 0.0};
    held_ = 0.0;
  }
  external_.abort();
}

}  // namespace nc::detail
