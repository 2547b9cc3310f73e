// The superpositions of one axis: position compensation (seed 000 §2.5, SPEC B7) and external
// setpoint generation (seed 000 §2.6, seed 001, SPEC B8) — their commands and their share of
// the rules of the superposition stack as the axis applies them (superposition_stack.hpp).
#include <cmath>

#include "axis/superposition_commands.hpp"
#include "profile/validate.hpp"

namespace nc::detail {

namespace {

using plc::CommandState;
using Type = ExternalSetpoint::Type;

bool is_stop(JobKind kind) noexcept {
  return kind == JobKind::kHalt || kind == JobKind::kStop || kind == JobKind::kEmergencyStop;
}

}  // namespace

// ---------------------------------------------------------------- commands

ErrorCode SuperpositionCommands::start_compensation(const plc::Command& command) noexcept {
  // Seed 000 §2.5 general notes 8, 4, 5 and the start parameters, in this order.
  if (s_.config_.kind == AxisKind::kEncoder) return ErrorCode::kAxisKindNotAllowed;
  if (s_.channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (s_.stack_.compensation.running()) return ErrorCode::kCompensationActive;  // no iteration
  // The basic motion: the axis's job, or a coupled slave's master's path (seed 000 §3.2.4).
  const BasicPath path = s_.basic_path();
  if (path.stopping) return ErrorCode::kStopAlreadyActive;
  if (s_.locked_) return ErrorCode::kMotionCommandsLocked;
  const ErrorCode parameters =
      check_compensation(command.position, command.length, command.process_velocity,
                         command.velocity, command.acceleration, command.deceleration);
  if (parameters != ErrorCode::kNone) return parameters;
  // A compensation superimposes a running basic motion; none beside external generation.
  if (s_.stack_.external.enabled()) return ErrorCode::kFunctionNotAllowed;
  if (!path.running) return ErrorCode::kFunctionNotAllowed;

  // The direction of travel, to which D refers.
  double direction = s_.base_.v;
  if (direction == 0.0) {
    direction = path.positioning ? path.target - s_.base_.p : path.target_velocity;
  }
  direction = direction < 0.0 ? -1.0 : 1.0;
  // Seed 000 §2.5 note 5: the remaining distance replaces a longer L.
  double length = command.length;
  if (path.positioning) {
    const double remaining = std::abs(path.target - s_.base_.p);
    if (!(remaining > 0.0)) return ErrorCode::kFunctionNotAllowed;
    length = std::fmin(length, remaining);
  }
  // Planned into a copy first: a refusal leaves the published values of the last one alone.
  Compensation planned_compensation = s_.stack_.compensation;
  const ErrorCode planned = planned_compensation.start(
      command.number, command.position, length, command.process_velocity, command.velocity,
      command.acceleration, command.deceleration, direction, std::abs(s_.base_.v), s_.cycle_time_);
  if (planned != ErrorCode::kNone) return planned;
  if (path.positioning) {
    // Seed 000 §2.1 notes 4, 5: the compensated end must lie inside the software limits too.
    const double end = path.target + s_.stack_.held() + planned_compensation.planned_offset();
    if (s_.monitors_.below_min(end) || s_.monitors_.above_max(end)) {
      return ErrorCode::kTargetPositionNotAllowed;
    }
  }
  s_.stack_.compensation = planned_compensation;
  s_.channel_.answer(command.number, CommandState::kActive);
  s_.channel_.warnings.clear(Warning::kCompensationIncomplete);  // a former compensation's warning
  if (s_.stack_.compensation.planned_incomplete()) {
    s_.channel_.warnings.warn(Warning::kCompensationIncomplete);
  }
  return ErrorCode::kNone;
}

ErrorCode SuperpositionCommands::stop_compensation(const plc::Command& command) noexcept {
  const ErrorCode code = s_.stack_.compensation.request_stop();
  if (code != ErrorCode::kNone) return code;
  s_.channel_.answer(command.number, CommandState::kDone);
  return ErrorCode::kNone;
}

ErrorCode SuperpositionCommands::enable_external(const plc::Command& command) noexcept {
  // Seed 000 §2.6 "Activation": no axis error, controller and feed enables, not coupled (there
  // is no coupling yet); the start type must match one already active.
  if (s_.channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (!std::isfinite(command.position)) return ErrorCode::kPositionNotFinite;
  if (command.mode != static_cast<int32_t>(Type::kAbsolute) &&
      command.mode != static_cast<int32_t>(Type::kRelative)) {
    return ErrorCode::kStartTypeNotAllowed;
  }
  const Type type = static_cast<Type>(command.mode);
  if (!s_.channel_.controller_enabled() || !s_.channel_.feed_enabled(1.0) ||
      !s_.channel_.feed_enabled(-1.0)) {
    return ErrorCode::kNoControllerOrFeedEnable;
  }
  if (s_.stack_.external.taking() && s_.stack_.external.type() != type) {
    return ErrorCode::kStartTypeNotAllowed;
  }
  if (s_.stack_.compensation.running()) return ErrorCode::kCompensationActive;
  if (is_stop(s_.job_.kind())) return ErrorCode::kStopAlreadyActive;
  if (s_.locked_) return ErrorCode::kMotionCommandsLocked;
  if (s_.homing_.active()) return ErrorCode::kFunctionNotAllowed;  // the homing sequence owns it
  // Beside an internal motion only the relative type: two absolute sources cannot coexist.
  if (type == Type::kAbsolute && s_.job_.active()) return ErrorCode::kStartTypeNotAllowed;

  // Relative: the target refers to the internal generator's target (or position). The target
  // lies within the planner's range like a move's (fuzz: 3.6e307 overflowed a slave's TargetPos).
  const double reference = s_.job_.kind() == JobKind::kPosition
                               ? s_.job_.goal.target() + s_.stack_.held()
                               : s_.basic_state().p;
  const double target = type == Type::kAbsolute ? command.position : command.position + reference;
  if (const ErrorCode code = check_target(target); code != ErrorCode::kNone) return code;
  if (type == Type::kAbsolute) {
    if (!s_.stack_.external.taking()) {
      s_.base_ = s_.set_;  // the external set values take over from here
      s_.stack_.drop_held();
    }
    s_.stack_.external.enable(type, s_.set_, target, s_.config_.ext_setpoint_delay,
                              s_.config_.max_velocity);
  } else {
    s_.stack_.external.enable(type, KinematicState{}, target, s_.config_.ext_setpoint_delay,
                              s_.config_.max_velocity);
  }
  s_.target_ = target;
  s_.monitors_.reset_windows();
  s_.channel_.answer(command.number, CommandState::kDone);
  return ErrorCode::kNone;
}

ErrorCode SuperpositionCommands::disable_external(const plc::Command& command) noexcept {
  s_.stack_.external.disable();  // disabling what is not enabled is not an error: nothing to do
  s_.channel_.answer(command.number, CommandState::kDone);
  return ErrorCode::kNone;
}

// ---------------------------------------------------------------- the stack's rules

}  // namespace nc::detail
