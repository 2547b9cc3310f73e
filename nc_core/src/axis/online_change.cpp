// Online changes of a running positioning (SPEC B5, B6; seed 000 §2.3, §2.4) and the per-cycle
// step in which the override and a due new velocity act on the running job.
//
// New end position (MC_NewPos, kNewPos): the running positioning is replanned to the new target
// from the basic motion's set state with the user's V (the override applied). The planner gives
// the quickest way: where the axis has passed the new target or cannot stop before it, one
// continuous table stops and returns; where V was not reachable before and is now, it is reached.
// The command is answered kDone when accepted (Tc2 MC_NewPos: Done = new position accepted); the
// running command keeps CmdNo and ends kDone at the new target.
//
// New velocity and new end position (MC_NewPosAndVelo, kNewPosAndVelo: EPos, VNew, APos): the
// same replan to EPos with the old V (VOld), and VNew for later or now by the six cases of seed
// 000 §2.4, judged along the logical direction d (the direction of travel; at rest the direction
// to the running target):
//   1  Pos < APos <= EPos   VNew once the set position passes APos moving in d
//   2  APos <= Pos <= EPos  VNew at once
//   3  APos <= EPos < Pos   return to EPos with VOld
//   4  Pos <= EPos < APos   EPos with VOld only
//   5  EPos < APos <= Pos   return with VOld, VNew once APos is passed on the way back (beyond
//                           the vendor, who does not implement it)
//   6  EPos < Pos < APos    return with VOld
// New velocity: the table to the end position is replanned with VNew. VNew is "reachable" when
// that table holds or touches the level VNew (reaches_level); otherwise the level is reduced
// iteratively, halving its difference to the current speed, 8 attempts in all; when none is
// reachable the table that runs is kept.
// Brake phase: a due new velocity waits (is suspended) while the running table is in its brake
// phase and acts once it is not — e.g. when the new end position gives the table a new
// acceleration; a table that brakes to its end drops it with the job.
// Events: a request replaces a pending activation (cases 1, 5: by its own; cases 2, 3, 4, 6 and
// MC_NewPos: deletes it — seed 000 §2.4 "Event 1 … 4").
#include <cmath>

#include "axis/buffered_commands.hpp"
#include "axis/online_change.hpp"
#include "profile/validate.hpp"

