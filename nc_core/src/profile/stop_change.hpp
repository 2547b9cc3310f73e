// The stop (a velocity change to v1 = 0) in closed form, for any sink of pieces (internal):
// velocity_change's stop, and plan_position's stop written straight into the profile's anchored
// tail (issue 17: without a piece array between them). A sink has put(const Piece&).
#pragma once

#include <algorithm>
#include <cmath>

#include "profile/kinematics.hpp"
#include "profile/velocity_change.hpp"

namespace nc::detail {

// The stop (v1 = 0) in closed form: no bound changes at v = 0 matter (a stop never crosses
// v = 0 with a towards the bound that grows), so it is rise / hold at A- / fall, after bringing a
// back under A- if needed.
template <class Sink>
int stop_change(double v, double a, const Bounds& b, Sink& out) noexcept {
  const double jerk = b.j;
  const double am = b.am;
  const double s = natural_velocity(v, a, jerk) > 0.0 ? -1.0 : 1.0;  // mirror to an upward stop
  v *= s;
  a *= s;
  const double k_tol = kDecisionTolerance * (a * a + 2.0 * jerk * std::abs(v));
  int n = 0;
  auto put = [&](double t, double j, double a_end, double v_end) {
    if (t > 0.0) {
      out.put(Piece{t, s * j, s * a_end, s * v_end});
      ++n;
    }
  };
  // The acceleration the hold at A- has: A- after a ramp onto it; a start within
  // kDecisionTolerance above A- is taken as at it and held as it is, so the hold's time is taken
  // at that value, else a long hold drifts past v = 0 (fuzz finding P22: 1.6e-15 above A- for
  // 1.8e7 s crossed v = 0 by 1.4e-11 still at A-, twice the A+ beyond; P7 in the walk).
  double held = am;
  if (a > am * (1.0 + kDecisionTolerance)) {
    const double t = (a - am) / jerk;
    put(t, -jerk, am, NAN);
    v += t * (a - 0.5 * jerk * t);
    a = am;
  } else {
    const double meet2 = 0.5 * (a * a - 2.0 * jerk * v);
    if (meet2 <= k_tol) {
      // On the final curve already (v_nat = 0 within rounding): a rises to 0 exactly at v = 0.
      // A tiny forced overshoot (a < 0 < v, v_nat < 0) is absorbed by a jerk above J by at most
      // ~4 kDecisionTolerance, so that the ramp lands exactly: on it |v_nat| / v stays constant, so
      // every state sampled on the stop takes this same branch (see upward() in
      // velocity_change.cpp).
      if (a < 0.0 && v > 0.0) {
        const double t = -2.0 * v / a;
        put(t, -a / t, 0.0, 0.0);
      } else {
        put(-a / jerk, jerk, 0.0, 0.0);
      }
      return n;
    }
    const double a_meet = std::sqrt(meet2);
    // The last ramp starts on the final curve v = -a^2 / 2J: its start velocity is set from that
    // (rounding of its own size) rather than integrated (rounding of the start's speed), so a
    // state sampled on it re-plans to the same ramp, not to a reversal of the rounding's size.
    if (a_meet <= am) {
      put((a_meet - a) / jerk, jerk, a_meet, -0.5 * a_meet * a_meet / jerk);
      put(a_meet / jerk, -jerk, 0.0, 0.0);
      return n;
    }
    const double t = (am - a) / jerk;
    put(t, jerk, am, NAN);
    if (t > 0.0) v += t * (a + 0.5 * jerk * t);
    held = std::max(a, am);
    a = am;
  }
  const double v_curve = -am * am / (2.0 * jerk);
  put((v_curve - v) / held, 0.0, am, v_curve);
  put(am / jerk, -jerk, 0.0, 0.0);
  return n;
}

}  // namespace nc::detail
