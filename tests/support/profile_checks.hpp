// Checks shared by the planner tests: structure, continuity, limits, end state and at().
//
// A Profile is a list of constant-jerk segments, so every limit can be checked exactly rather
// than by sampling: inside one segment a(t) is linear and v(t) quadratic, hence |v| peaks at the
// segment ends or where a crosses 0, and |a| peaks at the ends of the pieces on which the signs
// of v and a stay fixed (those pieces end at segment ends, at zeros of v and at the zero of a).
// The acceleration bound is path-relative (seed 000 §2.1, SPEC B2): A+ while |v| grows (v and a
// of one sign), A- while |v| shrinks. Each check returns a Finding: empty when the rule holds,
// otherwise what failed, where, by how much — cheap on success, so it runs a million times.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "nc_core/profile.hpp"

namespace profile_checks {

enum class Check {
  kOk,
  kNotOk,         // the planner refused a valid problem
  kNotFinite,     // a NaN or infinity in a segment, the duration or the final state
  kTiming,        // segment start times do not chain, negative lengths, duration mismatch
  kStart,         // the profile does not start at the given state
  kJerk,          // |j| > J
  kVelocity,      // |v| > V
  kAcceleration,  // |a| above its path-relative bound
  kContinuity,    // a segment does not start where the previous one ends
  kAt,            // at(t) disagrees with the segments
  kEndPosition,   // integrated end position not at the target
  kEndVelocity,   // integrated end velocity not the requested one
  kEndAcceleration,
  kFinalState,  // final_state() disagrees with the integrated end or the target
  kCount,
};

inline const char* check_name(Check c) {
  static constexpr std::array<const char*, static_cast<std::size_t>(Check::kCount)> kNames = {
      "ok",           "not ok",       "not finite",       "timing",     "start",
      "jerk",         "velocity",     "acceleration",     "continuity", "at()",
      "end position", "end velocity", "end acceleration", "final state"};
  return kNames[static_cast<std::size_t>(c)];
}

struct Finding {
  Check check = Check::kOk;
  std::size_t segment = 0;  // segment index where it was found
  double t = 0.0;           // time in the profile
  double value = 0.0;       // the offending value
  double bound = 0.0;       // what it had to stay within
  bool ok() const { return check == Check::kOk; }
  // How far past the bound, relative to it (for "worst excess" statistics).
  double excess() const { return bound > 0.0 ? (std::fabs(value) - bound) / bound : value; }
};

inline std::string to_string(const Finding& f) {
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s at segment %zu, t=%.17g: value %.17g, bound %.17g",
                check_name(f.check), f.segment, f.t, f.value, f.bound);
  return buf;
}

// Tolerances of the checks (relative unless named _abs).
struct Tolerance {
  double limit = 1e-9;       // excess over V, A+, A-, J
  double end = 1e-9;         // end velocity / acceleration relative to V / A, end position rel.
  double end_abs = 1e-8;     // mm, absolute part of the end position tolerance
  double continuity = 1e-9;  // jumps between segments, relative to the problem's scales
  double timing = 1e-14;     // chaining of segment start times, relative to duration()
};

// The largest errors seen, each relative to its bound or scale (for a suite's summary): how close
// the planner comes to V, A±, J (value/bound - 1, so 0 = exactly at the limit) and how far its
// integrated end is from the requested state (error/scale).
struct Extremes {
  double velocity = -1.0;
  double acceleration = -1.0;      // raw: may pass 0 by the rounding slack at v = 0 crossings
  double acceleration_net = -1.0;  // beyond the rounding slack (the checked quantity)
  double jerk = -1.0;
  double end_position = 0.0;  // |p_end - target| / max(1, |p0|, |target|)
  double end_velocity = 0.0;  // |v_end - v_target| / V
  double end_acceleration = 0.0;
  double continuity = 0.0;  // largest jump, relative to the scales
  void merge(const Extremes& o) {
    velocity = std::max(velocity, o.velocity);
    acceleration = std::max(acceleration, o.acceleration);
    acceleration_net = std::max(acceleration_net, o.acceleration_net);
    jerk = std::max(jerk, o.jerk);
    end_position = std::max(end_position, o.end_position);
    end_velocity = std::max(end_velocity, o.end_velocity);
    end_acceleration = std::max(end_acceleration, o.end_acceleration);
    continuity = std::max(continuity, o.continuity);
  }
};

