// The override (SPEC B3, seed 000 §2.2): PlcToNc.Override, 0 … 1'000'000 = 0 … 100 %, read at
// the start of every NC cycle. Instantaneous, not time-scaled: on a change the running table is
// replanned from the basic motion's set state with the new velocity level, which the planner
// reaches as fast as A+, A- and J allow (a lower level from above without undershoot).
//
// The level is base · override, the base being chosen by AxisConfig::override_type:
//   1, 3: the level "calculated and possibly reduced at the start" = the highest path velocity of
//         the table planned at 100 % when the job started (V when V is reached);
//   2, 4: the user's V.
// Types 1 and 2 keep the old table when the new table would not reach the new level; types 3
// and 4 take the new table, which reaches the best level below it that the distance allows
// (the planner is time-optimal, so that is the "smaller optimal velocity level").
// Override 0 brings a positioning to rest on its path (a rest table, the job stays active) and a
// velocity job to v = 0; a rising override moves on from there — from a rest the new table is
// always taken (keeping the rest would leave the job waiting for ever).
#include <cmath>

#include "axis/buffered_commands.hpp"
#include "axis/online_change.hpp"

namespace nc::detail {

namespace {

bool user_velocity_type(int override_type) noexcept {
  return override_type == 2 || override_type == 4;
}

// Types 1 and 2 keep the old table when the new level is not achievable.
bool keeps_table_type(int override_type) noexcept {
  return override_type == 1 || override_type == 2;
}

}  // namespace

// Fuzz finding K4: a new job starting from a hard-accelerating set state brings a back to 0 at
// its own J, which passes v + a·|a| / 2J; with a smaller J than the running job's that can pass
// the axis's max velocity. Then the new job takes the running job's (larger) jerk, as Halt and
// Stop keep the larger values; the running job kept the max velocity with it. The error ramp
// does the same (K5).
Limits with_running_jerk(const Limits& limits, const KinematicState& from, const MasterJob& running,
                         double max_velocity) noexcept {
  Limits l = limits;
  if (!running.active() || !(running.goal.limits().jerk > l.jerk)) return l;
  const double peak = std::abs(from.v + from.a * std::abs(from.a) / (2.0 * l.jerk));
  if (peak > max_velocity) l.jerk = running.goal.limits().jerk;
  return l;
}

double OnlineChange::override_level(double user_velocity, double reduced_velocity,
                                    uint32_t override_value) const noexcept {
  const double base =
      user_velocity_type(s_.config_.override_type) ? user_velocity : reduced_velocity;
  return base * override_factor(override_value);
}

bool OnlineChange::plan_table(const KinematicState& from, double target, const Limits& limits,
                              double level, bool& final) noexcept {
  if (level > 0.0) {
    Limits at_level = limits;
    at_level.velocity = level;
    s_.scratch_ = plan_position(from, target, at_level);
    final = true;
  } else {
    s_.scratch_ = plan_stop(from, limits.deceleration, limits.jerk);
    final = false;
  }
  return s_.scratch_.ok();
}

ErrorCode OnlineChange::start_positioning(uint16_t number, double target,
                                          const Limits& limits) noexcept {
  const Limits planned =
      with_running_jerk(limits, s_.set_, s_.running_motion(), s_.config_.max_velocity);
  // Planned at 100 % first: its peak is the level reduced at the start (types 1 and 3).
  s_.scratch_ = plan_position(s_.set_, target, planned);
  if (!s_.scratch_.ok()) return s_.scratch_.error();
  const double reduced = reduced_level(s_.scratch_, planned.velocity);
  const double direction = target >= s_.set_.p ? 1.0 : -1.0;
  const uint32_t override_value = s_.job_.online.override_value();
  const double level = override_level(planned.velocity, reduced, override_value);
  bool final = true;
  if (override_value != plc::kOverrideFull && !plan_table(s_.set_, target, planned, level, final)) {
    return s_.scratch_.error();
  }
  s_.accept(JobKind::kPosition, number, s_.scratch_, target, final ? direction * level : 0.0,
            planned);
  s_.job_.goal.set_levels(planned.velocity, reduced, direction);
  if (!final) s_.job_.replan(s_.scratch_, false);  // a start at override 0 waits at rest
  return ErrorCode::kNone;
}

ErrorCode OnlineChange::start_continuous(uint16_t number, double velocity,
                                         const Limits& limits) noexcept {
  const Limits planned =
      with_running_jerk(limits, s_.set_, s_.running_motion(), s_.config_.max_velocity);
  const double direction = velocity < 0.0 ? -1.0 : 1.0;
  const double speed = std::abs(velocity);
  const double level = speed * override_factor(s_.job_.online.override_value());
  s_.scratch_ = plan_velocity(s_.set_, direction * level, planned);
  if (!s_.scratch_.ok()) return s_.scratch_.error();
  s_.accept(JobKind::kVelocity, number, s_.scratch_, s_.target_, direction * level, planned);
  s_.job_.goal.set_levels(speed, speed, direction);
  return ErrorCode::kNone;
}

void OnlineChange::apply_override() noexcept {
  // Answered once: a change that is refused (brake phase, types 1 and 2) is not retried
  // (seed 000 §2.1 "In case of failure, the function is not called again automatically").
  s_.job_.online.set_handled_override(s_.job_.online.override_value());
  const KinematicState from = s_.basic_state();
  const double level = override_level(s_.job_.goal.user_velocity(), s_.job_.goal.reduced_velocity(),
                                      s_.job_.online.override_value());
  if (s_.job_.kind() == JobKind::kVelocity) {
    s_.scratch_ = plan_velocity(from, s_.job_.goal.direction() * level, s_.job_.goal.limits());
    if (s_.scratch_.ok()) install_table(s_.job_.goal.target(), true, level);
    return;
  }
  const bool resting = !s_.job_.final_table();
  if (!resting && s_.job_.in_brake_phase(s_.cycle_time_)) return;  // seed 000 §2.2
  // The job's end, moved by what ended superpositions left (s_.basic_state() includes it).
  const double target = s_.job_.goal.target() + (from.p - s_.job_.table.state().p);
  bool final = true;
  if (!plan_table(from, target, s_.job_.goal.limits(), level, final)) return;
  if (!final) {
    if (resting) return;
    // Override 0: rest on the path. A rest that would pass the target means the braking to the
    // target has in effect begun: the table goes on.
    const double toward = target - from.p;
    if (from.v * toward > 0.0 && (s_.scratch_.final_state().p - target) * toward > 0.0) return;
  } else if (!resting && keeps_table_type(s_.config_.override_type) &&
             !reaches_level(s_.scratch_, level)) {
    return;  // types 1 and 2: the new level is not achievable, the old table is kept
  }
  install_table(target, final, level);
}

}  // namespace nc::detail
