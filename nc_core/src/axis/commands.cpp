// Step a of the NC cycle for one axis: drain the mailbox, validate each command, act, answer
// (contract in plc_interface/command.hpp and the team brief). A refused command changes nothing:
// every check runs before anything is written, and a start is planned into a scratch profile.
#include <cmath>

#include "axis/axis_commands.hpp"
#include "axis/group_errors.hpp"

#include "axis/buffered_commands.hpp"
#include "axis/online_change.hpp"
#include "axis/servo_axis.hpp"
#include "axis/slave_coupling.hpp"
#include "axis/superposition_commands.hpp"
#include "homing/axis_homing.hpp"
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

void AxisCommands::drain(CouplingPort& port) noexcept {
  plc::CommandMailbox& mailbox = s_.channel_.ref().Mailbox;
  plc::Command command;
  s_.note_event();  // any command may change what publish shows
  while (mailbox.take(command))
    handle(command, port);
}

void AxisCommands::handle(const plc::Command& command, CouplingPort& port) noexcept {
  ErrorCode code = ErrorCode::kNone;
  // An HLI target's program feeds its drive only through its list (SPEC D3): external setpoints
  // are refused there as on a coupled slave.
  if (((s_.slave_link_.coupled || s_.slave_link_.detached) &&
       SlaveCoupling::refused_while_coupled(command.type)) ||
      (s_.hli_target() && command.type == CommandType::kExtSetPointGenEnable)) {
    s_.channel_.answer(command.number, CommandState::kError,
                       plc::to_id(ErrorCode::kFunctionNotAllowed));
    return;
  }
  if (command.buffer_mode != plc::MC_Aborting && bufferable(command.type)) {
    code = BufferedCommands(s_).buffer_command(command, port);  // command_buffer.cpp
  } else {
    code = handle_now(command, port);
  }
  if (code != ErrorCode::kNone) {
    s_.channel_.answer(command.number, CommandState::kError, plc::to_id(code));
  }
}

ErrorCode AxisCommands::handle_now(const plc::Command& command, CouplingPort& port) noexcept {
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
      code = OnlineChange(s_).new_position(command);
      break;
    case CommandType::kNewPosAndVelo:
      code = OnlineChange(s_).new_position_and_velocity(command);
      break;
    case CommandType::kHalt:
    case CommandType::kStop:
      code = start_halt_or_stop(command);
      break;
    case CommandType::kMoveSuperImposed:
      code = SuperpositionCommands(s_).start_compensation(command);
      break;
    case CommandType::kAbortSuperposition:
      code = SuperpositionCommands(s_).stop_compensation(command);
      break;
    case CommandType::kExtSetPointGenEnable:
      code = SuperpositionCommands(s_).enable_external(command);
      break;
    case CommandType::kExtSetPointGenDisable:
      code = SuperpositionCommands(s_).disable_external(command);
      break;
    case CommandType::kGearIn:
      code = SlaveCoupling(s_).gear_in(command, port);
      break;
    case CommandType::kGearInDyn:
      code = SlaveCoupling(s_).gear_in_dyn(command, port);
      break;
    case CommandType::kGearOut:
      code = SlaveCoupling(s_).gear_out(command, port);
      break;
    case CommandType::kHome:
      code = AxisHoming(s_).start_home(command);
      break;
    case CommandType::kReset:
      // Answered at once and without taking CmdNo: a reset is not a job. It also cancels an
      // MC_Stop lock (Tc2_MC2: "the locking of the axis is canceled with an MC_Reset").
      GroupErrors(s_).reset_error();
      s_.locked_ = false;
      s_.end_external_generation();  // seed 000 §2.6: an axis reset switches it off
      s_.channel_.answer(command.number, CommandState::kDone);
      break;
    case CommandType::kStopRelease:
      s_.locked_ = false;
      s_.channel_.answer(command.number, CommandState::kDone);
      break;
    default:
      code = ErrorCode::kUnknownCommand;
      break;
  }
  return code;
}