namespace nc::detail {

namespace {

// Seed 000 §2.4: "the set velocity is reduced iteratively 7-8 times".
constexpr int kVelocityAttempts = 8;

}  // namespace

bool OnlineChange::stop_active() const noexcept {
  return s_.locked_ || s_.job_.kind() == JobKind::kHalt || s_.job_.kind() == JobKind::kStop;
}

ErrorCode OnlineChange::check_new_target(double target) const noexcept {
  // Beyond the planner's range (profile/validate.hpp) or outside the software limits: 0x4222.
  if (!within_magnitude(target) || s_.monitors_.below_min(target) ||
      s_.monitors_.above_max(target)) {
    return ErrorCode::kTargetPositionNotAllowed;
  }
  if (s_.job_.kind() != JobKind::kPosition) return ErrorCode::kFunctionNotAllowed;
  if (s_.stack_.compensation.running()) {
    return ErrorCode::kCompensationActive;  // seed 000 §2.3, §2.4
  }
  if (!s_.channel_.controller_enabled() || !s_.channel_.feed_enabled(target - s_.basic_state().p)) {
    return ErrorCode::kNoControllerOrFeedEnable;
  }
  return ErrorCode::kNone;
}

ErrorCode OnlineChange::new_position(const plc::Command& command) noexcept {
  if (s_.channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (stop_active()) return ErrorCode::kStopAlreadyActive;
  if (!std::isfinite(command.position)) return ErrorCode::kPositionNotFinite;
  if (const ErrorCode code = check_new_target(command.position); code != ErrorCode::kNone) {
    return code;
  }
  if (!retarget(command.position, s_.job_.goal.user_velocity()))
    return ErrorCode::kPlannerNoSolution;
  s_.job_.online.activation() =
      Activation{};  // an instantaneous-only request deletes a pending one
  s_.channel_.answer(command.number, plc::CommandState::kDone);
  return ErrorCode::kNone;
}

ErrorCode OnlineChange::new_position_and_velocity(const plc::Command& command) noexcept {
  if (s_.channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (stop_active()) return ErrorCode::kStopAlreadyActive;
  if (!std::isfinite(command.position)) return ErrorCode::kPositionNotFinite;
  if (!std::isfinite(command.velocity) || !std::isfinite(command.activation_position)) {
    return ErrorCode::kParameterNotFinite;
  }
  if (command.velocity <= 0.0) return ErrorCode::kVelocityNotPositive;
  if (command.velocity > s_.config_.max_velocity || command.velocity > s_.config_.ref_velocity) {
    return ErrorCode::kVelocityNotAllowed;
  }
  if (const ErrorCode code = check_new_target(command.position); code != ErrorCode::kNone) {
    return code;
  }

  // The six cases of seed 000 §2.4 in the logical direction d (positions multiplied by d).
  const KinematicState now = s_.basic_state();
  double d = now.v > 0.0 ? 1.0 : (now.v < 0.0 ? -1.0 : 0.0);
  if (d == 0.0) d = s_.job_.goal.target() >= s_.job_.table.state().p ? 1.0 : -1.0;
  const double pos = d * now.p;
  const double apos = d * command.activation_position;
  const double epos = d * command.position;
  Activation next{};
  next.velocity = command.velocity;
  next.position = command.activation_position;
  if (epos >= pos) {
    if (apos <= pos) {
      next.armed = true;  // case 2: at once (or as soon as the brake phase allows)
      next.immediate = true;
    } else if (apos <= epos) {
      next.armed = true;  // case 1: once APos is passed
      next.direction = d;
    }  // case 4: APos lies beyond the end, VNew never acts
  } else if (apos > epos && apos <= pos) {
    next.armed = true;  // case 5: once APos is passed on the way back
    next.direction = -d;
  }  // cases 3 and 6: back to EPos with VOld

  if (!retarget(command.position, s_.job_.goal.user_velocity()))
    return ErrorCode::kPlannerNoSolution;
  s_.job_.online.activation() =
      next;  // replaces (or, when not armed, deletes) a pending activation
  s_.channel_.answer(command.number, plc::CommandState::kDone);
  return ErrorCode::kNone;
}

bool OnlineChange::retarget(double target, double velocity) noexcept {
  const KinematicState from = s_.basic_state();
  Limits limits = s_.job_.goal.limits();
  limits.velocity = velocity;
  s_.scratch_ = plan_position(from, target, limits);
  if (!s_.scratch_.ok()) return false;
  const double reduced = reduced_level(s_.scratch_, velocity);
  const double direction = target >= from.p ? 1.0 : -1.0;
  const uint32_t override_value = s_.job_.online.override_value();
  const double level = override_level(velocity, reduced, override_value);
  bool final = true;
  if (override_value != plc::kOverrideFull && !plan_table(from, target, limits, level, final)) {
    return false;
  }
  s_.job_.goal.set_levels(velocity, reduced, direction);
  s_.job_.online.set_handled_override(override_value);
  install_table(target, final, level);
  s_.monitors_.reset_windows();
  return true;
}

bool OnlineChange::activate_velocity(double velocity) noexcept {
  const uint32_t override_value = s_.job_.online.override_value();
  const double f = override_factor(override_value);
  if (f == 0.0) {
    // At override 0 the job rests: VNew becomes its V and acts when the override rises.
    s_.job_.goal.set_levels(velocity, velocity, s_.job_.goal.direction());
    return false;
  }
  const KinematicState from = s_.basic_state();
  const double target = s_.job_.goal.target() + (from.p - s_.job_.table.state().p);
  const double direction = target >= from.p ? 1.0 : -1.0;
  const double speed = std::abs(from.v);
  Limits limits = s_.job_.goal.limits();
  double level = velocity * f;
  for (int attempt = 0; attempt < kVelocityAttempts; ++attempt) {
    limits.velocity = level;
    s_.scratch_ = plan_position(from, target, limits);
    if (s_.scratch_.ok() && reaches_level(s_.scratch_, level)) {
      s_.job_.goal.set_levels(velocity, level / f, direction);
      s_.job_.online.set_handled_override(override_value);
      install_table(target, true, level);
      return true;
    }
    level = speed + 0.5 * (level - speed);  // halve the difference to the current speed
  }
  return false;
}

void OnlineChange::install_table(double target, bool final, double level) noexcept {
  s_.job_.replan(s_.scratch_, final);
  s_.stack_.rebase();  // planned from s_.basic_state(): the held offset is in the table now
  if (s_.job_.kind() == JobKind::kPosition) {
    s_.job_.goal.set_target(target);
    s_.target_ = target;
  }
  s_.job_.goal.set_target_velocity(final ? s_.job_.goal.direction() * level : 0.0);
  if (final)
    BufferedCommands(s_).plan_blend(
        level);  // a blending command waits: the new table passes its target
}

}  // namespace nc::detail
