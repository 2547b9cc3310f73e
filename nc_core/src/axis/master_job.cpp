#include "axis/master_job.hpp"

#include <algorithm>
#include <cmath>

namespace nc::detail {

namespace {
constexpr double kEndTolerance = JobTable::kEndTolerance;
// An acceleration this small is "a = 0" when looking for a held velocity level (the planner sets
// the acceleration at the end of a velocity change exactly; this absorbs the sign of -0.0 and
// the rounding of a sampled start state).
constexpr double kZeroAcceleration = 1e-6;  // mm/s²
// Relative tolerance of "|v| = level".
constexpr double kLevelTolerance = 1e-9;

double sign_of(double x) noexcept {
  return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
}

double end_acceleration(const Segment& s) noexcept {
  return s.a + s.j * s.duration;
}

double end_velocity(const Segment& s) noexcept {
  return s.v + s.a * s.duration + 0.5 * s.j * s.duration * s.duration;
}

// Calls f(v, a) at every point of interest of a table: its start, each segment start, the zero
// of a inside a segment, and its end.
template <class F>
void for_each_extremum(const Profile& profile, F&& f) noexcept {
  const KinematicState start = profile.start_state();
  f(start.v, start.a);
  for (std::size_t i = 0; i < profile.segment_count(); ++i) {
    const Segment& s = profile.segment(i);
    f(s.v, s.a);
    if (s.j != 0.0) {
      const double t = -s.a / s.j;
      if (t > 0.0 && t < s.duration) f(s.v + s.a * t + 0.5 * s.j * t * t, 0.0);
    }
  }
  const KinematicState end = profile.final_state();
  f(end.v, end.a);
}

}  // namespace

double brake_start(const Profile& profile) noexcept {
  const std::size_t n = profile.segment_count();
  double start = profile.duration();
  for (std::size_t i = n; i-- > 0;) {
    const Segment& s = profile.segment(i);
    const double v_end = end_velocity(s);
    const double dir = s.v != 0.0 ? sign_of(s.v) : sign_of(v_end);
    const double a0 = dir * s.a;
    const double a1 = dir * end_acceleration(s);
    const bool cruise = s.j == 0.0 && std::abs(s.a) <= kZeroAcceleration;
    if (!cruise && dir != 0.0 && a0 <= kZeroAcceleration && a1 <= kZeroAcceleration) {
      start = s.t0;  // |v| does not grow on this segment: still braking
      continue;
    }
    // A segment on which the acceleration falls through 0 (the planner may merge "acceleration
    // decrease" and "deceleration increase"): the braking starts at the zero of a.
    if (dir * s.j < 0.0 && a0 > 0.0 && a1 < 0.0) start = s.t0 + s.a / -s.j;
    break;
  }
  return start;
}

double peak_speed(const Profile& profile) noexcept {
  double peak = 0.0;
  for_each_extremum(profile, [&](double v, double) { peak = std::max(peak, std::abs(v)); });
  return peak;
}

bool reaches_level(const Profile& profile, double level) noexcept {
  bool reached = false;
  const double tolerance = kLevelTolerance * std::max(1.0, level);
  for_each_extremum(profile, [&](double v, double a) {
    if (std::abs(a) <= kZeroAcceleration && std::abs(std::abs(v) - level) <= tolerance) {
      reached = true;
    }
  });
  return reached;
}

double reduced_level(const Profile& profile, double velocity) noexcept {
  const double peak = peak_speed(profile);
  return peak >= velocity * (1.0 - kLevelTolerance) ? velocity : peak;
}

bool moves_only_along(const Profile& profile, double direction) noexcept {
  double scale = 0.0;
  double lowest = 0.0;
  for_each_extremum(profile, [&](double v, double) {
    scale = std::max(scale, std::abs(v));
    lowest = std::min(lowest, direction * v);
  });
  return lowest >= -kLevelTolerance * std::max(1.0, scale);
}

void MasterJob::start(JobKind kind, uint16_t number, const Profile& profile, double target,
                      double target_velocity, const Limits& limits) noexcept {
  kind_ = kind;
  number_ = number;
  goal.start(target, target_velocity, limits);
  online.start();
  final_ = true;
  table.install(profile);
  has_brake_phase_ = kind == JobKind::kPosition;
  brake_start_ = has_brake_phase_ ? brake_start(profile) : 0.0;
}

void MasterJob::replan(const Profile& profile, bool final) noexcept {
  final_ = final;
  table.install(profile);
  has_brake_phase_ = final && kind_ == JobKind::kPosition;
  brake_start_ = has_brake_phase_ ? brake_start(profile) : 0.0;
}

void MasterJob::clear() noexcept {
  kind_ = JobKind::kNone;
  number_ = 0;
  final_ = true;
  has_brake_phase_ = false;
  table.clear();
  online.activation() = Activation{};
}

void MasterJob::follow(const DecouplingChain& chain, uint16_t number, const Limits& limits,
                       uint32_t override_value) noexcept {
  number_ = number;
  goal.follow(chain, limits);
  online.follow(chain, override_value);
  table.follow(chain);
}

bool MasterJob::passes_in_next_cycle(double cycle_time) const noexcept {
  if (!passing() || table.generation_ended()) return false;
  const double end = table.duration();
  return table.sample_time(cycle_time) + cycle_time >= end - kEndTolerance * std::max(1.0, end);
}

void JobGoal::follow(const DecouplingChain& chain, const Limits& limits) noexcept {
  const double f = chain.total_factor();
  target_ = chain.position(target_);
  target_velocity_ = chain.velocity(target_velocity_);
  reduced_velocity_ *= std::abs(f);
  direction_ = f < 0.0 ? -direction_ : direction_;
  limits_ = limits;
}

void JobOnline::follow(const DecouplingChain& chain, uint32_t override_value) noexcept {
  if (activation_.armed) {
    const double f = chain.total_factor();
    activation_.position = chain.position(activation_.position);
    activation_.direction = f < 0.0 ? -activation_.direction : activation_.direction;
    activation_.velocity *= std::abs(f);
  }
  override_ = override_value;
  handled_override_ = override_value;
}

void JobTable::install(const Profile& profile) noexcept {
  profile_ = profile;
  chain_.count = 0;
  chained_ = false;
  k_ = 0;
  offset_ = 0.0;
  ended_ = false;
  reached_ = false;
  steady_until_ = 0;
  jerk_ = 0.0;
  state_ = profile.start_state();
}

void JobTable::clear() noexcept {
  k_ = 0;
  ended_ = false;
  reached_ = false;
  steady_until_ = 0;
  jerk_ = 0.0;
}

void JobTable::follow(const DecouplingChain& chain) noexcept {
  state_ = chain.state(state_);
  jerk_ *= chain.total_factor();
  // The chain of this table comes first (a former master that was itself decoupled online).
  DecouplingChain joined = chain_;
  for (std::size_t i = 0; i < chain.count; ++i)
    (void)joined.push(chain.levels[i].factor, chain.levels[i].offset);
  chain_ = joined;
  chained_ = chain_.count != 0;
  steady_until_ = 0;
}

bool MasterJob::in_brake_phase(double cycle_time) const noexcept {
  if (!has_brake_phase_) return false;
  if (table.generation_ended()) return true;
  const double t = table.sample_time(cycle_time);
  return t >= brake_start_ - kEndTolerance * std::max(1.0, brake_start_);
}

}  // namespace nc::detail