ErrorCode AxisCommands::check_dynamics(const plc::Command& command, Limits& limits) const noexcept {
  if (!std::isfinite(command.velocity) || !std::isfinite(command.acceleration) ||
      !std::isfinite(command.deceleration) || !std::isfinite(command.jerk)) {
    return ErrorCode::kParameterNotFinite;
  }
  // Table 2 of seed 000 §2.1: V > 0, V <= Vmax, and not above the reference velocity.
  if (command.velocity <= 0.0) return ErrorCode::kVelocityNotPositive;
  if (command.velocity > s_.config_.max_velocity || command.velocity > s_.config_.ref_velocity) {
    return ErrorCode::kVelocityNotAllowed;
  }
  ErrorCode code = check_dynamic(command.acceleration, ErrorCode::kAccelerationNotAllowed);
  if (code == ErrorCode::kNone) {
    code = check_dynamic(command.deceleration, ErrorCode::kDecelerationNotAllowed);
  }
  if (code == ErrorCode::kNone) code = check_dynamic(command.jerk, ErrorCode::kJerkNotAllowed);
  if (code != ErrorCode::kNone) return code;
  limits.velocity = command.velocity;
  limits.acceleration = command.acceleration > 0.0 ? command.acceleration : s_.config_.acceleration;
  limits.deceleration = command.deceleration > 0.0 ? command.deceleration : s_.config_.deceleration;
  limits.jerk = command.jerk > 0.0 ? command.jerk : s_.config_.jerk;
  return ErrorCode::kNone;
}