// The magnitudes that make errors relative: positions, velocities, accelerations of a problem.
struct Scales {
  double p = 1.0;
  double v = 1.0;
  double a = 1.0;
  double j = 1.0;
};

inline Scales scales_for(const nc::KinematicState& start, double target, const nc::Limits& l) {
  Scales s;
  s.p = std::max({1.0, std::fabs(start.p), std::fabs(target)});
  s.v = std::max(l.velocity, std::fabs(start.v));
  s.a = std::max({l.acceleration, l.deceleration, std::fabs(start.a)});
  s.j = l.jerk;
  return s;
}

// The end-position tolerance of the issue: 1e-9·max(1, |p0|, |target|) + 1e-8 mm.
inline double end_position_tolerance(const nc::KinematicState& start, double target,
                                     const Tolerance& tol = {}) {
  return tol.end * std::max({1.0, std::fabs(start.p), std::fabs(target)}) + tol.end_abs;
}

// State dt after the start of a constant-jerk segment.
inline nc::KinematicState advance(const nc::Segment& s, double dt) {
  nc::KinematicState k;
  k.p = s.p + dt * (s.v + dt * (0.5 * s.a + dt * (s.j / 6.0)));
  k.v = s.v + dt * (s.a + dt * (0.5 * s.j));
  k.a = s.a + dt * s.j;
  return k;
}

inline nc::KinematicState state_of(const nc::Segment& s) {
  return {s.p, s.v, s.a};
}

// The state at time t computed from the segments alone (independent of Profile::at()).
inline nc::KinematicState evaluate(const nc::Profile& prof, double t) {
  const std::size_t n = prof.segment_count();
  if (n == 0 || t >= prof.duration()) return prof.final_state();
  if (t <= 0.0) return prof.start_state();
  std::size_t i = 0;
  while (i + 1 < n && prof.segment(i + 1).t0 <= t)
    ++i;
  return advance(prof.segment(i), t - prof.segment(i).t0);
}

// Path-relative acceleration bound for a sampled state. At v == 0 a sample cannot tell which way
// v moves next, so either bound is allowed there (the segment check below is exact instead).
inline double acceleration_bound(double v, double a, const nc::Limits& l) {
  if (v == 0.0 || a == 0.0) return std::max(l.acceleration, l.deceleration);
  return ((v > 0.0) == (a > 0.0)) ? l.acceleration : l.deceleration;
}

inline bool finite(const nc::KinematicState& k) {
  return std::isfinite(k.p) && std::isfinite(k.v) && std::isfinite(k.a);
}

