// The walk of the time-optimal velocity change (internal; seed 000 §2.1: phases of +J, constant
// acceleration, -J), a template over the sink of its pieces: velocity_change.cpp's entries
// instantiate it, and plan_velocity with the profile writer directly (issue 17: inlined there, the
// writer's running state stays in registers).
//
// Walking the envelope: for an upward change, a rises at +J from a0 until it meets the highest
// admissible acceleration at the current velocity, then follows it. That ceiling is
//   - the path-relative bound: A- while v < 0 (|v| shrinks), A+ while v >= 0 (|v| grows);
//   - before v crosses 0 upwards: a^2 + 2Jv <= A+^2, so that a is down to A+ when v reaches 0
//     (only binding when A+ < A-);
//   - the final ramp: a^2 + 2Jv <= 2J v1, so that a is 0 exactly when v reaches v1.
// Both curves are -J arcs (a^2 + 2Jv is constant along -J), so following them means jerk -J,
// following a bound means jerk 0. Downward changes are the mirror image (v, a -> -v, -a), which
// the path-relative bounds are symmetric under.
#pragma once

#include <algorithm>
#include <cmath>

#include "profile/profile_writer.hpp"
#include "profile/stop_change.hpp"
#include "profile/velocity_change.hpp"

namespace nc::detail::walk {

inline constexpr double kRel = kDecisionTolerance;

// The pieces are written mirrored by `sign` (-1 for a downward change walked as its mirror image;
// multiplying by +-1 is exact).
template <class Sink>
int upward(double v, double a, double v1, const Bounds& b, double sign, Sink& out) noexcept {
  const double jerk = b.j;
  const double kf = 2.0 * jerk * v1;
  const bool cross = v1 > 0.0;
  const double kc = cross ? std::min(kf, b.ap * b.ap) : kf;
  // Scales of the problem itself (not of the bounds, which may be far larger than needed).
  const double v_scale = std::max({std::abs(v1), std::abs(v), a * a / jerk});
  const double tol_v = kRel * v_scale;
  // The acceleration's tolerance at v1, taken only where v is at v1 within tol_v (issue 17: its
  // square root on every walk cost more than the rare test it serves).
  auto tol_a = [&] { return kRel * std::sqrt(jerk * v_scale); };
  int n = 0;
  // Appends a piece and moves the walk's state to its (exactly known) end.
  auto put = [&](double t, double j, double a_end, double v_end, bool v_exact) {
    if (t > 0.0) {
      out.put(Piece{t, sign * j, sign * a_end, v_exact ? sign * v_end : NAN});
      ++n;
    }
    a = a_end;
    v = v_end;
  };
  // The rest of the change once its bound is `cap` up to v1 (no bound change at v = 0 ahead),
  // in closed form (issue 17): rise (to the final curve, or to the bound and hold), final ramp.
  // It decides as the loop below would on the same values, in the same order, and writes the
  // same pieces; it leaves out only the loop's tests that cannot hold on this path (the state
  // is not outside the bound again, v = 0 is not reached, and after the rise onto the final
  // curve or the hold up to it the final ramp follows: the curve's excess there is rounding of
  // a^2 and 2J v, far below k_tol). Returns false where the loop must go on (a start above the
  // bound, the landing within rounding of the curve, a rise onto it at a = 0), with the pieces
  // written so far and the state at their end.
  auto closed = [&](double cap) -> bool {
    const double kf_abs = std::abs(kf);
    if (a > cap * (1.0 + kRel)) return false;
    // 0: at the start; 2: at the bound after a rise; 3: on the final curve (its ramp is next).
    // One put() per piece in one place (the push scan's put is large).
    int phase = 0;
    for (;;) {
      double t = 0.0;
      double j = -jerk;
      double a_end = 0.0;
      double v_end = v1;
      bool exact = true;
      int next = -1;  // the phase after this piece; -1: it is the last one
      if (phase == 3) {
        t = a / jerk;
      } else {
        if (phase == 2 && v >= v1 - tol_v && std::abs(a) <= tol_a()) {
          // At v1 within rounding (the loop's end test).
          if (a == 0.0) return true;
          t = std::abs(a) / jerk;
          j = a > 0.0 ? -jerk : jerk;
        } else {
          const double excess = a * a + 2.0 * jerk * (v - v1);
          const double k_tol = kRel * (kf_abs + a * a + 2.0 * jerk * std::abs(v));
          if (a > 0.0 && excess >= -k_tol) {
            t = a / jerk;  // the final ramp
          } else if (phase == 2 || a >= cap * (1.0 - kRel)) {
            // Hold the bound up to the final curve, at the value a has (as the loop does).
            const double v_curve = v1 - cap * cap / (2.0 * jerk);
            t = std::max((v_curve - v) / a, 0.0);
            j = 0.0;
            a_end = cap;
            v_end = std::max(v_curve, v);
            exact = false;
            next = 3;
          } else {
            const double t_cap = (cap - a) / jerk;
            const double meet2 = 0.5 * (a * a - 2.0 * jerk * (v - v1));
            const bool on_final = meet2 <= k_tol;
            if (on_final && a < 0.0 && v > v1) return false;
            const double a_meet = on_final ? 0.0 : std::sqrt(std::max(meet2, 0.0));
            const double t_curve = std::max((a_meet - a) / jerk, 0.0);
            j = jerk;
            exact = false;
            if (t_curve <= t_cap) {
              if (!(a_meet > 0.0)) return false;
              t = t_curve;
              a_end = a_meet;
              v_end = v1 - a_meet * a_meet / (2.0 * jerk);
              next = 3;
            } else {
              t = t_cap;
              a_end = cap;
              v_end = v + t_cap * (a + 0.5 * jerk * t_cap);
              next = 2;
            }
          }
        }
      }
      put(t, j, a_end, v_end, exact);
      if (next < 0 || out.stopped()) return true;
      phase = next;
    }
  };
  for (int iter = 0; iter < kMaxChangePieces; ++iter) {
    if (out.stopped()) return n;  // the sink has what it needs (PushScan)
    const bool neg = v < 0.0 || (v == 0.0 && a < 0.0);
    if ((!neg || !cross) && v >= v1 - tol_v && std::abs(a) <= tol_a()) {
      // At v1 within rounding. An acceleration left there still ramps to 0 at J (a piece of
      // rounding-size duration): it may be all of A when J is huge against A (fuzz finding P6:
      // A = 7e-9, J = 6e8, tol_a = 1.3e-8), and dropping it would jump a by A.
      if (a != 0.0) put(std::abs(a) / jerk, a > 0.0 ? -jerk : jerk, 0.0, v1, true);
      return n;
    }
    // No bound change ahead: v stays above 0 up to v1 > 0 (a >= 0, or v's lowest point v_nat
    // is above 0), or below 0 up to v1 < 0; where a rise could come near v = 0, with a margin
    // far above the rounding of the loop's tests for reaching it. (closed() returns false before
    // it writes anything: the loop then takes this state.)
    const bool closed_form =
        !neg ? cross && (a >= 0.0 || a * a - 2.0 * jerk * v < -1e-6 * (2.0 * jerk * v))
             : !cross && v1 < -1e-6 * v_scale;
    if (closed_form && closed(neg ? b.am : b.ap)) return n;
    const double cap = neg ? b.am : b.ap;
    const double k = neg ? kc : kf;
    // The curve's a reaches 0 at vk (k = 2J vk); differences to it are taken in v, where they
    // are exact for close values, not in a^2 + 2Jv, which cancels.
    const bool final_curve = !neg || !cross || kc == kf;
    const double vk = final_curve ? v1 : kc / (2.0 * jerk);
    const double k_now = a * a + 2.0 * jerk * v;
    const double excess = a * a + 2.0 * jerk * (v - vk);  // k_now - k
    const double k_tol = kRel * (std::abs(k) + a * a + 2.0 * jerk * std::abs(v));

    if (a > cap * (1.0 + kRel)) {
      // Above the bound: back to it at -J (in v < 0 the bound may change at v = 0 first).
      const double t_cap = (a - cap) / jerk;
      if (neg && k_now >= 0.0) {
        const double sq = std::sqrt(k_now);
        const double t_zero = -2.0 * v / (a + sq);
        if (t_zero < t_cap) {
          put(t_zero, -jerk, sq, 0.0, true);
          continue;
        }
      }
      put(t_cap, -jerk, cap, v + t_cap * (a - 0.5 * jerk * t_cap), false);
      continue;
    }
    if (a > 0.0 && excess >= -k_tol) {
      // On a -J curve: the final ramp, or the ramp down to A+ before v = 0.
      if (!neg || !cross) {
        put(a / jerk, -jerk, 0.0, v1, true);
        return n;
      }
      // The arc's constant is the curve's (k), known exactly; k_now = a^2 + 2Jv would cancel
      // badly when a^2 >> k. Only a start above the curve (a violation that cannot be avoided)
      // keeps its own constant.
      const double sq = std::sqrt(std::max(excess > k_tol ? k_now : k, 0.0));
      put((a - sq) / jerk, -jerk, sq, 0.0, true);
      continue;
    }
    if (a >= cap * (1.0 - kRel)) {
      // At the bound: hold it until the -J curve is met (or v reaches 0). The profile holds the
      // acceleration it has, within kRel of the bound: the times are taken at that value, else a
      // long hold drifts past its end velocity (fuzz finding P7: a 3e-14 above A- for 1.8e7 s
      // crossed v = 0 by 2.7e-10 still at A-, above the smaller A+ beyond).
      const double held = a;
      a = cap;
      const double v_curve = vk - cap * cap / (2.0 * jerk);
      const double t_curve = std::max((v_curve - v) / held, 0.0);
      if (neg) {
        const double t_zero = -v / held;
        if (t_zero < t_curve) {
          put(t_zero, 0.0, cap, 0.0, true);
          continue;
        }
      }
      put(t_curve, 0.0, cap, std::max(v_curve, v), false);
      continue;
    }
    // Below the ceiling: rise at +J until the bound, the curve, or a change of the bound at v = 0.
    const double t_cap = (cap - a) / jerk;
    const double r = a * a - 2.0 * jerk * v;  // constant along +J
    const double meet2 = 0.5 * (a * a - 2.0 * jerk * (v - vk));
    // Within rounding of the final curve (v_nat = v1) the rise ends at a = 0 exactly: the
    // remaining time must not jump with the square root of the rounding.
    const bool on_final = final_curve && meet2 <= k_tol;
    // Coming down onto v1 with a slightly forced overshoot: one ramp that lands exactly, its
    // jerk a^2 / 2(v - v1) above J by at most ~4 kRel. Along that ramp the overshoot stays the
    // same fraction of v - v1 and of k_tol, so every state sampled on it decides the same way
    // (re-planning gives the rest of it); a ramp at J would keep the absolute overshoot while
    // k_tol shrinks, and the decision would flip part-way. Only where that jerk is within the
    // ~4 kRel: when 2J|v| dominates k_tol, "within rounding" of the final curve allows an a^2
    // far above 2J(v - v1) (fuzz finding P5: 11.6 J), and the ramp at J below is taken instead.
    const double landing_t = 2.0 * (v1 - v) / a;
    if (on_final && a < 0.0 && v > v1 && -a / landing_t <= jerk * (1.0 + 8.0 * kRel)) {
      // A landing below J only comes from rounding here (v_nat <= v1 was decided on rounded
      // values, so v may sit an ulp above the curve). Its length 2 (v - v1) / |a| would carry
      // that ulp of v into the distance at v1 / |a| per ulp, and a state sampled on a profile's
      // final ramp at J would then re-plan to a reversal (the Bellman suite's seeds 1, 10, 12:
      // 0.35 ulp of v = 7995 against A- = 3.07 moved the end by 1.7e-9): the ramp at J is taken
      // instead, ending on v1 exactly (a velocity jump within the rounding of v, as the walk's
      // mirror image makes from the other side of the curve).
      const double over = (v - v1) - 0.5 * a * a / jerk;  // v_nat - v1: where a ramp at J ends
      if (-a / landing_t < jerk && std::abs(over) <= tol_v) {
        put(-a / jerk, jerk, 0.0, v1, true);
      } else {
        put(landing_t, -a / landing_t, 0.0, v1, true);
      }
      return n;
    }
    const double a_meet = on_final ? 0.0 : std::sqrt(std::max(meet2, 0.0));
    const double t_curve = std::max((a_meet - a) / jerk, 0.0);
    double t_zero = INFINITY;
    if (neg) {
      const double sq = std::sqrt(std::max(r, 0.0));
      t_zero = a >= 0.0 ? -2.0 * v / (a + sq) : (sq - a) / jerk;
    } else if (a < 0.0 && r >= 0.0) {
      t_zero = 2.0 * v / (std::sqrt(r) - a);
    }
    const double t_event = std::min(t_cap, t_curve);
    if (t_zero < t_event * (1.0 - kRel)) {
      put(t_zero, jerk, a + jerk * t_zero, 0.0, true);
      continue;
    }
    if (t_curve <= t_cap) {
      if (!(a_meet > 0.0)) {
        // Meets the final curve at a = 0: that is the end velocity itself. A positive a left
        // there (on the curve within rounding, but below the final ramp's own tolerance) still
        // ramps to 0 at J (fuzz finding P15: a = 1.1e-13 against A+ = 2e-6 was dropped).
        if (a > 0.0) {
          put(a / jerk, -jerk, 0.0, v1, true);
        } else {
          put(t_curve, jerk, 0.0, v1, true);
        }
        return n;
      }
      put(t_curve, jerk, a_meet, vk - a_meet * a_meet / (2.0 * jerk), false);
      continue;
    }
    put(t_cap, jerk, cap, v + t_cap * (a + 0.5 * jerk * t_cap), false);
  }
  return -1;
}

template <class Sink>
int change(double v0, double a0, double v1, const Bounds& bounds, Sink& out) noexcept {
  if (v1 == 0.0) return stop_change(v0, a0, bounds, out);
  if (v1 >= natural_velocity(v0, a0, bounds.j)) return upward(v0, a0, v1, bounds, 1.0, out);
  return upward(-v0, -a0, -v1, bounds, -1.0, out);
}

// Where the pieces go: an array, or straight into a profile (both take the whole change), or
// plan_position's push scan (PushScan::stopped()).
struct ArraySink {
  Piece* out;
  void put(const Piece& piece) noexcept { *out++ = piece; }
  static constexpr bool stopped() noexcept { return false; }
};
struct WriterSink {
  ProfileWriter& writer;
  // upward() and stop_change() hand on only pieces with t > 0 and a known a_end.
  void put(const Piece& piece) noexcept {
    writer.append_change_piece(piece.t, piece.j, piece.a_end, piece.v_end);
  }
  static constexpr bool stopped() noexcept { return false; }
};

}  // namespace nc::detail::walk
