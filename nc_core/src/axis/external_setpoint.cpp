// External setpoint generation of one axis (seed 000 §2.6, SPEC B8); see external_setpoint.hpp.
#include "axis/external_setpoint.hpp"

#include <cmath>

#include "profile/validate.hpp"

namespace nc::detail {

void ExternalSetpoint::enable(Type type, const KinematicState& start, double target, double delay,
                              double max_velocity) noexcept {
  target_ = target;
  delay_ = delay;
  max_velocity_ = max_velocity;
  if (taking() && type == type_) {
    enabled_ = true;
    final_cycle_ = false;
    return;
  }
  type_ = type;
  state_ = start;
  enabled_ = true;
  final_cycle_ = false;
  was_moving_ = false;
}

void ExternalSetpoint::disable() noexcept {
  if (!enabled_) return;
  enabled_ = false;
  final_cycle_ = true;
}

void ExternalSetpoint::abort() noexcept {
  enabled_ = false;
  final_cycle_ = false;
  was_moving_ = false;
  state_.v = 0.0;
  state_.a = 0.0;
}

ExternalSetpoint::Step ExternalSetpoint::take(const plc::PLCTONC_AXIS_REF& in,
                                              double cycle_time) noexcept {
  Step step;
  if (!taking()) {
    step.state = state_;
    return step;
  }
  const bool moving = in.ExtSetDirection == 1 || in.ExtSetDirection == -1;
  const bool full = enabled_ && moving;
  // Seed 000 §2.6: after the direction returns to 0, and after the disable, the external set
  // position is taken for exactly one more cycle.
  const bool position_only = !full && (final_cycle_ || was_moving_);
  if (full) {
    if (std::isfinite(in.ExtSetPos) && std::isfinite(in.ExtSetVelo) &&
        std::isfinite(in.ExtSetAcc)) {
      const double d = delay_;
      const KinematicState packet{in.ExtSetPos + in.ExtSetVelo * d + 0.5 * in.ExtSetAcc * d * d,
                                  in.ExtSetVelo + in.ExtSetAcc * d, in.ExtSetAcc};
      // Finite but out of range (fuzz finding K2): not taken, like a NaN packet.
      step.too_large = !within_magnitude(packet.p) || !within_magnitude(packet.a) ||
                       !(std::abs(packet.v) <= max_velocity_);
      if (!step.too_large) state_ = packet;
    } else {
      step.not_finite = true;
    }
  } else if (position_only && std::isfinite(in.ExtSetPos)) {
    step.too_large = !within_magnitude(in.ExtSetPos);
    if (!step.too_large) state_ = KinematicState{in.ExtSetPos, 0.0, 0.0};
  } else {
    step.not_finite = position_only;  // position_only with a non-finite ExtSetPos
  }
  if (step.not_finite || step.too_large) {
    const double t = cycle_time;
    state_ = KinematicState{state_.p + state_.v * t + 0.5 * state_.a * t * t,
                            state_.v + state_.a * t, state_.a};
  } else if (!full) {
    // Not taken (or the position only): the set position holds, nothing moves.
    state_.v = 0.0;
    state_.a = 0.0;
  }
  was_moving_ = enabled_ && moving;
  if (final_cycle_) {
    final_cycle_ = false;
    step.finished = true;
  }
  step.state = state_;
  return step;
}

}  // namespace nc::detail