// ok(), finite numbers, start state, start times chained, durations >= 0, duration() matches.
inline Finding check_structure(const nc::Profile& prof, const nc::KinematicState& start,
                               const Tolerance& tol = {}) {
  if (!prof.ok()) return {Check::kNotOk, 0, 0.0, static_cast<double>(prof.error()), 0.0};
  const double T = prof.duration();
  if (!std::isfinite(T) || T < 0.0) return {Check::kNotFinite, 0, 0.0, T, 0.0};
  if (!finite(prof.final_state())) return {Check::kNotFinite, 0, T, prof.final_state().p, 0.0};
  const nc::KinematicState s0 = prof.start_state();
  if (s0.p != start.p || s0.v != start.v || s0.a != start.a)
    return {Check::kStart, 0, 0.0, s0.p - start.p, 0.0};
  const std::size_t n = prof.segment_count();
  if (n > nc::Profile::kMaxSegments) return {Check::kTiming, n, 0.0, static_cast<double>(n), 0.0};
  double t_expected = 0.0;
  const double slack = tol.timing * std::max(1.0, T);
  for (std::size_t i = 0; i < n; ++i) {
    const nc::Segment& s = prof.segment(i);
    if (!std::isfinite(s.t0) || !std::isfinite(s.duration) || !std::isfinite(s.p) ||
        !std::isfinite(s.v) || !std::isfinite(s.a) || !std::isfinite(s.j))
      return {Check::kNotFinite, i, s.t0, s.duration, 0.0};
    if (s.duration < 0.0) return {Check::kTiming, i, s.t0, s.duration, 0.0};
    if (std::fabs(s.t0 - t_expected) > slack) return {Check::kTiming, i, s.t0, t_expected, slack};
    t_expected = s.t0 + s.duration;
  }
  if (n > 0) {
    const nc::Segment& s = prof.segment(0);
    if (s.p != start.p || s.v != start.v || s.a != start.a)
      return {Check::kStart, 0, 0.0, s.v - start.v, 0.0};
  }
  if (std::fabs(T - t_expected) > slack) return {Check::kTiming, n, T, t_expected, slack};
  return {};
}

// Every segment starts where the previous one ends, and the final state is where the last ends.
inline Finding check_continuity(const nc::Profile& prof, const Scales& sc,
                                const Tolerance& tol = {}, Extremes* ext = nullptr) {
  const std::size_t n = prof.segment_count();
  double p_scale = sc.p;
  for (std::size_t i = 0; i < n; ++i)
    p_scale = std::max(p_scale, std::fabs(prof.segment(i).p));
  const double tp = tol.continuity * p_scale;
  const double tv = tol.continuity * sc.v;
  const double ta = tol.continuity * sc.a;
  for (std::size_t i = 0; i < n; ++i) {
    const nc::Segment& s = prof.segment(i);
    const nc::KinematicState e = advance(s, s.duration);
    const nc::KinematicState next =
        (i + 1 < n) ? state_of(prof.segment(i + 1)) : prof.final_state();
    const double t = s.t0 + s.duration;
    if (ext != nullptr)
      ext->continuity = std::max({ext->continuity, std::fabs(e.p - next.p) / p_scale,
                                  std::fabs(e.v - next.v) / sc.v, std::fabs(e.a - next.a) / sc.a});
    if (std::fabs(e.p - next.p) > tp) return {Check::kContinuity, i, t, e.p - next.p, tp};
    if (std::fabs(e.v - next.v) > tv) return {Check::kContinuity, i, t, e.v - next.v, tv};
    if (std::fabs(e.a - next.a) > ta) return {Check::kContinuity, i, t, e.a - next.a, ta};
  }
  return {};
}

// How a start outside the limits may relax the limit check (SPEC B2: back inside as fast as the
// limits allow). Without it every point of the profile must be inside.
struct StartRelief {
  // |v| may stay up to |v0| until the profile's |v| first comes within V.
  bool over_speed = false;
  // |a| may exceed its bound by what is left of |a0| after ramping down at J: |a0| - J·t.
  bool over_acceleration = false;
};

namespace detail {
// Zeros of v + a·τ + j·τ²/2 in (0, d), written into out; returns how many.
inline int velocity_zeros(const nc::Segment& s, double d, double* out) {
  int n = 0;
  auto keep = [&](double tau) {
    if (tau > 0.0 && tau < d) out[n++] = tau;
  };
  if (s.j == 0.0) {
    if (s.a != 0.0) keep(-s.v / s.a);
    return n;
  }
  const double disc = s.a * s.a - 2.0 * s.j * s.v;
  if (disc < 0.0) return 0;
  const double r = std::sqrt(disc);
  // Numerically stable pair: q = -(a + sign(a)·r); roots q/j and 2v/q.
  const double q = -(s.a + std::copysign(r, s.a));
  if (q != 0.0) {
    keep(q / s.j);
    keep(2.0 * s.v / q);
  } else {
    keep(0.0);
  }
  return n;
}
}  // namespace detail