ErrorCode AxisCommands::check_start(const plc::Command& command, bool has_position,
                                    Limits& limits) const noexcept {
  if (s_.channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (s_.locked_) return ErrorCode::kMotionCommandsLocked;
  // Seed 000 §2.6: external generation may join a running PTP motion (relative), "the opposite
  // case is not permitted".
  if (s_.stack_.external.enabled()) return ErrorCode::kStartTypeNotAllowed;
  if (!known_buffer_mode(command.buffer_mode)) return ErrorCode::kBufferModeNotSupported;
  if (has_position && !std::isfinite(command.position)) return ErrorCode::kPositionNotFinite;
  return check_dynamics(command, limits);
}

ErrorCode AxisCommands::start_position(const plc::Command& command) noexcept {
  Limits limits;
  if (const ErrorCode code = check_start(command, true, limits); code != ErrorCode::kNone) {
    return code;
  }
  const double target =
      command.type == CommandType::kMoveAbsolute ? command.position : s_.set_.p + command.position;
  return start_to_target(command.number, target, limits);
}

ErrorCode AxisCommands::start_to_target(uint16_t number, double target,
                                        const Limits& limits) noexcept {
  // NaN / inf 0x4F01; beyond the planner's range (profile/validate.hpp) 0x4222.
  if (const ErrorCode code = check_target(target); code != ErrorCode::kNone) return code;
  // Seed 000 §2.1 notes 4 and 5: the target must lie inside the software limits; where the axis
  // starts from does not matter, so a start from outside back into the range is allowed.
  if (s_.monitors_.below_min(target) || s_.monitors_.above_max(target)) {
    return ErrorCode::kTargetPositionNotAllowed;
  }
  const double distance = target - s_.set_.p;
  if (!s_.channel_.controller_enabled() || !s_.channel_.feed_enabled(distance)) {
    return ErrorCode::kNoControllerOrFeedEnable;
  }
  const bool at_rest = s_.set_.v == 0.0 && s_.set_.a == 0.0;
  if (at_rest && (distance == 0.0 || std::abs(distance) < s_.config_.encoder_increment)) {
    // Seed 000 §2.1: no start for a path shorter than one encoder increment — a warning.
    s_.channel_.warnings.warn(Warning::kMovementSmallerThanIncrement);
    s_.channel_.answer(number, CommandState::kDone);
    return ErrorCode::kNone;
  }
  return OnlineChange(s_).start_positioning(number, target,
                                            limits);  // override.cpp: the override applies
}

ErrorCode AxisCommands::start_velocity(const plc::Command& command) noexcept {
  Limits limits;
  if (const ErrorCode code = check_start(command, false, limits); code != ErrorCode::kNone) {
    return code;
  }
  // MC_Current_Direction: the direction the axis moves in; at standstill there is none.
  const double direction = command.direction == plc::MC_Current_Direction
                               ? s_.current_direction()
                               : velocity_direction(command.direction);
  if (direction == 0.0) return ErrorCode::kDirectionInvalid;
  // Continuous motion has no target: refuse it only when it would run further out from (or
  // straight through) an enabled software limit it already stands on or beyond.
  if (direction > 0.0 && s_.monitors_.at_or_above_max(s_.set_.p)) {
    return ErrorCode::kSoftLimitMaxAtStart;
  }
  if (direction < 0.0 && s_.monitors_.at_or_below_min(s_.set_.p)) {
    return ErrorCode::kSoftLimitMinAtStart;
  }
  if (!s_.channel_.controller_enabled() || !s_.channel_.feed_enabled(direction)) {
    return ErrorCode::kNoControllerOrFeedEnable;
  }
  return OnlineChange(s_).start_continuous(command.number, direction * limits.velocity, limits);
}

ErrorCode AxisCommands::check_halt_or_stop(const plc::Command& command) const noexcept {
  const bool stop = command.type == CommandType::kStop;
  if (s_.channel_.has_error()) return ErrorCode::kAxisInErrorState;
  // A stop has priority and may replace a stop; a halt is a motion command and is locked out.
  if (!stop && s_.locked_) return ErrorCode::kMotionCommandsLocked;
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
  if (!s_.channel_.controller_enabled()) return ErrorCode::kNoControllerOrFeedEnable;
  return ErrorCode::kNone;
}

ErrorCode AxisCommands::start_halt_or_stop(const plc::Command& command) noexcept {
  const bool stop = command.type == CommandType::kStop;
  if (const ErrorCode code = check_halt_or_stop(command); code != ErrorCode::kNone) return code;

  // 0 = the running motion's deceleration and jerk (a homing's too, K8; the error ramp's, which
  // a reset lets finish, K24: at the axis's defaults a hard acceleration would be brought back
  // too slowly and pass the max velocity), or the axis default when nothing runs.
  const MasterJob& running = s_.running_motion();
  const bool motion = running.is_motion() || running.kind() == JobKind::kHalt ||
                      running.kind() == JobKind::kStop || running.kind() == JobKind::kEmergencyStop;
  Limits limits{motion ? running.goal.limits().velocity : s_.config_.max_velocity,
                motion ? running.goal.limits().acceleration : s_.config_.acceleration,
                motion ? running.goal.limits().deceleration : s_.config_.deceleration,
                motion ? running.goal.limits().jerk : s_.config_.jerk};
  // Seed 000 §2.2 "Emergency stop": the command's deceleration and jerk replace the running
  // motion's only when both are larger, and never in the brake phase (the braking that runs goes
  // on: a stop with the running motion's values continues it).
  const bool braking = running.in_brake_phase(s_.cycle_time_);
  if (!braking && command.deceleration > limits.deceleration && command.jerk > limits.jerk) {
    limits.deceleration = command.deceleration;
    limits.jerk = command.jerk;
  }
  // Without the running compensation: it gets its compensation stop on top (seed 000 §2.5).
  s_.scratch_ = plan_stop(s_.stack_.stop_start_state(s_.set_), limits.deceleration, limits.jerk);
  if (!s_.scratch_.ok()) return s_.scratch_.error();
  s_.accept(stop ? JobKind::kStop : JobKind::kHalt, command.number, s_.scratch_,
            s_.scratch_.final_state().p, 0.0, limits);
  if (braking) s_.job_.mark_brake_phase();
  if (stop) s_.locked_ = true;
  s_.has_been_stopped_ = true;
  return ErrorCode::kNone;
}

}  // namespace nc::detail
