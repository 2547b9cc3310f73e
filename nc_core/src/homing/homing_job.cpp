#include "homing/homing_job.hpp"

#include <cmath>

namespace nc::detail {

bool HomingJob::plan(const KinematicState& from, double velocity, bool stop,
                     Profile& scratch) noexcept {
  Limits limits = limits_;
  limits.velocity = std::abs(velocity);
  scratch = stop ? plan_stop(from, limits.deceleration, limits.jerk)
                 : plan_velocity(from, velocity, limits);
  if (!scratch.ok()) return false;
  motion_.start(stop ? JobKind::kStop : JobKind::kVelocity, number_, scratch,
                scratch.final_state().p, velocity, limits);
  return true;
}

bool HomingJob::start(uint16_t number, const KinematicState& from, double home,
                      const AxisConfig& config, double jerk, Profile& scratch) noexcept {
  number_ = number;
  home_ = home;
  cam_direction_ = config.homing_cam_search_positive ? 1.0 : -1.0;
  sync_direction_ = config.homing_sync_search_positive ? 1.0 : -1.0;
  velocity_off_cam_ = config.homing_velocity_off_cam;
  pulse_distance_ = config.homing_sync_pulse_distance;
  search_distance_ = config.homing_search_distance;
  limits_ = Limits{config.homing_velocity_to_cam, config.acceleration, config.deceleration, jerk};
  travel_ = 0.0;
  last_position_ = from.p;
  cam_seen_ = false;
  if (!plan(from, cam_direction_ * config.homing_velocity_to_cam, false, scratch)) {
    phase_ = Phase::kIdle;
    return false;
  }
  phase_ = Phase::kTowardsCam;
  return true;
}

HomingJob::Step HomingJob::advance(const Inputs& in, double cycle_time, Profile& scratch) noexcept {
  Step step;
  step.state = motion_.advance(cycle_time);
  step.jerk = motion_.table.jerk();
  travel_ += std::abs(step.state.p - last_position_);
  last_position_ = step.state.p;

  bool reference = false;
  double reference_actual = 0.0;  // displayed position of the reference point before the shift
  switch (phase_) {
    case Phase::kIdle:
    case Phase::kStopping:
      return step;
    case Phase::kTowardsCam:
      if (in.cam) {
        travel_ = 0.0;
        if (!plan(step.state, sync_direction_ * velocity_off_cam_, false, scratch)) {
          step.error = ErrorCode::kPlannerNoSolution;
          return step;
        }
        phase_ = Phase::kOffCam;
        cam_seen_ = true;
      } else if (travel_ > search_distance_) {
        step.error = ErrorCode::kHomingCamNotFound;
      }
      return step;
    case Phase::kOffCam:
      cam_seen_ = cam_seen_ || in.cam;
      if (cam_seen_ && !in.cam) {
        // A pulse grid finer than the position's resolution (|position / distance| >= 2^52, or
        // not finite: a denormal distance, fuzz finding K9) puts the next pulse within rounding
        // of the edge: the edge is the reference, as with no pulse.
        const double n = pulse_distance_ > 0.0 ? in.raw_position / pulse_distance_ : 0.0;
        if (pulse_distance_ > 0.0 && std::abs(n) < 0x1p52) {
          // The first pulse strictly beyond the edge in the sync direction.
          pulse_ =
              (sync_direction_ > 0.0 ? std::floor(n) + 1.0 : std::ceil(n) - 1.0) * pulse_distance_;
          phase_ = Phase::kSyncPulse;
        } else {
          reference = true;
          reference_actual = in.actual_position;
        }
      }
      break;
    case Phase::kSyncPulse:
      if (sync_direction_ > 0.0 ? in.raw_position >= pulse_ : in.raw_position <= pulse_) {
        reference = true;
        reference_actual = pulse_ + in.offset;  // where the display showed the pulse
      }
      break;
  }
  if (!reference) {
    if (travel_ > search_distance_) step.error = ErrorCode::kHomingSyncPulseNotFound;
    return step;
  }
  step.referenced = true;
  step.shift = home_ - reference_actual;
  step.state.p += step.shift;
  last_position_ = step.state.p;
  if (!plan(step.state, 0.0, true, scratch)) {
    step.error = ErrorCode::kPlannerNoSolution;
    return step;
  }
  phase_ = Phase::kStopping;
  return step;
}

}  // namespace nc::detail
