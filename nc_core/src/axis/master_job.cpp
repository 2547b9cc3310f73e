#include "axis/master_job.hpp"

#include <algorithm>

namespace nc::detail {

namespace {
// A sample time this close below the duration counts as the end: k·T and a planned duration
// that are equal on paper may differ in the last bits.
constexpr double kEndTolerance = 1e-9;  // s
}  // namespace

void MasterJob::start(JobKind kind, uint16_t number, const Profile& profile, double target,
                      double target_velocity, const Limits& limits) noexcept {
  profile_ = profile;
  kind_ = kind;
  number_ = number;
  k_ = 0;
  ended_ = false;
  reached_ = false;
  target_ = target;
  target_velocity_ = target_velocity;
  jerk_ = 0.0;
  limits_ = limits;
}

void MasterJob::clear() noexcept {
  kind_ = JobKind::kNone;
  number_ = 0;
  k_ = 0;
  ended_ = false;
  reached_ = false;
  jerk_ = 0.0;
}

KinematicState MasterJob::advance(double cycle_time) noexcept {
  if (ended_) {
    jerk_ = 0.0;
    return profile_.final_state();
  }
  ++k_;
  const double t = static_cast<double>(k_) * cycle_time;
  const double end = profile_.duration();
  const bool at_end = t >= end - kEndTolerance * std::max(1.0, end);
  if (kind_ == JobKind::kVelocity) {
    // The hold goes on past the end of the profile: at() extrapolates it.
    if (at_end) reached_ = true;
    jerk_ = at_end ? 0.0 : profile_.jerk_at(t);
    return profile_.at(t);
  }
  if (at_end) {
    ended_ = true;
    jerk_ = 0.0;
    return profile_.final_state();
  }
  jerk_ = profile_.jerk_at(t);
  return profile_.at(t);
}

}  // namespace nc::detail