// |v| <= V and |a| <= its path-relative bound everywhere (exact per segment), |j| <= J.
inline Finding check_limits(const nc::Profile& prof, const nc::Limits& l, const Tolerance& tol = {},
                            const StartRelief& relief = {}, Extremes* ext = nullptr) {
  const std::size_t n = prof.segment_count();
  const double j_max = l.jerk * (1.0 + tol.limit);
  const double v_lim = l.velocity * (1.0 + tol.limit);
  const nc::KinematicState s0 = prof.start_state();
  bool speed_inside = !relief.over_speed || std::fabs(s0.v) <= v_lim;
  const double v_start_allow = std::fabs(s0.v) * (1.0 + tol.limit);
  const double dv =
      4.0 * std::numeric_limits<double>::epsilon() * std::max(l.velocity, std::fabs(s0.v));
  for (std::size_t i = 0; i < n; ++i) {
    const nc::Segment& s = prof.segment(i);
    const double d = s.duration;
    const double s_j = std::fabs(s.j);
    const double a_round =
        4.0 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(s.a), s_j * d);
    if (ext != nullptr) ext->jerk = std::max(ext->jerk, std::fabs(s.j) / l.jerk - 1.0);
    if (std::fabs(s.j) > j_max) return {Check::kJerk, i, s.t0, s.j, l.jerk};
    // Evaluation points: the ends, zeros of v, the zero of a, the kink of the relief envelope.
    std::array<double, 8> pts{};
    std::size_t m = 0;
    pts[m++] = 0.0;
    pts[m++] = d;
    m += static_cast<std::size_t>(detail::velocity_zeros(s, d, pts.data() + m));
    if (s.j != 0.0) {
      const double tau = -s.a / s.j;
      if (tau > 0.0 && tau < d) pts[m++] = tau;
    }
    if (relief.over_acceleration) {
      const double bmin = std::min(l.acceleration, l.deceleration);
      const double tk = (std::fabs(s0.a) - bmin) / l.jerk - s.t0;
      if (tk > 0.0 && tk < d) pts[m++] = tk;
      const double bmax = std::max(l.acceleration, l.deceleration);
      const double tk2 = (std::fabs(s0.a) - bmax) / l.jerk - s.t0;
      if (tk2 > 0.0 && tk2 < d) pts[m++] = tk2;
    }
    // At most 7 points: a plain insertion sort (std::sort trips GCC's -Warray-bounds here).
    for (std::size_t x = 1; x < m; ++x)
      for (std::size_t y = x; y > 0 && pts[y - 1] > pts[y]; --y)
        std::swap(pts[y - 1], pts[y]);
    // Velocity at every point (covers the extremum where a crosses 0).
    for (std::size_t k = 0; k < m; ++k) {
      const nc::KinematicState x = advance(s, pts[k]);
      const double av = std::fabs(x.v);
      if (!speed_inside) {
        if (av <= v_lim) {
          speed_inside = true;
        } else if (av > v_start_allow) {
          return {Check::kVelocity, i, s.t0 + pts[k], x.v, std::fabs(s0.v)};
        }
        continue;
      }
      if (ext != nullptr) ext->velocity = std::max(ext->velocity, av / l.velocity - 1.0);
      if (av > v_lim) return {Check::kVelocity, i, s.t0 + pts[k], x.v, l.velocity};
    }
    // Acceleration on each piece with fixed signs of v and a: linear, so its ends bound it.
    for (std::size_t k = 0; k + 1 < m; ++k) {
      const double ta = pts[k];
      const double tb = pts[k + 1];
      if (tb <= ta) continue;
      const nc::KinematicState mid = advance(s, 0.5 * (ta + tb));
      if (mid.v == 0.0 || mid.a == 0.0) continue;
      double bound = ((mid.v > 0.0) == (mid.a > 0.0)) ? l.acceleration : l.deceleration;
      // A piece on which |v| never leaves the rounding of 0 has no direction: either bound
      // (v is monotone on a piece, so its ends bound it).
      if (std::max(std::fabs(advance(s, ta).v), std::fabs(advance(s, tb).v)) <= 4.0 * dv)
        bound = std::max(l.acceleration, l.deceleration);
      for (double tau : {ta, tb}) {
        const double aa = std::fabs(s.a + tau * s.j);
        double allowed = bound;
        // a inside a segment is a + j·tau, rounded to a few ulp of its largest term.
        double slack = a_round;
        if (relief.over_acceleration) {
          allowed = std::max(allowed, std::fabs(s0.a) - l.jerk * (s.t0 + tau));
          // The envelope runs in the profile's absolute time, and so does its kink where it meets
          // the bound: the segments' start times are sums of durations, known to a few ulp of t,
          // and (|a0| - bound) / J to a few ulp of |a0| / J. A ramp that ends on the bound there
          // is only known to end at the kink to J times that (fuzz finding P27, a mistake of the
          // checker: a0 = 1.7e7 A+ ramped down to A+ at t = 512 s, 0.6 ulp of t after the kink
          // computed from a0, and a at the kink was 2.3e-9 of A+ above it).
          slack += 4.0 * std::numeric_limits<double>::epsilon() *
                   (std::fabs(s0.a) + l.jerk * (s.t0 + tau));
        }
        // Where v crosses 0 the bound switches from A- to A+. v itself is only known to a few
        // ulp of the speeds it went through (dv), so the crossing time only to dv/|a|, and a
        // there only to J·dv/|a|: with a large J that is more than 1e-9 of A.
        if (std::fabs(advance(s, tau).v) <= 4.0 * dv && aa > 0.0) slack += s_j * dv / aa;
        if (ext != nullptr) {
          ext->acceleration = std::max(ext->acceleration, aa / allowed - 1.0);
          ext->acceleration_net = std::max(ext->acceleration_net, (aa - slack) / allowed - 1.0);
        }
        if (aa > allowed * (1.0 + tol.limit) + slack)
          return {Check::kAcceleration, i, s.t0 + tau, s.a + tau * s.j, allowed};
      }
    }
  }
  return {};
}

