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
  if (a_.channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (a_.locked_) return ErrorCode::kMotionCommandsLocked;
  if (command.buffer_mode != plc::MC_Aborting) return ErrorCode::kBufferModeNotSupported;
  if (!a_.channel_.controller_enabled()) return ErrorCode::kNoControllerOrFeedEnable;

  if (command.mode == plc::MC_ForceCalibration || command.mode == plc::MC_ResetCalibration) {
    // Only the flag: answered at once, without taking the axis (a running command goes on).
    a_.set_homed(command.mode == plc::MC_ForceCalibration);
    a_.channel_.answer(command.number, CommandState::kDone);
    return ErrorCode::kNone;
  }

  const double home = command.position == plc::DEFAULT_HOME_POSITION
                          ? a_.config_.homing_reference_position
                          : command.position;
  if (const ErrorCode code = check_target(home); code != ErrorCode::kNone) return code;

  if (command.mode == plc::MC_Direct) {
    // The actual position becomes `home`; the set position moves with it, so nothing jumps.
    if (a_.job_.active() || a_.homing_.active() || a_.set_.v != 0.0 || a_.set_.a != 0.0 ||
        a_.stack_.compensation().running() || a_.stack_.external().enabled()) {
      return ErrorCode::kHomingAxisMoving;
    }
    shift_position(home - a_.drive_.measured_position());
    a_.set_homed(true);
    a_.channel_.answer(command.number, CommandState::kDone);
    return ErrorCode::kNone;
  }

  // MC_DefaultHoming: a motion start (aborting the running motion) in both search directions.
  if (a_.stack_.external().enabled()) return ErrorCode::kStartTypeNotAllowed;
  // Its velocities are start velocities (seed 000 §2.1 table 2: not above Vmax or Vref).
  const double fastest =
      std::max(a_.config_.homing_velocity_to_cam, a_.config_.homing_velocity_off_cam);
  if (fastest > a_.config_.max_velocity || fastest > a_.config_.ref_velocity) {
    return ErrorCode::kVelocityNotAllowed;
  }
  if (a_.stack_.compensation().running()) return ErrorCode::kCompensationActive;
  if (!a_.channel_.feed_enabled(a_.config_.homing_cam_search_positive ? 1.0 : -1.0) ||
      !a_.channel_.feed_enabled(a_.config_.homing_sync_search_positive ? 1.0 : -1.0)) {
    return ErrorCode::kNoControllerOrFeedEnable;
  }
  const uint16_t running =
      a_.job_.active() ? a_.job_.number() : (a_.homing_.active() ? a_.homing_.number() : 0);
  // From the set state, with the aborted motion's larger jerk where the axis's own would ramp
  // its acceleration down past the max velocity, as a move does (K4, K8).
  const Limits own{a_.config_.homing_velocity_to_cam, a_.config_.acceleration,
                   a_.config_.deceleration, a_.config_.jerk};
  const double jerk =
      with_running_jerk(own, a_.set_, a_.running_motion(), a_.config_.max_velocity).jerk;
  if (!a_.homing_.start(command.number, a_.set_, home, a_.config_, jerk, a_.scratch_)) {
    return ErrorCode::kPlannerNoSolution;
  }
  a_.job_.clear();
  a_.channel_.take_over(command.number, running);
  a_.set_homed(false);  // the reference is searched anew
  a_.target_ = a_.set_.p;
  a_.monitors_.reset_windows();
  a_.has_been_stopped_ = false;
  a_.channel_.clear_warnings_except(Warning::kOverrideNotAllowed);
  return ErrorCode::kNone;
}

bool AxisHoming::reference_cam() const noexcept {
  const double p = a_.drive_.raw_position();
  return a_.config_.homing_cam_width > 0.0 && p >= a_.config_.homing_cam_position &&
         p <= a_.config_.homing_cam_position + a_.config_.homing_cam_width;
}

void AxisHoming::shift_position(double delta) noexcept {
  a_.drive_.set_measured(a_.drive_.measured_position() + delta);
  a_.set_.p += delta;
  a_.base_.p += delta;
  a_.previous_set_position_ += delta;
  a_.previous_drive_position_ += delta;
  a_.drive_command_.p += delta;
  a_.target_ += delta;
}

void AxisHoming::run_homing() noexcept {
  HomingJob::Inputs in;
  in.cam = plc::test_bit(a_.channel_.ref().PlcToNc.ControlDWord, plc::kControlHomingSensor);
  in.raw_position = a_.drive_.raw_position();
  in.actual_position = a_.drive_.measured_position();
  in.offset = a_.drive_.offset();
  const HomingJob::Step step = a_.homing_.advance(in, a_.cycle_time_, a_.scratch_);
  if (step.referenced) {
    shift_position(step.shift);
    a_.set_homed(true);
  }
  a_.base_ = step.state;
  a_.set_jerk_ = step.jerk;
  if (step.error != ErrorCode::kNone) a_.raise_error(step.error);
}

}  // namespace nc::detail
