// MC_Home on a servo axis (SPEC F, issue 13): the homing modes, their refusals, the position
// setting, and phase b while the default homing runs (homing_job.hpp). The rules are written in
// docs/behaviour.md "Homing".
#include <algorithm>
#include <cmath>

#include "axis/servo_axis.hpp"
#include "profile/validate.hpp"

namespace nc::detail {

using plc::CommandState;

ErrorCode ServoAxis::start_home(const plc::Command& command) noexcept {
  // The modes Tc2_MC2 names but ncsdk does not provide, and values outside the enumeration.
  switch (command.mode) {
    case plc::MC_DefaultHoming:
    case plc::MC_Direct:
    case plc::MC_ForceCalibration:
    case plc::MC_ResetCalibration:
      break;
    case plc::MC_AbsSwitch:
    case plc::MC_LimitSwitch:
    case plc::MC_RefPulse:
      return ErrorCode::kHomingModeNotSupported;
    default:
      return ErrorCode::kBlockInputOutOfRange;
  }
  if (channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (locked_) return ErrorCode::kMotionCommandsLocked;
  if (command.buffer_mode != plc::MC_Aborting) return ErrorCode::kBufferModeNotSupported;
  if (!channel_.controller_enabled()) return ErrorCode::kNoControllerOrFeedEnable;

  if (command.mode == plc::MC_ForceCalibration || command.mode == plc::MC_ResetCalibration) {
    // Only the flag: answered at once, without taking the axis (a running command goes on).
    set_homed(command.mode == plc::MC_ForceCalibration);
    channel_.answer(command.number, CommandState::kDone);
    return ErrorCode::kNone;
  }

  const double home = command.position == plc::DEFAULT_HOME_POSITION
                          ? config_.homing_reference_position
                          : command.position;
  if (const ErrorCode code = check_target(home); code != ErrorCode::kNone) return code;

  if (command.mode == plc::MC_Direct) {
    // The actual position becomes `home`; the set position moves with it, so nothing jumps.
    if (job_.active() || homing_.active() || set_.v != 0.0 || set_.a != 0.0 ||
        stack_.compensation().running() || stack_.external().enabled()) {
      return ErrorCode::kHomingAxisMoving;
    }
    shift_position(home - drive_.measured_position());
    set_homed(true);
    channel_.answer(command.number, CommandState::kDone);
    return ErrorCode::kNone;
  }

  // MC_DefaultHoming: a motion start (aborting the running motion) in both search directions.
  if (stack_.external().enabled()) return ErrorCode::kStartTypeNotAllowed;
  // Its velocities are start velocities (seed 000 §2.1 table 2: not above Vmax or Vref).
  const double fastest = std::max(config_.homing_velocity_to_cam, config_.homing_velocity_off_cam);
  if (fastest > config_.max_velocity || fastest > config_.ref_velocity) {
    return ErrorCode::kVelocityNotAllowed;
  }
  if (stack_.compensation().running()) return ErrorCode::kCompensationActive;
  if (!channel_.feed_enabled(config_.homing_cam_search_positive ? 1.0 : -1.0) ||
      !channel_.feed_enabled(config_.homing_sync_search_positive ? 1.0 : -1.0)) {
    return ErrorCode::kNoControllerOrFeedEnable;
  }
  const uint16_t running =
      job_.active() ? job_.number() : (homing_.active() ? homing_.number() : 0);
  // From the set state, with the aborted motion's larger jerk where the axis's own would ramp
  // its acceleration down past the max velocity, as a move does (K4, K8).
  const Limits own{config_.homing_velocity_to_cam, config_.acceleration, config_.deceleration,
                   config_.jerk};
  const double jerk = with_running_jerk(own, set_, running_motion(), config_.max_velocity).jerk;
  if (!homing_.start(command.number, set_, home, config_, jerk, scratch_)) {
    return ErrorCode::kPlannerNoSolution;
  }
  job_.clear();
  channel_.take_over(command.number, running);
  set_homed(false);  // the reference is searched anew
  target_ = set_.p;
  monitors_.reset_windows();
  has_been_stopped_ = false;
  channel_.clear_warnings_except(Warning::kOverrideNotAllowed);
  return ErrorCode::kNone;
}

bool ServoAxis::reference_cam() const noexcept {
  const double p = drive_.raw_position();
  return config_.homing_cam_width > 0.0 && p >= config_.homing_cam_position &&
         p <= config_.homing_cam_position + config_.homing_cam_width;
}

void ServoAxis::shift_position(double delta) noexcept {
  drive_.set_measured(drive_.measured_position() + delta);
  set_.p += delta;
  base_.p += delta;
  previous_set_position_ += delta;
  previous_drive_position_ += delta;
  drive_command_.p += delta;
  target_ += delta;
}

void ServoAxis::run_homing() noexcept {
  HomingJob::Inputs in;
  in.cam = plc::test_bit(channel_.ref().PlcToNc.ControlDWord, plc::kControlHomingSensor);
  in.raw_position = drive_.raw_position();
  in.actual_position = drive_.measured_position();
  in.offset = drive_.offset();
  const HomingJob::Step step = homing_.advance(in, cycle_time_, scratch_);
  if (step.referenced) {
    shift_position(step.shift);
    set_homed(true);
  }
  base_ = step.state;
  set_jerk_ = step.jerk;
  if (step.error != ErrorCode::kNone) raise_error(step.error);
}

}  // namespace nc::detail
