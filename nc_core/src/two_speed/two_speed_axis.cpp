// The phases of the NC cycle for a two-speed axis: the blocks' commands into the sequencer, the
// sequencer's image into the plant, the NC→PLC image with nAxisState (SPEC E1-E6; the choices in
// docs/behaviour.md "Two-speed axis").
#include "two_speed/two_speed_axis.hpp"

#include <cmath>

namespace nc::detail {

namespace {

using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

// +1 / -1 for the direction bits of nExtControlByte, 0 when the image commands no travel.
double image_direction(const plc::NCTOIO_DRIVE_TWO_SPEED& image) noexcept {
  using E = plc::ExtControlByteBit;
  if (plc::bit_set(image.nExtControlByte, E::bDirectionPlus)) return 1.0;
  if (plc::bit_set(image.nExtControlByte, E::bDirectionMinus)) return -1.0;
  return 0.0;
}

}  // namespace

TwoSpeedAxis::TwoSpeedAxis(const AxisConfig& config, double cycle_time, AxisChannel& channel)
    : config_(config),
      cycle_time_(cycle_time),
      channel_(channel),
      sequencer_(config),
      plant_(config, 0.0) {
  monitors_.configure(config_, cycle_time_);
}

void TwoSpeedAxis::phase_commands() noexcept {
  const uint32_t override_value = channel_.ref().PlcToNc.Override;
  if (sequencer_.set_override(override_value) == ErrorCode::kNone) {
    channel_.warnings.clear(Warning::kOverrideNotAllowed);
  } else {
    channel_.warnings.warn(Warning::kOverrideNotAllowed);  // not taken: the last valid value stays
  }
  plc::CommandMailbox& mailbox = channel_.ref().Mailbox;
  if (mailbox.pending() != 0) {
    plc::Command command;
    while (mailbox.take(command))
      handle(command);
  }
  check_enables();
}

void TwoSpeedAxis::handle(const plc::Command& command) noexcept {
  ErrorCode code = ErrorCode::kNone;
  switch (command.type) {
    case CommandType::kMoveAbsolute:
    case CommandType::kMoveRelative:
      code = start(command);
      break;
    case CommandType::kHalt:
    case CommandType::kStop:
      code = stop(command);
      break;
    case CommandType::kReset:
      // As on a servo axis: not a job, answered at once; it also ends an MC_Stop lock.
      channel_.warnings.clear_all();
      channel_.clear_error();
      locked_ = false;
      channel_.answer(command.number, CommandState::kDone);
      return;
    case CommandType::kStopRelease:
      locked_ = false;
      channel_.answer(command.number, CommandState::kDone);
      return;
    case CommandType::kHome:
      code = ErrorCode::kUnknownCommand;  // homing comes with its issue, for every axis kind
      break;
    default:
      // Continuous motion, modulo, new positions, superpositions, external setpoints and every
      // coupling: a two-speed axis knows only positionings and stops (seed 004).
      code = ErrorCode::kAxisKindNotAllowed;
      break;
  }
  if (code != ErrorCode::kNone) {
    channel_.answer(command.number, CommandState::kError, plc::to_id(code));
  }
}

ErrorCode TwoSpeedAxis::start(const plc::Command& command) noexcept {
  if (channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (locked_) return ErrorCode::kMotionCommandsLocked;
  if (command.buffer_mode != plc::MC_Aborting) return ErrorCode::kBufferModeNotSupported;
  if (!std::isfinite(command.position)) return ErrorCode::kPositionNotFinite;
  // No set position: a distance counts from the actual one.
  const double actual = plant_.position();
  const double target =
      command.type == CommandType::kMoveAbsolute ? command.position : actual + command.position;
  if (!std::isfinite(target)) return ErrorCode::kPositionNotFinite;
  if (monitors_.below_min(target) || monitors_.above_max(target)) {
    return ErrorCode::kTargetPositionNotAllowed;
  }
  // Both feed enables a looping positioning needs: out past the target and back.
  const double distance = target - actual;
  const double loop = config_.looping_distance_enabled ? config_.looping_distance : 0.0;
  const bool returns = loop != 0.0 && (loop > 0.0) == (distance > 0.0);
  if (!channel_.controller_enabled() || !channel_.feed_enabled(distance) ||
      (returns && !channel_.feed_enabled(-distance))) {
    return ErrorCode::kNoControllerOrFeedEnable;
  }
  const ErrorCode code = sequencer_.start(target, command.velocity, actual);
  if (code != ErrorCode::kNone) return code;
  channel_.take_over(command.number, job_);
  job_ = command.number;
  has_been_stopped_ = false;
  channel_.warnings.clear_except(Warning::kOverrideNotAllowed);
  monitors_.reset_windows();
  return ErrorCode::kNone;
}

ErrorCode TwoSpeedAxis::stop(const plc::Command& command) noexcept {
  const bool is_stop = command.type == CommandType::kStop;
  if (channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (!is_stop && locked_) return ErrorCode::kMotionCommandsLocked;
  if (!is_stop && command.buffer_mode != plc::MC_Aborting) {
    return ErrorCode::kBufferModeNotSupported;
  }
  // A two-speed stop has no ramp to set, but a broken value is still refused.
  if (!std::isfinite(command.deceleration) || !std::isfinite(command.jerk)) {
    return ErrorCode::kParameterNotFinite;
  }
  if (command.deceleration < 0.0) return ErrorCode::kDecelerationNotAllowed;
  if (command.jerk < 0.0) return ErrorCode::kJerkNotAllowed;
  if (!channel_.controller_enabled()) return ErrorCode::kNoControllerOrFeedEnable;
  const ErrorCode code = sequencer_.stop(plant_.position());
  if (code != ErrorCode::kNone) return code;
  channel_.take_over(command.number, job_);
  job_ = command.number;
  if (is_stop) locked_ = true;
  has_been_stopped_ = true;
  return ErrorCode::kNone;
}

void TwoSpeedAxis::check_enables() noexcept {
  const bool enabled = channel_.controller_enabled();
  if (!enabled && sequencer_.busy()) raise_error(ErrorCode::kControllerEnableMissing);
  sequencer_.set_enabled(enabled);
  if (!enabled || channel_.has_error()) return;
  // The feed enable of the direction the contactors drive in is gone: the brake comes on.
  const double direction = image_direction(sequencer_.image());
  if (direction > 0.0 && !channel_.feed_enabled(1.0)) {
    raise_error(ErrorCode::kFeedEnablePlusMissing);
  } else if (direction < 0.0 && !channel_.feed_enabled(-1.0)) {
    raise_error(ErrorCode::kFeedEnableMinusMissing);
  }
}

void TwoSpeedAxis::raise_error(ErrorCode code) noexcept {
  if (!channel_.raise(code)) return;
  has_been_stopped_ = true;
  if (sequencer_.busy() && channel_.runs(job_)) {
    channel_.answer_current(CommandState::kError, plc::to_id(code));
  }
  sequencer_.abort();
}

void TwoSpeedAxis::phase_set_values(AxisSnapshot& snapshot) noexcept {
  const TwoSpeedCycle cycle = sequencer_.step(plant_.position(), cycle_time_);
  switch (cycle.event) {
    case TwoSpeedEvent::kNone:
      break;
    case TwoSpeedEvent::kDone:
    case TwoSpeedEvent::kStopped:
      if (channel_.runs(job_)) channel_.answer_current(CommandState::kDone);
      break;
    case TwoSpeedEvent::kError:
      raise_error(cycle.error);
      break;
  }
  // No set position: the other axes (and the HLI stage) see the actual one.
  snapshot.set_position = plant_.position();
  snapshot.set_velocity = commanded_velocity();
  snapshot.set_acceleration = 0.0;
  snapshot.set_jerk = 0.0;
}

void TwoSpeedAxis::phase_drive(AxisSnapshot& snapshot) noexcept {
  previous_velocity_ = plant_.velocity();
  plant_.step(sequencer_.image(), cycle_time_);
  snapshot.actual_position = plant_.position();
  snapshot.actual_velocity = plant_.velocity();
  snapshot.actual_acceleration = (plant_.velocity() - previous_velocity_) / cycle_time_;
}

void TwoSpeedAxis::phase_monitors(AxisSnapshot& snapshot) noexcept {
  // The windows count once a positioning has ended (its brake is on); they do not gate Done.
  const bool settled = channel_.controller_enabled() && !sequencer_.busy() &&
                       sequencer_.state() == plc::TwoSpeedAxisState::kStopped;
  monitors_.windows(plant_.position(), sequencer_.target(), settled);
  snapshot.error = channel_.error();
  snapshot.error_event = false;
  const uint32_t control = channel_.ref().PlcToNc.ControlDWord;
  snapshot.controller_enabled = plc::test_bit(control, plc::kControlEnable);
  snapshot.feed_enabled_plus = plc::test_bit(control, plc::kControlFeedEnablePlus);
  snapshot.feed_enabled_minus = plc::test_bit(control, plc::kControlFeedEnableMinus);
}

double TwoSpeedAxis::commanded_velocity() const noexcept {
  const plc::NCTOIO_DRIVE_TWO_SPEED& image = sequencer_.image();
  using E = plc::ExtControlByteBit;
  const double speed = plc::bit_set(image.nExtControlByte, E::bVeloHigh)  ? config_.rapid_velocity
                       : plc::bit_set(image.nExtControlByte, E::bVeloLow) ? config_.creep_velocity
                                                                          : 0.0;
  return image_direction(image) * speed;
}

void TwoSpeedAxis::phase_publish(uint64_t cycle_counter, int32_t index) noexcept {
  plc::NCTOPLC_AXIS_REF& out = channel_.ref().NcToPlc;
  const double actual = plant_.position();
  const double commanded = commanded_velocity();
  const bool enabled = channel_.controller_enabled();
  const bool error = channel_.has_error();
  out.ActPos = actual;
  out.ActVelo = plant_.velocity();
  out.ActAcc = (plant_.velocity() - previous_velocity_) / cycle_time_;
  out.SetPos = actual;
  out.SetVelo = commanded;
  out.SetAcc = 0.0;
  out.SetJerk = 0.0;
  out.PosDiff = 0.0;
  out.TargetPos = sequencer_.target();
  out.TargetVelo = std::abs(commanded);
  out.CycleCounter = static_cast<uint32_t>(cycle_counter);
  channel_.publish(index);

  uint32_t word = 0;
  const auto set_bit = [&word](plc::StateBit bit, bool value) noexcept {
    word |= static_cast<uint32_t>(value) << bit;
  };
  set_bit(plc::kStateOperational, enabled && !error);
  set_bit(plc::kStateHomed, true);  // no homing sequence: a two-speed axis counts as homed
  set_bit(plc::kStateNotMoving, std::abs(plant_.velocity()) < config_.standstill_window);
  set_bit(plc::kStateInPositionArea, monitors_.in_position_area());
  set_bit(plc::kStateInTargetPosition, monitors_.in_target_position());
  set_bit(plc::kStateHasBeenStopped, has_been_stopped_);
  set_bit(plc::kStateHasJob, sequencer_.busy());
  set_bit(plc::kStatePositiveDirection, commanded > 0.0);
  set_bit(plc::kStateNegativeDirection, commanded < 0.0);
  set_bit(plc::kStateConstantVelocity, commanded != 0.0 && plant_.velocity() == commanded);
  set_bit(plc::kStatePtpMode, true);
  set_bit(plc::kStateSoftLimitMinExceeded, monitors_.below_min(actual));
  set_bit(plc::kStateSoftLimitMaxExceeded, monitors_.above_max(actual));
  set_bit(plc::kStateMotionCommandsLocked, locked_);
  set_bit(plc::kStateError, error);
  out.StateDWord = word;
  out.AxisState = static_cast<uint32_t>(sequencer_.state());  // nAxisState (E5)
}

}  // namespace nc::detail