// End state: final_state() at (target, v_end, 0) within the tolerance, and the integrated
// end of the last segment there too. The integrated end can be no more exact than the positions
// the profile passes through (a start moving away at 1e4 mm/s with A 0.1 mm/s² turns 1e9 mm
// away), so its position tolerance also scales with the largest |p| of the segments.
inline Finding check_end(const nc::Profile& prof, const nc::KinematicState& start, double target,
                         double v_end, const Scales& sc, const Tolerance& tol = {},
                         Extremes* ext = nullptr) {
  const double tp = end_position_tolerance(start, target, tol);
  double excursion = 0.0;
  for (std::size_t i = 0; i < prof.segment_count(); ++i)
    excursion = std::max(excursion, std::fabs(prof.segment(i).p));
  const double tp_integrated = tp + tol.end * excursion;
  const double tv = tol.end * sc.v;
  const double ta = tol.end * sc.a;
  const std::size_t n = prof.segment_count();
  const nc::KinematicState e =
      n == 0 ? prof.start_state() : advance(prof.segment(n - 1), prof.segment(n - 1).duration);
  const double T = prof.duration();
  if (ext != nullptr) {
    ext->end_position =
        std::max(ext->end_position, std::fabs(e.p - target) / std::max(sc.p, excursion));
    ext->end_velocity = std::max(ext->end_velocity, std::fabs(e.v - v_end) / sc.v);
    ext->end_acceleration = std::max(ext->end_acceleration, std::fabs(e.a) / sc.a);
  }
  if (std::fabs(e.p - target) > tp_integrated)
    return {Check::kEndPosition, n, T, e.p - target, tp_integrated};
  if (std::fabs(e.v - v_end) > tv) return {Check::kEndVelocity, n, T, e.v - v_end, tv};
  if (std::fabs(e.a) > ta) return {Check::kEndAcceleration, n, T, e.a, ta};
  const nc::KinematicState f = prof.final_state();
  if (std::fabs(f.p - target) > tp) return {Check::kFinalState, n, T, f.p - target, tp};
  if (std::fabs(f.v - v_end) > tv) return {Check::kFinalState, n, T, f.v - v_end, tv};
  if (std::fabs(f.a) > ta) return {Check::kFinalState, n, T, f.a, ta};
  return {};
}

