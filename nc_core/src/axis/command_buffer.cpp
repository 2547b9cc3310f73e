// BufferMode (issue 14; docs/behaviour.md "BufferMode"): the axis's one buffered command, when it
// takes over, and the blend — the running positioning replanned to pass its target with the
// blend velocity, so that the next command starts there without stopping.
//
// Blend velocity: the mode's choice of the two commands' velocities (times the override), then
// limited to what the path allows: 0 when the next command reverses (or is a halt), not above
// the speed from which the next positioning can still stop at its own target, and within the
// speeds the running table can reach at its target without moving backwards (found by
// bisection between the wanted speed and the speed the axis has now).
#include "axis/buffered_commands.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "axis/axis_commands.hpp"
#include "axis/command_buffer.hpp"

namespace nc::detail {

namespace {

using plc::CommandState;
using plc::CommandType;

// Bisection steps for a speed limit: 2^-40 of the wanted speed is far below one cycle's change.
constexpr int kBisectionSteps = 40;

double sign_of(double x) noexcept {
  return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
}

// The distance the shortest stop from `speed` (a = 0) takes at `deceleration` and `jerk`.
double stop_distance(double speed, double deceleration, double jerk) noexcept {
  const Profile stop = plan_stop(KinematicState{0.0, speed, 0.0}, deceleration, jerk);
  return stop.ok() ? stop.final_state().p : std::numeric_limits<double>::infinity();
}

// Appends `from`'s segments to `to` with their exact end values; false when `to` is full.
bool append_all(Profile& to, const Profile& from) noexcept {
  for (std::size_t i = 0; i < from.segment_count(); ++i) {
    const Segment& s = from.segment(i);
    const KinematicState end =
        i + 1 < from.segment_count()
            ? KinematicState{0.0, from.segment(i + 1).v, from.segment(i + 1).a}
            : from.final_state();
    if (!to.append(s.duration, s.j, end.a, end.v)) return false;
  }
  return true;
}

}  // namespace

double blend_velocity(int32_t mode, double previous, double next) noexcept {
  switch (mode) {
    case plc::MC_BlendingLow:
      return std::min(previous, next);
    case plc::MC_BlendingPrevious:
      return previous;
    case plc::MC_BlendingNext:
      return next;
    case plc::MC_BlendingHigh:
      return std::max(previous, next);
    default:
      return 0.0;
  }
}

ErrorCode BufferedCommands::buffer_command(const plc::Command& command,
                                           CouplingPort& port) noexcept {
  // The command's own checks now (a refusal leaves the waiting one and the running job as
  // they are); what depends on where it starts (targets, enables) when it takes over.
  if (command.type == CommandType::kHalt) {
    if (const ErrorCode code = AxisCommands(s_).check_halt_or_stop(command);
        code != ErrorCode::kNone) {
      return code;
    }
  } else {
    Limits limits;
    const bool has_position = command.type != CommandType::kMoveVelocity;
    if (const ErrorCode code = AxisCommands(s_).check_start(command, has_position, limits);
        code != ErrorCode::kNone) {
      return code;
    }
  }
  if (s_.buffer_waiting_) return ErrorCode::kBufferFull;
  s_.buffer_.command = command;
  s_.buffer_waiting_ = true;
  s_.channel_.answer(command.number, CommandState::kBuffered);
  if (ready_for_next()) {
    take_next(port);
  } else if (blending_mode(command.buffer_mode)) {
    plan_blend(std::abs(s_.job_.goal.target_velocity()));
  }
  return ErrorCode::kNone;
}

bool BufferedCommands::ready_for_next() const noexcept {
  // Behind MC_Home: when the homing is Done (it ends at rest, so a blend waits as MC_Buffered).
  if (s_.homing_.active()) return false;
  switch (s_.job_.kind()) {
    case JobKind::kNone:
      return true;
    case JobKind::kPosition:
      return s_.job_.final_table() &&
             (s_.job_.table.generation_ended() || s_.job_.passes_in_next_cycle(s_.cycle_time_));
    case JobKind::kHalt:
      return s_.job_.table.generation_ended();
    case JobKind::kVelocity:
      return s_.job_.table.velocity_reached();
    case JobKind::kStop:
    case JobKind::kEmergencyStop:
      return false;  // a stop locks, an error ramp drops the buffer: never reached
  }
  return false;
}

void BufferedCommands::run_buffer(CouplingPort& port) noexcept {
  if (s_.buffer_waiting_ && ready_for_next()) take_next(port);
  // A pass whose next command was refused when taking over (or dropped) must not run away.
  if (!s_.buffer_waiting_ && s_.job_.passing() && s_.job_.table.generation_ended()) stop_pass();
}

void BufferedCommands::take_next(CouplingPort& port) noexcept {
  plc::Command next = s_.buffer_.command;
  s_.buffer_waiting_ = false;
  next.buffer_mode = plc::MC_Aborting;
  // Relative and modulo targets count from the running positioning's target (where a buffered
  // command starts), not from where the set values are when it takes over.
  const bool after_positioning = s_.job_.kind() == JobKind::kPosition;
  const double base = after_positioning ? s_.job_.goal.target() : s_.set_.p;
  ErrorCode code = ErrorCode::kNone;
  if (next.type == CommandType::kMoveRelative) {
    next.type = CommandType::kMoveAbsolute;
    next.position = base + next.position;
  } else if (next.type == CommandType::kMoveModulo) {
    double end = 0.0;
    code = AxisCommands(s_).modulo_end(
        next, base, after_positioning ? s_.job_.goal.direction() : s_.current_direction(), end);
    next.type = CommandType::kMoveAbsolute;
    next.position = end;
  }
  // The running command is done here (a velocity job is aborted by the take-over itself).
  if (s_.job_.kind() == JobKind::kPosition || s_.job_.kind() == JobKind::kHalt) {
    if (s_.channel_.runs(s_.job_.number())) s_.channel_.answer_current(CommandState::kDone);
  }
  if (code == ErrorCode::kNone) {
    const KinematicState basic = s_.basic_state();
    const bool exact = s_.job_.passes_in_next_cycle(s_.cycle_time_) && basic.p == s_.set_.p &&
                       basic.v == s_.set_.v && basic.a == s_.set_.a;
    if (exact) {
      // The pass ends within this cycle: the next command starts from the pass's end state at
      // its end time, so its first sample lies between 0 and T after the target.
      const KinematicState now = s_.set_;
      const double offset = s_.job_.table.sample_time(s_.cycle_time_) - s_.job_.table.duration();
      s_.set_ = s_.job_.table.end_state();
      code = AxisCommands(s_).handle_now(next, port);
      s_.set_ = now;
      if (code == ErrorCode::kNone && s_.job_.number() == next.number) {
        s_.job_.table.set_time_offset(offset);
      }
    } else {
      code = AxisCommands(s_).handle_now(next, port);
    }
  }
  if (code != ErrorCode::kNone) {
    s_.channel_.answer(next.number, CommandState::kError, plc::to_id(code));
    if (s_.job_.passing()) stop_pass();
  }
}

void BufferedCommands::stop_pass() noexcept {
  s_.scratch_ = plan_stop(s_.set_, s_.job_.goal.limits().deceleration, s_.job_.goal.limits().jerk);
  if (!s_.scratch_.ok()) return;
  s_.job_.replan(s_.scratch_, true);
  s_.job_.goal.set_target(s_.scratch_.final_state().p);
  s_.job_.goal.set_target_velocity(0.0);
  s_.target_ = s_.scratch_.final_state().p;
  s_.monitors_.reset_windows();
}

double BufferedCommands::next_direction(const plc::Command& next, double from, double direction,
                                        double& end) const noexcept {
  end = std::numeric_limits<double>::quiet_NaN();
  switch (next.type) {
    case CommandType::kMoveAbsolute:
      end = next.position;
      break;
    case CommandType::kMoveRelative:
      end = from + next.position;
      break;
    case CommandType::kMoveModulo:
      if (AxisCommands(s_).modulo_end(next, from, direction, end) != ErrorCode::kNone) return 0.0;
      break;
    case CommandType::kMoveVelocity:
      if (next.direction == plc::MC_Current_Direction) return direction;
      if (next.direction == plc::MC_Positive_Direction) return 1.0;
      if (next.direction == -1 || next.direction == plc::MC_Negative_Direction) return -1.0;
      return 0.0;
    default:
      return 0.0;  // a halt ends the motion: nothing to blend into
  }
  return sign_of(end - from);
}

void BufferedCommands::plan_blend(double level) noexcept {
  if (!s_.buffer_waiting_ || !blending_mode(s_.buffer_.command.buffer_mode)) return;
  if (s_.job_.kind() != JobKind::kPosition || !s_.job_.final_table() ||
      s_.job_.table.generation_ended()) {
    return;
  }
  if (!(level > 0.0)) return;
  const plc::Command& next = s_.buffer_.command;
  const KinematicState from = s_.basic_state();
  // The job's end, moved by what ended superpositions left (as apply_override()).
  const double target = s_.job_.goal.target() + (from.p - s_.job_.table.state().p);
  const double direction = s_.job_.goal.direction();
  double end = 0.0;
  if (next_direction(next, target, direction, end) != direction) return;  // reversal: at rest

  const double factor = level / s_.job_.goal.user_velocity();  // the override in force
  double wanted = std::min(
      blend_velocity(next.buffer_mode, s_.job_.goal.user_velocity(), next.velocity) * factor,
      s_.config_.max_velocity);
  if (std::isfinite(end)) {
    // Not faster than the next positioning can still stop from before its own end.
    const double room = std::abs(end - target);
    const double dec = next.deceleration > 0.0 ? next.deceleration : s_.config_.deceleration;
    const double jerk = next.jerk > 0.0 ? next.jerk : s_.config_.jerk;
    if (stop_distance(wanted, dec, jerk) > room) {
      double fits = 0.0;
      double too_fast = wanted;
      for (int i = 0; i < kBisectionSteps; ++i) {
        const double mid = 0.5 * (fits + too_fast);
        (stop_distance(mid, dec, jerk) <= room ? fits : too_fast) = mid;
      }
      wanted = fits;
    }
  }
  if (!(wanted > 0.0)) return;

  Limits limits = s_.job_.goal.limits();
  limits.velocity = level;
  double speed = wanted;
  if (!plan_pass(from, target, direction, speed, limits)) {
    // Between the speed the axis has now (reachable unless it is already too late to stop) and
    // the wanted one lies the bound of what the rest of the path allows.
    double good = std::clamp(direction * from.v, 0.0, wanted);
    if (!(good > 0.0) || !plan_pass(from, target, direction, good, limits)) return;
    double bad = wanted;
    for (int i = 0; i < kBisectionSteps; ++i) {
      const double mid = 0.5 * (good + bad);
      (plan_pass(from, target, direction, mid, limits) ? good : bad) = mid;
    }
    speed = good;
    if (!plan_pass(from, target, direction, speed, limits)) return;
  }
  s_.job_.replan(s_.scratch_, true);
  s_.stack_.rebase();  // planned from s_.basic_state(): the held offset is in the table now
  s_.job_.goal.set_target(target);
  s_.job_.goal.set_target_velocity(direction * level);
  s_.target_ = target;
}

bool BufferedCommands::plan_pass(const KinematicState& from, double target, double direction,
                                 double speed, const Limits& limits) noexcept {
  if (speed <= limits.velocity) {
    s_.scratch_ = plan_position(from, target, direction * speed, limits);
    return s_.scratch_.ok() && moves_only_along(s_.scratch_, direction);
  }
  // Faster than the running level: hold the level, then speed up so that the speed is reached
  // exactly at the target (the speed-up is the last part of the running command).
  Limits up = limits;
  up.velocity = speed;
  const Profile rise =
      plan_velocity(KinematicState{0.0, direction * limits.velocity, 0.0}, direction * speed, up);
  if (rise.ok()) {
    const Profile lead =
        plan_position(from, target - rise.final_state().p, direction * limits.velocity, limits);
    if (lead.ok() && moves_only_along(lead, direction)) {
      s_.scratch_.reset(from);
      if (append_all(s_.scratch_, lead) && append_all(s_.scratch_, rise)) {
        const KinematicState exact{target, direction * speed, 0.0};
        s_.scratch_.close(&exact, true);
        s_.scratch_.anchor_to_end(lead.segment_count());
        return true;
      }
    }
  }
  // Too short to hold the level first: the quickest way to the speed at the target.
  s_.scratch_ = plan_position(from, target, direction * speed, up);
  return s_.scratch_.ok() && moves_only_along(s_.scratch_, direction);
}

}  // namespace nc::detail
