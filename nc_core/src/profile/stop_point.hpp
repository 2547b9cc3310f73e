// Where the shortest stop from a state ends, with its derivative along a push (internal): the
// function whose root plan_position finds. Same closed form as the stop's pieces
// (velocity_change.cpp, stop_change), written once for plain numbers and once for jets (value,
// first and second derivative), so that the root can be found with a second-order (Halley-type)
// method; stop_point_along (below) writes the derivatives out for the common stop shapes and
// takes the jets for the others. stop_distance_of and stop_point_along compute the values by the
// same operations as the pieces (bit for bit); only the derivatives use reciprocals, since they
// steer the root finder and never enter a profile. The closed forms at the end (stop_point_rise,
// stop_distance_closed; the quartic of the rise-hold-ramp shape) are within rounding of those
// values, for the switch search and the push scan (issue 17).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

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
inline Jet operator/(Jet a, Jet b) noexcept {
  const double x = a.x / b.x;
  const double inv = 1.0 / b.x;
  const double d = (a.d - x * b.d) * inv;
  return {x, d, (a.dd - 2.0 * d * b.d - x * b.dd) * inv};
}
inline Jet sqrt(Jet a) noexcept {
  const double r = std::sqrt(a.x);
  if (!(r > 0.0)) return {r, 0.0, 0.0};
  const double inv = 1.0 / r;
  const double d = 0.5 * a.d * inv;
  return {r, d, (0.5 * a.dd - d * d) * inv};
}
// a / b where 1 / b is known: the value divided (as the pieces compute it), derivatives scaled.
inline double over(double a, double b, double) noexcept {
  return a / b;
}
inline Jet over(Jet a, double b, double inv_b) noexcept {
  return {a.x / b, a.d * inv_b, a.dd * inv_b};
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

// The constants of the shortest stop under one pair (A-, J), computed once per plan by the same
// operations the stop's closed form uses, so that caching them changes no bit.
struct StopBounds {
  explicit StopBounds(const Bounds& b) noexcept
      : am(b.am),
        jerk(b.j),
        inv_jerk(1.0 / b.j),
        inv_am(1.0 / b.am),
        jerk6(b.j / 6.0),
        am_limit(b.am * (1.0 + kStopRel)),
        v_curve(-b.am * b.am / (2.0 * b.j)),
        t3(b.am / b.j),
        tail(t3 * (0.5 * b.am - (b.j / 6.0) * t3)) {}
  double am;
  double jerk;
  double inv_jerk;
  double inv_am;
  double jerk6;     // J / 6
  double am_limit;  // A- (1 + kStopRel): above it a is first brought back to A-
  double v_curve;   // -A-^2 / 2J: start velocity of the final ramp from A-
  double t3;        // A- / J: length of that ramp
  double tail;      // its distance beyond its start velocity's share: t3 (A-/2 - J t3 / 6)
};

// Distance of the shortest stop from (v, a) (stop_change's pieces, integrated).
template <class T>
T stop_distance_of(T v, T a, const StopBounds& b) noexcept {
  using std::sqrt;
  const double jerk = b.jerk;
  const double am = b.am;
  const double s = natural_velocity(value(v), value(a), jerk) > 0.0 ? -1.0 : 1.0;
  v = s * v;
  a = s * a;
  const double av = value(a), vv = value(v);
  const double k_tol = kStopRel * (av * av + 2.0 * jerk * std::abs(vv));
  T p = constant(v, 0.0);
  if (av > b.am_limit) {
    const T t = over(a - constant(a, am), jerk, b.inv_jerk);
    p = t * (v + t * (0.5 * a - b.jerk6 * t));
    v = v + t * (a - (0.5 * jerk) * t);
  } else {
    const T meet2 = 0.5 * (a * a - (2.0 * jerk) * v);
    if (value(meet2) <= k_tol) {
      // stop_change's landing ramp: t = -2v/a with the adjusted jerk covers t v / 3.
      if (av < 0.0 && vv > 0.0) return s * ((-2.0 / 3.0) * (v * v / a));
      const T t = constant(a, 0.0) - over(a, jerk, b.inv_jerk);
      return s * (t * (v + t * (0.5 * a + b.jerk6 * t)));
    }
    const T a_meet = sqrt(meet2);
    if (value(a_meet) <= am) {
      const T t1 = over(a_meet - a, jerk, b.inv_jerk);
      if (value(t1) > 0.0) {
        p = t1 * (v + t1 * (0.5 * a + b.jerk6 * t1));
        v = v + t1 * (a + (0.5 * jerk) * t1);
      }
      const T t2 = over(a_meet, jerk, b.inv_jerk);
      return s * (p + t2 * (v + t2 * (0.5 * a_meet - b.jerk6 * t2)));
    }
    const T t = over(constant(a, am) - a, jerk, b.inv_jerk);
    if (value(t) > 0.0) {
      p = t * (v + t * (0.5 * a + b.jerk6 * t));
      v = v + t * (a + (0.5 * jerk) * t);
    }
  }
  const T t_hold = over(constant(v, b.v_curve) - v, am, b.inv_am);
  if (value(t_hold) > 0.0) {
    p = p + t_hold * (v + (0.5 * am) * t_hold);
    v = v + am * t_hold;
  }
  return s * (p + b.t3 * (v + constant(v, b.tail)));
}

// The stop point S = p + D (D = stop_distance_of(v, a)) along a push of jerk g from (p, v, a)
// (p' = v, v' = a, a' = g): D and the first and second derivative of S, the function and
// derivatives plan_position's root finder needs. For the two common shapes of the stop (a rise to
// a_meet <= A- and the final ramp; a rise to A-, a hold and the final ramp) the derivatives are
// written out instead of taken by jet arithmetic (issue 17: 250 instructions per evaluation);
// the other shapes take stop_distance_of<Jet>. D is stop_distance_of's value by the same
// operations (bit for bit).
//
// In the stop's mirrored frame (v, a -> sv, sa; g -> sg) a push at +J is the stop's own rise,
// along which S stays put: D_v a + D_a J = -v. So S' = v + D' = -s (J - sg) D_a and
// S'' = -s (J - sg) (D_va sa + D_aa sg), free of the cancellation between p' and D'. With
// m = a_meet = sqrt((a^2 - 2Jv) / 2) (mirrored values):
//   rise and ramp: D = (a m^2 - m^3 - a^3 / 6) / J^2, so D_a = (m - a)(m - a/2) / J^2,
//     D_va = (3a / 4m - 1) / J, D_aa = (2a - 3m/2 - 3a^2 / 4m) / J^2;
//   rise to A- for t = (A- - a) / J to v1, hold, ramp: D = D_rise + (v_curve^2 - v1^2) / 2A- +
//     const, so D_a = t (t/2 - v1 / A-), D_va = -t / A-, D_aa = (v1 - J t^2) / (A- J). Without
//     the rise (a at A- within rounding) D depends on v alone: S' = s v (A- - a) / A-,
//     S'' = s (a (A- - a) - v sg) / A-.
//
// On the second shape with a rise (t > 0) S is a polynomial of degree 4 in the push's time (p is
// cubic, t linear, v1 quadratic; D is quadratic in v1 and cubic in t): with t' = -sg / J,
// v1' = a (J - sg) / J, v1'' = sg (J - sg) / J, S''' = lag (t'^2 - 2 t' v1' / A- - t v1'' / A-)
// and S'''' = -3 lag t' v1'' / A- (0 on a hold, where S is quadratic). `quartic` marks those
// points: there the four derivatives give S exactly wherever the stop keeps that shape
// (stop_has_hold_shape), and the root finder solves that polynomial instead of evaluating S again.
struct StopAlong {
  double distance;     // D
  double d;            // S'
  double dd;           // S''
  double d3 = 0.0;     // S''' (only where `quartic`)
  double d4 = 0.0;     // S'''' (only where `quartic`)
  double frame = 0.0;  // the stop's mirror sign s (only where `quartic`)
  bool quartic = false;
};
inline StopAlong stop_point_along(double v0, double a0, double g, const StopBounds& b) noexcept {
  const double jerk = b.jerk;
  const double am = b.am;
  const double s = natural_velocity(v0, a0, jerk) > 0.0 ? -1.0 : 1.0;
  const double v = s * v0;
  const double a = s * a0;
  const double k_tol = kStopRel * (a * a + 2.0 * jerk * std::abs(v));
  if (!(a > b.am_limit)) {
    const double meet2 = 0.5 * (a * a - (2.0 * jerk) * v);
    if (meet2 > k_tol) {
      const double m = std::sqrt(meet2);
      const double gs = s * g;              // a' in the mirrored frame
      const double lag = -s * (jerk - gs);  // S' = lag D_a, S'' = lag (D_va a + D_aa gs)
      const double ij = b.inv_jerk;
      if (m <= am) {
        const double t1 = (m - a) / jerk;
        if (t1 > 0.0) {
          const double p = t1 * (v + t1 * (0.5 * a + b.jerk6 * t1));
          const double v1 = v + t1 * (a + (0.5 * jerk) * t1);
          const double t2 = m / jerk;
          const double x = s * (p + t2 * (v1 + t2 * (0.5 * m - b.jerk6 * t2)));
          const double am_ratio = 0.75 * a / m;
          const double d_a = (m - a) * (m - 0.5 * a) * (ij * ij);
          const double d_va = (am_ratio - 1.0) * ij;
          const double d_aa = (2.0 * a - 1.5 * m - am_ratio * a) * (ij * ij);
          return {x, lag * d_a, lag * (d_va * a + d_aa * gs)};
        }
      } else {
        const double t = (am - a) / jerk;
        double p = 0.0;
        double v1 = v;
        if (t > 0.0) {
          p = t * (v + t * (0.5 * a + b.jerk6 * t));
          v1 = v + t * (a + (0.5 * jerk) * t);
        }
        const double t_hold = (b.v_curve - v1) / am;
        if (t_hold > 0.0) {
          const double x =
              s * (p + t_hold * (v1 + (0.5 * am) * t_hold) + b.t3 * (v1 + am * t_hold + b.tail));
          if (!(t > 0.0)) {
            // No rise (a within rounding above A-): D depends on v alone, D' = -v a / A-.
            return {x, s * v * (am - a) * b.inv_am, s * (a * (am - a) - v * gs) * b.inv_am};
          }
          const double d_a = t * (0.5 * t - v1 * b.inv_am);
          const double d_va = -t * b.inv_am;
          const double d_aa = (v1 - jerk * t * t) * (b.inv_am * ij);
          const double t_d = -gs * ij;                                                // t'
          const double v1_d = a * (jerk - gs) * ij;                                   // v1'
          const double v1_dd = gs * (jerk - gs) * ij;                                 // v1''
          const double d_a2 = t_d * t_d - (2.0 * t_d * v1_d + t * v1_dd) * b.inv_am;  // (D_a)''
          const double d_a3 = -3.0 * t_d * v1_dd * b.inv_am;                          // (D_a)'''
          return {x, lag * d_a, lag * (d_va * a + d_aa * gs), lag * d_a2, lag * d_a3, s, true};
        }
      }
    }
  }
  const Jet d = stop_distance_of(Jet{v0, a0, g}, Jet{a0, g, 0.0}, b);
  return {d.x, v0 + d.d, a0 + d.dd};
}

// The stop point along a push where the stop is a rise to a_meet = m <= A- and the final ramp (the
// first shape above), in closed form: D = s (m^2 (a - m) - a^3 / 6) / J^2 (mirrored a), S' and S''
// as stop_point_along's. For plan_position's switch search on that shape (issue 17): about a third
// of stop_point_along's instructions, without its branches or piece integration; D differs from the
// integrated pieces by rounding only. In two parts: RisePoint::at decides the shape (false where
// the stop has another one: the same decisions as stop_point_along's) and gives D; slopes() S' and
// S'', which the search only needs where D does not settle the root (issue 17: their division
// and products were computed at every accepted point too).
struct RisePoint {
  double s = 0.0;         // the stop's mirror sign
  double a = 0.0;         // the mirrored acceleration
  double m = 0.0;         // a_meet
  double distance = 0.0;  // D
  bool at(double v0, double a0, const StopBounds& b) noexcept {
    const double jerk = b.jerk;
    s = natural_velocity(v0, a0, jerk) > 0.0 ? -1.0 : 1.0;
    const double v = s * v0;
    a = s * a0;
    if (a > b.am_limit) return false;
    const double meet2 = 0.5 * (a * a - (2.0 * jerk) * v);
    if (!(meet2 > kStopRel * (a * a + 2.0 * jerk * std::abs(v)))) return false;
    m = std::sqrt(meet2);
    if (!(m <= b.am && m > a)) return false;
    distance = s * ((meet2 * (a - m) - (1.0 / 6.0) * (a * a * a)) * (b.inv_jerk * b.inv_jerk));
    return true;
  }
  // S' and S'' along a push of jerk g (into out.d, out.dd).
  void slopes(double g, const StopBounds& b, StopAlong& out) const noexcept {
    const double ij = b.inv_jerk;
    const double ij2 = ij * ij;
    const double gs = s * g;
    const double lag = -s * (b.jerk - gs);
    const double am_ratio = 0.75 * a / m;
    const double d_a = (m - a) * (m - 0.5 * a) * ij2;
    const double d_va = (am_ratio - 1.0) * ij;
    const double d_aa = (2.0 * a - 1.5 * m - am_ratio * a) * ij2;
    out.d = lag * d_a;
    out.dd = lag * (d_va * a + d_aa * gs);
  }
};
// Both parts at once: false (out untouched) where the stop has another shape.
inline bool stop_point_rise(double v0, double a0, double g, const StopBounds& b,
                            StopAlong& out) noexcept {
  RisePoint r;
  if (!r.at(v0, a0, b)) return false;
  out.distance = r.distance;
  r.slopes(g, b, out);
  return true;
}

// stop_distance_of for plan_position's push scan (the stop points at the push's piece ends): the
// rise-and-ramp shape in closed form (stop_point_rise's D), the other shapes by stop_distance_of.
// The closed form is within rounding of the integrated pieces; these points only bracket the switch
// and start its search (and give the cruise's length, where the stop from (V, 0) is the shape).
inline double stop_distance_closed(double v0, double a0, const StopBounds& b) noexcept {
  const double s = natural_velocity(v0, a0, b.jerk) > 0.0 ? -1.0 : 1.0;
  const double v = s * v0;
  const double a = s * a0;
  if (!(a > b.am_limit)) {
    const double meet2 = 0.5 * (a * a - (2.0 * b.jerk) * v);
    if (meet2 > kStopRel * (a * a + 2.0 * b.jerk * std::abs(v))) {
      const double m = std::sqrt(meet2);
      if (m <= b.am && m > a) {
        return s * ((meet2 * (a - m) - (1.0 / 6.0) * (a * a * a)) * (b.inv_jerk * b.inv_jerk));
      }
    }
  }
  return stop_distance_of(v0, a0, b);
}

// An upper bound of cbrt(x) for x > 0, about 0.1 % above it: fdlibm's first guess (the high
// word's exponent divided by three, 5 bits) and one Newton step, which lands at or above the root
// of the convex y^3 - x from either side (the mean of y, y and x / y^2 is at least their geometric
// mean). For switch_on_rise's start: libm's cbrt takes about 58 instructions.
inline double cbrt_above(double x) noexcept {
  const auto hi = static_cast<std::uint32_t>(std::bit_cast<std::uint64_t>(x) >> 32U);
  const double y = std::bit_cast<double>(static_cast<std::uint64_t>(hi / 3U + 715094163U) << 32U);
  return (2.0 * y + x / (y * y)) * (1.0 / 3.0);
}

// The switch on a push piece in closed form where the stop from a reference point of the piece
// (its end, or its start) is a rise to a_meet = m and the final ramp with the motion going on
// forwards (frame s = -1, the shape of stop_point_rise), for plan_position's switch search to start
// from (issue 17: the power law put its first point 5-50 % off on jerk pieces, and every further
// evaluation of the stop point is a chain of two square roots and two divisions on the plan's
// critical path). Along such a piece S = p + D has a closed form in one variable (from
// S' = lag D_a, stop_point_along):
//  - a hold at a = A > 0: m^2 = (A^2 + 2 J v) / 2 grows linearly with time and
//    S = K + (m (m + A))^2 / (2 J^2 A). At the root m (m + A) = sqrt(u^2 - 2 J^2 A f) with
//    u = m (m + A) at the reference: a quadratic in m, then v and the time.
//  - a rise at +J: c = J v - a^2 / 2 stays constant, m = sqrt(a^2 + c), and with
//    E = (a + m) / sqrt|c| (a = sqrt|c| sinh w for c > 0, cosh w for c < 0; E = e^w),
//    S = K + |c|^(3/2) / (4 J^2) (E^3 +- 4 E - 1 / E). The root's E solves
//    E^4 +- 4 E^2 - r E - 1 = 0: Halley steps from an upper bound near the root (below).
// K is set by the stop point at the reference, at time t_ref of the piece from its start `s`
// (jerk g), with f = S(ref) - goal (>= 0 at the end, < 0 at the start); `at_end`: the reference is
// the piece's end, whose E bounds the root's. Returns the time from the piece's start, or NaN
// where the reference has another shape or frame. Only a starting point: the search evaluates S
// there as from any other; where the shape changes between the root and the reference the point
// is merely off.
inline double switch_from(const KinematicState& s, double t_ref, double g, double f, bool at_end,
                          const StopBounds& b) noexcept {
  const double jerk = b.jerk;
  const double a_r = s.a + g * t_ref;
  const double v_r = s.v + t_ref * (s.a + (0.5 * g) * t_ref);
  if (!(natural_velocity(v_r, a_r, jerk) > 0.0)) return NAN;
  if (g == jerk) {
    const double c = jerk * v_r - 0.5 * a_r * a_r;
    const double m = std::sqrt(a_r * a_r + c);
    if (!(m <= b.am && a_r + m > 0.0)) return NAN;
    const double pm4 = c > 0.0 ? 4.0 : -4.0;
    const double sc = std::sqrt(std::abs(c));
    const double scale = std::abs(c) * sc * (0.25 * b.inv_jerk * b.inv_jerk);
    const double e_ref = (a_r + m) / sc;
    const double r = e_ref * (e_ref * e_ref + pm4) - 1.0 / e_ref - f / scale;
    // From the start: where m reaches A- (a = sqrt(A-^2 - c)) the stop leaves the shape; a root
    // beyond that point (S there below the goal) is no start, and one before it lies below its E.
    double e_cap = e_ref;
    if (!at_end) {
      e_cap = (std::sqrt(b.am * b.am - c) + b.am) / sc;
      if (!(e_cap * (e_cap * e_cap + pm4) - 1.0 / e_cap >= r)) return NAN;
    }
    // Start at an upper bound near the root, not at the end's E, which can be hundreds of times
    // the root's (from there 86 of the benchmark set's 723 starts took 10 steps or more, 47 of them
    // stopped at the cap short of the root; from the bound 3.2 steps on average, at most 6). For c
    // > 0 the root lies below the root of 4E^2 - rE - 1 (h is that plus E^4) and below cbrt(r)
    // where that is at least 1/2 (there E (E^3 - r) + 4E^2 - 1 >= 0). For c < 0 (E >= 1, where S
    // grows with E) S at E = sqrt(4 + (r + 1) / 2) >= 2 is at least the root's, and as E^3 = r + 4E
    // + 1/E with the right side growing in E, cbrt(r + 4u + 1/u) bounds the root again from that
    // bound u. h is convex above the root (everywhere for c > 0, for E >= sqrt(2/3) for c < 0), so
    // the steps fall monotonically onto it.
    double e = 0.0;
    if (c > 0.0) {
      e = std::min(e_cap, 0.125 * (r + std::sqrt(r * r + 16.0)));
      if (r >= 0.125) e = std::min(e, cbrt_above(r));
    } else {
      const double u = std::min(e_cap, std::sqrt(4.0 + 0.5 * std::max(r + 1.0, 0.0)));
      const double u3 = r + 4.0 * u + 1.0 / u;
      e = u3 > 0.0 ? std::min(u, cbrt_above(u3)) : u;
    }
    for (int k = 0; k < 12; ++k) {
      const double e2 = e * e;
      const double h = e * (e * (e2 + pm4) - r) - 1.0;
      const double dh = e * (4.0 * e2 + 2.0 * pm4) - r;
      const double ddh = 12.0 * e2 + 2.0 * pm4;
      const double step = h * dh / (dh * dh - 0.5 * h * ddh);
      e -= step;
      if (!(std::abs(step) > 1e-15 * e)) break;
    }
    // r keeps about 1e-16 of the terms at the reference; that moves the root by its share of
    // h'(E) / E = 3E^3 +- 4E + 1/E (at the root). Where the root's E could be off by more than
    // 1e-8 of itself (a root far below the end of a long piece), the point is no start.
    const double terms_ref = e_ref * (e_ref * e_ref + 4.0) + 1.0 / e_ref + std::abs(f) / scale;
    if (!(e * (3.0 * e * e + pm4) + 1.0 / e >= 1e-8 * terms_ref)) return NAN;
    const double a_root = 0.5 * sc * (c > 0.0 ? e - 1.0 / e : e + 1.0 / e);
    // The time is a difference of accelerations: where it keeps less than 1e-8 of them (a root
    // near the start of a long piece), the point is no start either.
    const double rise = a_root - s.a;
    if (!(std::abs(rise) >= 1e-8 * (std::abs(a_root) + std::abs(s.a) + sc))) return NAN;
    return rise / jerk;
  }
  if (g == 0.0 && s.a > 0.0) {
    const double aa = s.a;
    const double m = std::sqrt(0.5 * (aa * aa + 2.0 * jerk * v_r));
    if (!(m <= b.am)) return NAN;
    const double u = m * (m + aa);
    const double q2 = u * u - 2.0 * (jerk * jerk) * aa * f;
    // The difference keeps about 1e-16 of u^2: where the root's q^2 is below 1e-8 of it (a root
    // far below the end of a long hold), the point is no start (fuzz: on a hold of 8e16 s the
    // difference of two values near 1.5e35 put the start 2e10 times beyond a switch at 0.074 s,
    // and the search from there ended 3 times too late). From the start (f < 0) it is a sum.
    if (!(q2 >= 1e-8 * (u * u))) return NAN;
    // From the start: a root beyond m = A- (where the stop leaves the shape) is no start.
    const double u_cap = b.am * (b.am + aa);
    if (!at_end && !(q2 <= u_cap * u_cap)) return NAN;
    const double q = std::sqrt(q2);
    const double m_root = 2.0 * q / (aa + std::sqrt(aa * aa + 4.0 * q));
    // The time is a difference of velocities, as above.
    const double v_root = (2.0 * m_root * m_root - aa * aa) / (2.0 * jerk);
    const double gain = v_root - s.v;
    if (!(std::abs(gain) >= 1e-8 * (std::abs(v_root) + std::abs(s.v) + aa * aa * b.inv_jerk)))
      return NAN;
    return gain / aa;
  }
  return NAN;
}

// switch_from with the piece's end (length t_piece) as the reference, `over` = S(end) - goal >= 0.
inline double switch_on_rise(const KinematicState& s, double t_piece, double g, double over,
                             const StopBounds& b) noexcept {
  return switch_from(s, t_piece, g, over, true, b);
}

// The switch search's first point on a piece (length t_piece) where S(start) - goal = f_start < 0
// and S(end) - goal = f_end >= 0: switch_from with the start as the reference where the stop there
// has the shape and gives a point inside the piece, else with the end (issue 17: from the end the
// root's m (m + A) or E is the difference of the end's and the excess, which cancels for a root far
// from the end, and the end may have left the shape that the start and the root still have).
inline double switch_in_piece(const KinematicState& s, double t_piece, double g, double f_start,
                              double f_end, const StopBounds& b) noexcept {
  const double x = switch_from(s, 0.0, g, f_start, false, b);
  if (x > 0.0 && x < t_piece) return x;
  return switch_from(s, t_piece, g, f_end, true, b);
}

// Whether the shortest stop from (v0, a0) has the shape on which stop_point_along marks S as
// `quartic`, in the stop's frame `s`: a rise to A- (t > 0), then a hold (v1 below the final
// ramp's start). That implies stop_point_along's other decisions for it (a below A-, meet2 > A-^2
// far above its tolerance), except within rounding of the boundary to the shape without a hold,
// where both shapes give the same S.
inline bool stop_has_hold_shape(double v0, double a0, double s, const StopBounds& b) noexcept {
  if ((natural_velocity(v0, a0, b.jerk) > 0.0 ? -1.0 : 1.0) != s) return false;
  const double v = s * v0;
  const double a = s * a0;
  const double t = (b.am - a) * b.inv_jerk;
  return t > 0.0 && v + t * (a + (0.5 * b.jerk) * t) < b.v_curve;
}
}  // namespace nc::detail