// Velocity-profile end: the same without a position target.
inline Finding check_end_velocity(const nc::Profile& prof, double v_end, const Scales& sc,
                                  const Tolerance& tol = {}, Extremes* ext = nullptr) {
  const double tv = tol.end * sc.v;
  const double ta = tol.end * sc.a;
  const std::size_t n = prof.segment_count();
  const double T = prof.duration();
  const nc::KinematicState f = prof.final_state();
  if (std::fabs(f.v - v_end) > tv) return {Check::kFinalState, n, T, f.v - v_end, tv};
  if (std::fabs(f.a) > ta) return {Check::kFinalState, n, T, f.a, ta};
  // The last segment with a length ends at the final velocity (the hold has length 0).
  for (std::size_t i = n; i-- > 0;) {
    const nc::Segment& s = prof.segment(i);
    if (s.duration <= 0.0) continue;
    const nc::KinematicState e = advance(s, s.duration);
    if (ext != nullptr) {
      ext->end_velocity = std::max(ext->end_velocity, std::fabs(e.v - v_end) / sc.v);
      ext->end_acceleration = std::max(ext->end_acceleration, std::fabs(e.a) / sc.a);
    }
    if (std::fabs(e.v - v_end) > tv) return {Check::kEndVelocity, i, T, e.v - v_end, tv};
    if (std::fabs(e.a) > ta) return {Check::kEndAcceleration, i, T, e.a, ta};
    break;
  }
  return {};
}

// at() agrees with the segments: exactly at each segment start, closely inside each segment
// (at its middle), the start state before 0 and the final state at and past the end.
inline Finding check_at(const nc::Profile& prof, const Scales& sc, const Tolerance& tol = {}) {
  const std::size_t n = prof.segment_count();
  const double T = prof.duration();
  auto same = [](const nc::KinematicState& x, const nc::KinematicState& y) {
    return x.p == y.p && x.v == y.v && x.a == y.a;
  };
  if (!same(prof.at(-1.0), prof.start_state())) return {Check::kAt, 0, -1.0, prof.at(-1.0).p, 0.0};
  if (!same(prof.at(T), prof.final_state())) return {Check::kAt, n, T, prof.at(T).p, 0.0};
  // Past the end: the final state, or for a profile that holds its end velocity the motion at it.
  if (!prof.holds_velocity() && !same(prof.at(T + 1.0 + T), prof.final_state()))
    return {Check::kAt, n, 2.0 * T + 1.0, prof.at(2.0 * T + 1.0).p, 0.0};
  double p_scale = sc.p;
  for (std::size_t i = 0; i < n; ++i)
    p_scale = std::max(p_scale, std::fabs(prof.segment(i).p));
  for (std::size_t i = 0; i < n; ++i) {
    const nc::Segment& s = prof.segment(i);
    if (s.duration <= 0.0 || s.t0 >= T) continue;
    // A segment shorter than the time resolution at its t0 shares that t0 with the next one;
    // at(t0) then belongs to the last of them.
    const bool owns_t0 = i + 1 == n || prof.segment(i + 1).t0 > s.t0;
    const nc::KinematicState x = prof.at(s.t0);
    if (owns_t0 && !same(x, state_of(s))) return {Check::kAt, i, s.t0, x.v - s.v, 0.0};
    const double tm = s.t0 + 0.5 * s.duration;
    if (tm <= s.t0 || tm >= s.t0 + s.duration) continue;
    const nc::KinematicState y = prof.at(tm);
    const nc::KinematicState z = advance(s, tm - s.t0);
    // at() may evaluate from either end of the segment; the two differ by the resolution of the
    // absolute times (a few ulp of T), times the rate of change of each quantity.
    const double dt = 4.0 * std::numeric_limits<double>::epsilon() * T;
    const double tp = tol.continuity * p_scale + sc.v * dt;
    const double tv = tol.continuity * sc.v + sc.a * dt;
    const double ta = tol.continuity * sc.a + sc.j * dt;
    if (!finite(y)) return {Check::kAt, i, tm, y.p, 0.0};
    if (std::fabs(y.p - z.p) > tp) return {Check::kAt, i, tm, y.p - z.p, tp};
    if (std::fabs(y.v - z.v) > tv) return {Check::kAt, i, tm, y.v - z.v, tv};
    if (std::fabs(y.a - z.a) > ta) return {Check::kAt, i, tm, y.a - z.a, ta};
    if (prof.jerk_at(tm) != s.j) return {Check::kAt, i, tm, prof.jerk_at(tm), s.j};
  }
  return {};
}

