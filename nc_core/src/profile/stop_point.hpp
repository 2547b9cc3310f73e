// Where the shortest stop from a state ends, with its derivative along a push (internal): the
// function whose root plan_position finds. Same closed form as the stop's pieces
// (velocity_change.cpp, stop_change), written once for plain numbers and once for jets (value,
// first and second derivative), so that the root can be found with a second-order (Halley-type)
// method.
#pragma once

#include <cmath>

#include "profile/kinematics.hpp"
#include "profile/velocity_change.hpp"

namespace nc::detail {

// A number with its first and second derivative with respect to one parameter.
struct Jet {
  double x = 0.0;
  double d = 0.0;
  double dd = 0.0;
};
inline Jet operator+(Jet a, Jet b) noexcept {
  return {a.x + b.x, a.d + b.d, a.dd + b.dd};
}
inline Jet operator-(Jet a, Jet b) noexcept {
  return {a.x - b.x, a.d - b.d, a.dd - b.dd};
}
inline Jet operator*(Jet a, Jet b) noexcept {
  return {a.x * b.x, a.d * b.x + a.x * b.d, a.dd * b.x + 2.0 * a.d * b.d + a.x * b.dd};
}
inline Jet operator*(double a, Jet b) noexcept {
  return {a * b.x, a * b.d, a * b.dd};
}
inline Jet operator/(Jet a, double b) noexcept {
  return {a.x / b, a.d / b, a.dd / b};
}
inline Jet operator/(Jet a, Jet b) noexcept {
  const double x = a.x / b.x;
  const double d = (a.d - x * b.d) / b.x;
  return {x, d, (a.dd - 2.0 * d * b.d - x * b.dd) / b.x};
}
inline Jet sqrt(Jet a) noexcept {
  const double r = std::sqrt(a.x);
  if (!(r > 0.0)) return {r, 0.0, 0.0};
  const double d = 0.5 * a.d / r;
  return {r, d, (0.5 * a.dd - d * d) / r};
}
inline double value(Jet a) noexcept {
  return a.x;
}
inline double value(double a) noexcept {
  return a;
}
inline Jet constant(Jet, double c) noexcept {
  return {c, 0.0, 0.0};
}
inline double constant(double, double c) noexcept {
  return c;
}

inline constexpr double kStopRel = kDecisionTolerance;

// Distance of the shortest stop from (v, a) (stop_change's pieces, integrated).
template <class T>
T stop_distance_of(T v, T a, const Bounds& b) noexcept {
  using std::sqrt;
  const double jerk = b.j;
  const double am = b.am;
  const double s = natural_velocity(value(v), value(a), jerk) > 0.0 ? -1.0 : 1.0;
  v = s * v;
  a = s * a;
  const double av = value(a), vv = value(v);
  const double k_tol = kStopRel * (av * av + 2.0 * jerk * std::abs(vv));
  T p = constant(v, 0.0);
  if (av > am * (1.0 + kStopRel)) {
    const T t = (a - constant(a, am)) / jerk;
    p = t * (v + t * (0.5 * a - (jerk / 6.0) * t));
    v = v + t * (a - (0.5 * jerk) * t);
  } else {
    const T meet2 = 0.5 * (a * a - (2.0 * jerk) * v);
    if (value(meet2) <= k_tol) {
      // stop_change's landing ramp: t = -2v/a with the adjusted jerk covers t v / 3.
      if (av < 0.0 && vv > 0.0) return s * ((-2.0 / 3.0) * (v * v / a));
      const T t = constant(a, 0.0) - a / jerk;
      return s * (t * (v + t * (0.5 * a + (jerk / 6.0) * t)));
    }
    const T a_meet = sqrt(meet2);
    if (value(a_meet) <= am) {
      const T t1 = (a_meet - a) / jerk;
      if (value(t1) > 0.0) {
        p = t1 * (v + t1 * (0.5 * a + (jerk / 6.0) * t1));
        v = v + t1 * (a + (0.5 * jerk) * t1);
      }
      const T t2 = a_meet / jerk;
      return s * (p + t2 * (v + t2 * (0.5 * a_meet - (jerk / 6.0) * t2)));
    }
    const T t = (constant(a, am) - a) / jerk;
    if (value(t) > 0.0) {
      p = t * (v + t * (0.5 * a + (jerk / 6.0) * t));
      v = v + t * (a + (0.5 * jerk) * t);
    }
  }
  const T t_hold = (constant(v, -am * am / (2.0 * jerk)) - v) / am;
  if (value(t_hold) > 0.0) {
    p = p + t_hold * (v + (0.5 * am) * t_hold);
    v = v + am * t_hold;
  }
  const double t3 = am / jerk;
  return s * (p + t3 * (v + constant(v, t3 * (0.5 * am - (jerk / 6.0) * t3))));
}

}  // namespace nc::detail
