// Step a of the NC cycle for one axis: drain the mailbox, validate each command, act, answer
// (contract in plc_interface/command.hpp and the team brief). A refused command changes nothing:
// every check runs before anything is written, and a start is planned into a scratch profile.
#include <cmath>

#include "axis/group_errors.hpp"
#include "axis/servo_axis.hpp"
#include "axis/slave_coupling.hpp"
#include "profile/validate.hpp"

namespace nc::detail {

namespace {

using plc::CommandState;
using plc::CommandType;

// Velocity-move direction: +1 or MC_Positive_Direction forward; -1 or MC_Negative_Direction
// backward (plc::Command documents both encodings). 0 = invalid.
double velocity_direction(int32_t direction) noexcept {
  if (direction == plc::MC_Positive_Direction) return 1.0;
  if (direction == -1 || direction == plc::MC_Negative_Direction) return -1.0;
  return 0.0;
}

// A command's A, D or J: 0 = the default, otherwise within the planner's numeric range
// (profile/validate.hpp, docs/behaviour.md "Starts"); negative or outside: `code`.
ErrorCode check_dynamic(double value, ErrorCode code) noexcept {
  if (value == 0.0) return ErrorCode::kNone;
  return check_positive(value, code);
}

}  // namespace

void ServoAxis::handle_commands(CouplingPort& port) noexcept {
  plc::CommandMailbox& mailbox = channel_.ref().Mailbox;
  if (mailbox.pending() == 0) return;  // the steady case: no call into the mailbox
  plc::Command command;
  while (mailbox.take(command))
    handle(command, port);
}

void ServoAxis::handle(const plc::Command& command, CouplingPort& port) noexcept {
  ErrorCode code = ErrorCode::kNone;
  // An HLI target's program feeds its drive only through its list (SPEC D3): external setpoints
  // are refused there as on a coupled slave.
  if (((slave_link_.coupled || slave_link_.detached) &&
       SlaveCoupling::refused_while_coupled(command.type)) ||
      (hli_target() && command.type == CommandType::kExtSetPointGenEnable)) {
    channel_.answer(command.number, CommandState::kError,
                    plc::to_id(ErrorCode::kFunctionNotAllowed));
    return;
  }
  if (command.buffer_mode != plc::MC_Aborting && bufferable(command.type)) {
    code = buffer_command(command, port);  // command_buffer.cpp
  } else {
    code = handle_now(command, port);
  }
  if (code != ErrorCode::kNone) {
    channel_.answer(command.number, CommandState::kError, plc::to_id(code));
  }
}

ErrorCode ServoAxis::handle_now(const plc::Command& command, CouplingPort& port) noexcept {
  ErrorCode code = ErrorCode::kNone;
  switch (command.type) {
    case CommandType::kMoveAbsolute:
    case CommandType::kMoveRelative:
      code = start_position(command);
      break;
    case CommandType::kMoveModulo:
      code = start_modulo(command);
      break;
    case CommandType::kMoveVelocity:
      code = start_velocity(command);
      break;
    case CommandType::kNewPos:
      code = new_position(command);
      break;
    case CommandType::kNewPosAndVelo:
      code = new_position_and_velocity(command);
      break;
    case CommandType::kHalt:
    case CommandType::kStop:
      code = start_halt_or_stop(command);
      break;
    case CommandType::kMoveSuperImposed:
      code = start_compensation(command);
      break;
    case CommandType::kAbortSuperposition:
      code = stop_compensation(command);
      break;
    case CommandType::kExtSetPointGenEnable:
      code = enable_external(command);
      break;
    case CommandType::kExtSetPointGenDisable:
      code = disable_external(command);
      break;
    case CommandType::kGearIn:
      code = SlaveCoupling(*this).gear_in(command, port);
      break;
    case CommandType::kGearInDyn:
      code = SlaveCoupling(*this).gear_in_dyn(command, port);
      break;
    case CommandType::kGearOut:
      code = SlaveCoupling(*this).gear_out(command, port);
      break;
    case CommandType::kHome:
      code = start_home(command);
      break;
    case CommandType::kReset:
      // Answered at once and without taking CmdNo: a reset is not a job. It also cancels an
      // MC_Stop lock (Tc2_MC2: "the locking of the axis is canceled with an MC_Reset").
      GroupErrors(*this).reset_error();
      locked_ = false;
      end_external_generation();  // seed 000 §2.6: an axis reset switches it off
      channel_.answer(command.number, CommandState::kDone);
      break;
    case CommandType::kStopRelease:
      locked_ = false;
      channel_.answer(command.number, CommandState::kDone);
      break;
    default:
      code = ErrorCode::kUnknownCommand;
      break;
  }
  return code;
}

ErrorCode ServoAxis::check_dynamics(const plc::Command& command, Limits& limits) const noexcept {
  if (!std::isfinite(command.velocity) || !std::isfinite(command.acceleration) ||
      !std::isfinite(command.deceleration) || !std::isfinite(command.jerk)) {
    return ErrorCode::kParameterNotFinite;
  }
  // Table 2 of seed 000 §2.1: V > 0, V <= Vmax, and not above the reference velocity.
  if (command.velocity <= 0.0) return ErrorCode::kVelocityNotPositive;
  if (command.velocity > config_.max_velocity || command.velocity > config_.ref_velocity) {
    return ErrorCode::kVelocityNotAllowed;
  }
  ErrorCode code = check_dynamic(command.acceleration, ErrorCode::kAccelerationNotAllowed);
  if (code == ErrorCode::kNone) {
    code = check_dynamic(command.deceleration, ErrorCode::kDecelerationNotAllowed);
  }
  if (code == ErrorCode::kNone) code = check_dynamic(command.jerk, ErrorCode::kJerkNotAllowed);
  if (code != ErrorCode::kNone) return code;
  limits.velocity = command.velocity;
  limits.acceleration = command.acceleration > 0.0 ? command.acceleration : config_.acceleration;
  limits.deceleration = command.deceleration > 0.0 ? command.deceleration : config_.deceleration;
  limits.jerk = command.jerk > 0.0 ? command.jerk : config_.jerk;
  return ErrorCode::kNone;
}

ErrorCode ServoAxis::check_start(const plc::Command& command, bool has_position,
                                 Limits& limits) const noexcept {
  if (channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (locked_) return ErrorCode::kMotionCommandsLocked;
  // Seed 000 §2.6: external generation may join a running PTP motion (relative), "the opposite
  // case is not permitted".
  if (stack_.external().enabled()) return ErrorCode::kStartTypeNotAllowed;
  if (!known_buffer_mode(command.buffer_mode)) return ErrorCode::kBufferModeNotSupported;
  if (has_position && !std::isfinite(command.position)) return ErrorCode::kPositionNotFinite;
  return check_dynamics(command, limits);
}

ErrorCode ServoAxis::start_position(const plc::Command& command) noexcept {
  Limits limits;
  if (const ErrorCode code = check_start(command, true, limits); code != ErrorCode::kNone) {
    return code;
  }
  const double target =
      command.type == CommandType::kMoveAbsolute ? command.position : set_.p + command.position;
  return start_to_target(command.number, target, limits);
}

ErrorCode ServoAxis::start_to_target(uint16_t number, double target,
                                     const Limits& limits) noexcept {
  // NaN / inf 0x4F01; beyond the planner's range (profile/validate.hpp) 0x4222.
  if (const ErrorCode code = check_target(target); code != ErrorCode::kNone) return code;
  // Seed 000 §2.1 notes 4 and 5: the target must lie inside the software limits; where the axis
  // starts from does not matter, so a start from outside back into the range is allowed.
  if (monitors_.below_min(target) || monitors_.above_max(target)) {
    return ErrorCode::kTargetPositionNotAllowed;
  }
  const double distance = target - set_.p;
  if (!channel_.controller_enabled() || !channel_.feed_enabled(distance)) {
    return ErrorCode::kNoControllerOrFeedEnable;
  }
  const bool at_rest = set_.v == 0.0 && set_.a == 0.0;
  if (at_rest && (distance == 0.0 || std::abs(distance) < config_.encoder_increment)) {
    // Seed 000 §2.1: no start for a path shorter than one encoder increment — a warning.
    channel_.warn(Warning::kMovementSmallerThanIncrement);
    channel_.answer(number, CommandState::kDone);
    return ErrorCode::kNone;
  }
  return start_positioning(number, target, limits);  // override.cpp: the override applies
}

ErrorCode ServoAxis::start_velocity(const plc::Command& command) noexcept {
  Limits limits;
  if (const ErrorCode code = check_start(command, false, limits); code != ErrorCode::kNone) {
    return code;
  }
  // MC_Current_Direction: the direction the axis moves in; at standstill there is none.
  const double direction = command.direction == plc::MC_Current_Direction
                               ? current_direction()
                               : velocity_direction(command.direction);
  if (direction == 0.0) return ErrorCode::kDirectionInvalid;
  // Continuous motion has no target: refuse it only when it would run further out from (or
  // straight through) an enabled software limit it already stands on or beyond.
  if (direction > 0.0 && monitors_.at_or_above_max(set_.p)) return ErrorCode::kSoftLimitMaxAtStart;
  if (direction < 0.0 && monitors_.at_or_below_min(set_.p)) return ErrorCode::kSoftLimitMinAtStart;
  if (!channel_.controller_enabled() || !channel_.feed_enabled(direction)) {
    return ErrorCode::kNoControllerOrFeedEnable;
  }
  return start_continuous(command.number, direction * limits.velocity, limits);
}

ErrorCode ServoAxis::check_halt_or_stop(const plc::Command& command) const noexcept {
  const bool stop = command.type == CommandType::kStop;
  if (channel_.has_error()) return ErrorCode::kAxisInErrorState;
  // A stop has priority and may replace a stop; a halt is a motion command and is locked out.
  if (!stop && locked_) return ErrorCode::kMotionCommandsLocked;
  if (!stop && !known_buffer_mode(command.buffer_mode)) {
    return ErrorCode::kBufferModeNotSupported;
  }
  if (!std::isfinite(command.deceleration) || !std::isfinite(command.jerk)) {
    return ErrorCode::kParameterNotFinite;
  }
  if (const ErrorCode code =
          check_dynamic(command.deceleration, ErrorCode::kDecelerationNotAllowed);
      code != ErrorCode::kNone) {
    return code;
  }
  if (const ErrorCode code = check_dynamic(command.jerk, ErrorCode::kJerkNotAllowed);
      code != ErrorCode::kNone) {
    return code;
  }
  if (!channel_.controller_enabled()) return ErrorCode::kNoControllerOrFeedEnable;
  return ErrorCode::kNone;
}

ErrorCode ServoAxis::start_halt_or_stop(const plc::Command& command) noexcept {
  const bool stop = command.type == CommandType::kStop;
  if (const ErrorCode code = check_halt_or_stop(command); code != ErrorCode::kNone) return code;

  // 0 = the running motion's deceleration and jerk (a homing's too, K8), or the axis default
  // when nothing runs.
  const MasterJob& running = running_motion();
  const bool motion =
      running.is_motion() || running.kind() == JobKind::kHalt || running.kind() == JobKind::kStop;
  Limits limits{motion ? running.limits().velocity : config_.max_velocity,
                motion ? running.limits().acceleration : config_.acceleration,
                motion ? running.limits().deceleration : config_.deceleration,
                motion ? running.limits().jerk : config_.jerk};
  // Seed 000 §2.2 "Emergency stop": the command's deceleration and jerk replace the running
  // motion's only when both are larger, and never in the brake phase (the braking that runs goes
  // on: a stop with the running motion's values continues it).
  const bool braking = running.in_brake_phase(cycle_time_);
  if (!braking && command.deceleration > limits.deceleration && command.jerk > limits.jerk) {
    limits.deceleration = command.deceleration;
    limits.jerk = command.jerk;
  }
  // Without the running compensation: it gets its compensation stop on top (seed 000 §2.5).
  scratch_ = plan_stop(stack_.stop_start_state(set_), limits.deceleration, limits.jerk);
  if (!scratch_.ok()) return scratch_.error();
  accept(stop ? JobKind::kStop : JobKind::kHalt, command.number, scratch_, scratch_.final_state().p,
         0.0, limits);
  if (braking) job_.mark_brake_phase();
  if (stop) locked_ = true;
  has_been_stopped_ = true;
  return ErrorCode::kNone;
}

}  // namespace nc::detail