// All checks of a profile to (target, v_end, 0) that is expected to stay inside the limits.
inline Finding check_passing_profile(const nc::Profile& prof, const nc::KinematicState& start,
                                     double target, double v_end, const nc::Limits& l,
                                     const Tolerance& tol = {}, const StartRelief& relief = {},
                                     Extremes* ext = nullptr) {
  const Scales sc = scales_for(start, target, l);
  Finding f = check_structure(prof, start, tol);
  if (f.ok()) f = check_continuity(prof, sc, tol, ext);
  if (f.ok()) f = check_end(prof, start, target, v_end, sc, tol, ext);
  if (f.ok()) f = check_limits(prof, l, tol, relief, ext);
  if (f.ok()) f = check_at(prof, sc, tol);
  return f;
}

// All checks of a position profile (to rest) that is expected to stay inside the limits.
inline Finding check_position_profile(const nc::Profile& prof, const nc::KinematicState& start,
                                      double target, const nc::Limits& l, const Tolerance& tol = {},
                                      const StartRelief& relief = {}, Extremes* ext = nullptr) {
  return check_passing_profile(prof, start, target, 0.0, l, tol, relief, ext);
}

// All checks of a velocity profile (plan_velocity) that is expected to stay inside the limits.
inline Finding check_velocity_profile(const nc::Profile& prof, const nc::KinematicState& start,
                                      double velocity, const nc::Limits& l,
                                      const Tolerance& tol = {}, const StartRelief& relief = {},
                                      Extremes* ext = nullptr) {
  Scales sc = scales_for(start, start.p, l);
  Finding f = check_structure(prof, start, tol);
  if (f.ok()) f = check_continuity(prof, sc, tol, ext);
  if (f.ok()) f = check_end_velocity(prof, velocity, sc, tol, ext);
  if (f.ok()) f = check_limits(prof, l, tol, relief, ext);
  return f;
}

// A printable problem, with full precision so that a failure can be reproduced.
inline std::string describe_problem(const char* kind, const nc::KinematicState& s, double target,
                                    const nc::Limits& l) {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s start={p=%.17g, v=%.17g, a=%.17g} target=%.17g limits={V=%.17g, A+=%.17g, "
                "A-=%.17g, J=%.17g}",
                kind, s.p, s.v, s.a, target, l.velocity, l.acceleration, l.deceleration, l.jerk);
  return buf;
}

// The same for a problem with an end velocity (plan_position's four-argument call).
inline std::string describe_passing_problem(const char* kind, const nc::KinematicState& s,
                                            double target, double v_end, const nc::Limits& l) {
  char buf[64];
  std::snprintf(buf, sizeof buf, " v_end=%.17g", v_end);
  return describe_problem(kind, s, target, l) + buf;
}

}  // namespace profile_checks
