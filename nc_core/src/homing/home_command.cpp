// MC_Home on a servo axis (SPEC F, issue 13): the homing modes, their refusals, the position
// setting, and phase b while the default homing runs (homing_job.hpp). The rules are written in
// docs/behaviour.md "Homing".
#include <algorithm>
#include <cmath>

#include "homing/axis_homing.hpp"
#include "profile/validate.hpp"

namespace nc::detail {

using plc::CommandState;

ErrorCode AxisHoming::start_home(const plc::Command& command) noexcept {
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
  if (s_.channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (s_.locked_) return ErrorCode::kMotionCommandsLocked;
  if (command.buffer_mode != plc::MC_Aborting) return ErrorCode::kBufferModeNotSupported;
  if (!s_.channel_.controller_enabled()) return ErrorCode::kNoControllerOrFeedEnable;

  if (command.mode == plc::MC_ForceCalibration || command.mode == plc::MC_ResetCalibration) {
    // Only the flag: answered at once, without taking the axis (a running command goes on).
    s_.set_homed(command.mode == plc::MC_ForceCalibration);
    s_.channel_.answer(command.number, CommandState::kDone);
    return ErrorCode::kNone;
  }

  const double home = command.position == plc::DEFAULT_HOME_POSITION
                          ? s_.config_.homing_reference_position
                          : command.position;
  if (const ErrorCode code = check_target(home); code != ErrorCode::kNone) return code;

  if (command.mode == plc::MC_Direct) {
    // The actual position becomes `home`; the set position moves with it, so nothing jumps.
    if (s_.job_.active() || s_.homing_.active() || s_.set_.v != 0.0 || s_.set_.a != 0.0 ||
        s_.stack_.compensation.running() || s_.stack_.external.enabled()) {
      return ErrorCode::kHomingAxisMoving;
    }
    shift_position(home - s_.drive_.measured_position());
    s_.set_homed(true);
    s_.channel_.answer(command.number, CommandState::kDone);
    return ErrorCode::kNone;
  }

  // MC_DefaultHoming: a motion start (aborting the running motion) in both search directions.
  if (s_.stack_.external.enabled()) return ErrorCode::kStartTypeNotAllowed;
  // Its velocities are start velocities (seed 000 §2.1 table 2: not above Vmax or Vref).
  const double fastest =
      std::max(s_.config_.homing_velocity_to_cam, s_.config_.homing_velocity_off_cam);
  if (fastest > s_.config_.max_velocity || fastest > s_.config_.ref_velocity) {
    return ErrorCode::kVelocityNotAllowed;
  }
  if (s_.stack_.compensation.running()) return ErrorCode::kCompensationActive;
  if (!s_.channel_.feed_enabled(s_.config_.homing_cam_search_positive ? 1.0 : -1.0) ||
      !s_.channel_.feed_enabled(s_.config_.homing_sync_search_positive ? 1.0 : -1.0)) {
    return ErrorCode::kNoControllerOrFeedEnable;
  }
  const uint16_t running =
      s_.job_.active() ? s_.job_.number() : (s_.homing_.active() ? s_.homing_.number() : 0);
  // From the set state, with the aborted motion's larger jerk where the axis's own would ramp
  // its acceleration down past the max velocity, as a move does (K4, K8).
  const Limits own{s_.config_.homing_velocity_to_cam, s_.config_.acceleration,
                   s_.config_.deceleration, s_.config_.jerk};
  const double jerk =
      with_running_jerk(own, s_.set_, s_.running_motion(), s_.config_.max_velocity).jerk;
  if (!s_.homing_.start(command.number, s_.set_, home, s_.config_, jerk, s_.scratch_)) {
    return ErrorCode::kPlannerNoSolution;
  }
  s_.job_.clear();
  s_.channel_.take_over(command.number, running);
  s_.set_homed(false);  // the reference is searched anew
  s_.target_ = s_.set_.p;
  s_.monitors_.reset_windows();
  s_.has_been_stopped_ = false;
  s_.channel_.warnings.clear_except(Warning::kOverrideNotAllowed);
  return ErrorCode::kNone;
}

bool AxisHoming::reference_cam() const noexcept {
  const double p = s_.drive_.raw_position();
  return s_.config_.homing_cam_width > 0.0 && p >= s_.config_.homing_cam_position &&
         p <= s_.config_.homing_cam_position + s_.config_.homing_cam_width;
}

void AxisHoming::shift_position(double delta) noexcept {
  s_.drive_.set_measured(s_.drive_.measured_position() + delta);
  s_.set_.p += delta;
  s_.base_.p += delta;
  s_.previous_set_position_ += delta;
  s_.previous_drive_position_ += delta;
  s_.drive_command_.p += delta;
  s_.target_ += delta;
}

void AxisHoming::run_homing() noexcept {
  HomingJob::Inputs in;
  in.cam = plc::test_bit(s_.channel_.ref().PlcToNc.ControlDWord, plc::kControlHomingSensor);
  in.raw_position = s_.drive_.raw_position();
  in.actual_position = s_.drive_.measured_position();
  in.offset = s_.drive_.offset();
  const HomingJob::Step step = s_.homing_.advance(in, s_.cycle_time_, s_.scratch_);
  if (step.referenced) {
    shift_position(step.shift);
    s_.set_homed(true);
  }
  s_.base_ = step.state;
  s_.set_jerk_ = step.jerk;
  if (step.error != ErrorCode::kNone) s_.raise_error(step.error);
}

}  // namespace nc::detail
