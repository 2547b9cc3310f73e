// A slow, obviously-correct reference for rest-to-rest moves (tests only).
//
// From rest to rest the time-optimal jerk-limited motion is one velocity peak vp: raise v from 0
// to vp with the acceleration limit A+ (v grows), hold vp if vp = V, lower it to 0 with A- (v
// shrinks) — seed 000 §2.1, the 7 phases. Each ramp between two velocities at a = 0 is elementary:
// trapezoidal acceleration when the velocity change dv ≥ A²/J (time dv/A + A/J), otherwise
// triangular (time 2·sqrt(dv/J)); by symmetry it covers dv·time/2 from rest. The distance grows
// with vp, so bisection on vp (200 halvings) finds the peak for a short move. No cleverness.
#pragma once

#include <array>
#include <cmath>

#include "nc_core/profile.hpp"

namespace reference {

// Shortest time to change the velocity by dv >= 0 from a = 0 to a = 0 with |a| <= a_max.
inline double ramp_time(double dv, double a_max, double jerk) {
  if (dv <= 0.0) return 0.0;
  if (dv * jerk >= a_max * a_max) return dv / a_max + a_max / jerk;
  return 2.0 * std::sqrt(dv / jerk);
}

struct RestToRest {
  double duration = 0.0;
  double peak_velocity = 0.0;  // vp (magnitude)
  double cruise_time = 0.0;    // time at V (0 when V is not reached)
};

// Optimal rest-to-rest duration over |distance| (direction does not matter by symmetry).
inline RestToRest rest_to_rest(double distance, const nc::Limits& l) {
  const double d = std::fabs(distance);
  RestToRest r;
  if (d == 0.0) return r;
  auto ramps = [&](double vp) {
    return ramp_time(vp, l.acceleration, l.jerk) + ramp_time(vp, l.deceleration, l.jerk);
  };
  auto covered = [&](double vp) { return 0.5 * vp * ramps(vp); };
  const double v = l.velocity;
  if (covered(v) <= d) {
    r.peak_velocity = v;
    r.cruise_time = (d - covered(v)) / v;
    r.duration = ramps(v) + r.cruise_time;
    return r;
  }
  double lo = 0.0;
  double hi = v;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (covered(mid) < d) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  r.peak_velocity = 0.5 * (lo + hi);
  r.duration = ramps(r.peak_velocity);
  return r;
}

// The reference's phases as (duration, jerk) pieces, in the direction of `distance`: lets a test
// integrate them and see that the reference is a valid motion that really ends at the target.
struct Piece {
  double duration = 0.0;
  double jerk = 0.0;
};

inline std::array<Piece, 7> rest_to_rest_pieces(double distance, const nc::Limits& l) {
  const RestToRest r = rest_to_rest(distance, l);
  const double sign = distance < 0.0 ? -1.0 : 1.0;
  const double vp = r.peak_velocity;
  const double J = l.jerk;
  // One ramp through the velocity change vp with limit a_max: (jerk time, hold time).
  auto ramp = [&](double a_max) {
    if (vp * J >= a_max * a_max) return std::array<double, 2>{a_max / J, vp / a_max - a_max / J};
    return std::array<double, 2>{std::sqrt(vp / J), 0.0};
  };
  const auto up = ramp(l.acceleration);
  const auto down = ramp(l.deceleration);
  return {Piece{up[0], sign * J},    Piece{up[1], 0.0},         Piece{up[0], -sign * J},
          Piece{r.cruise_time, 0.0}, Piece{down[0], -sign * J}, Piece{down[1], 0.0},
          Piece{down[0], sign * J}};
}

// From (v0, 0) to (distance, v_end, 0) with v0, v_end >= 0, through one velocity extreme vp with
// a = 0 there and v >= 0 throughout: a peak vp >= max(v0, v_end) (|v| grows to it under A+,
// shrinks after it under A-, held if vp = V) or a trough 0 <= vp <= min(v0, v_end) (A- down, A+
// up). Each ramp is elementary and symmetric, so it covers its mean velocity times its time; the
// distance grows with vp, so bisection on vp (200 halvings) finds it. Returns NaN when the target
// needs v < 0 on the way (not covered by this reference).
inline double through_extreme(double v0, double v_end, double distance, const nc::Limits& l) {
  const double J = l.jerk;
  auto leg = [&](double va, double vb, bool grows, double& time) {
    time = ramp_time(std::fabs(vb - va), grows ? l.acceleration : l.deceleration, J);
    return 0.5 * (va + vb) * time;
  };
  // Distance and duration through the extreme vp (peak when vp >= both ends).
  auto through = [&](double vp, double& time) {
    double t1 = 0.0;
    double t2 = 0.0;
    const bool peak = vp >= std::max(v0, v_end);
    const double d = leg(v0, vp, peak, t1) + leg(vp, v_end, !peak, t2);
    time = t1 + t2;
    return d;
  };
  double time = 0.0;
  const double direct = through(std::max(v0, v_end), time);
  double lo;
  double hi;
  if (distance >= direct) {
    const double at_v = through(l.velocity, time);
    if (at_v <= distance) return time + (distance - at_v) / l.velocity;
    lo = std::max(v0, v_end);
    hi = l.velocity;
  } else {
    if (through(0.0, time) > distance) return NAN;
    lo = 0.0;
    hi = std::min(v0, v_end);
  }
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (through(mid, time) < distance) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  through(0.5 * (lo + hi), time);
  return time;
}

// The elementary shortest stop from (v, 0) with deceleration A and jerk J: a ramp through |v|.
inline double stop_time_from_constant_velocity(double v, double deceleration, double jerk) {
  return ramp_time(std::fabs(v), deceleration, jerk);
}

}  // namespace reference
