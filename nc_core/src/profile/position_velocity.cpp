// plan_position with an end velocity: time-optimal motion from any state to (target, v_end, 0).
//
// The same construction as the stop at a target (position.cpp), with the stop replaced by the
// time-optimal velocity change to v_end: push = the velocity change towards ±V (then cruise at
// ±V) for a time tau, then the change to v_end from the state reached. The point E(tau) where
// that change ends moves towards the push direction, from E(0) (the change straight from the
// start) to infinity; so the direction is the side of the target relative to E(0), and tau is
// the root of E(tau) = target. A target behind E(0) gives a push the other way: the velocity goes
// below v_end (through v = 0 where needed: a run-up backwards) and the change brings it back.
// The change to v_end has no closed-form distance here (it may cross v = 0, where the bounds
// change), so tau is found by a bracketed regula falsi (Illinois) on the pieces' own integrated
// distance, first bracketed between the push's piece boundaries. v_end = 0 is plan_position's
// three-argument call itself (bit for bit).
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "nc_core/profile.hpp"
#include "profile/finish.hpp"
#include "profile/profile_writer.hpp"
#include "profile/validate.hpp"
#include "profile/velocity_change.hpp"

namespace nc {
namespace {

using detail::Bounds;
using detail::Piece;

constexpr double kRootTolerance = 1e-13;
// Points of the bounded scan for a first switch inside a push piece that slows the motion.
constexpr int kScanPoints = 4;
// Relative to |v_end|: an overshoot of v_end below this is no switch point past a flat stretch
// of E (the hold at v_end takes the same time to second order in it).
constexpr double kSwitchOvershoot = 1e-6;

// Closes on (target, v_end, 0), holding v_end past the end (profile/finish.hpp).
Profile finish_moving(const KinematicState& start, double target, double v_end, double dir,
                      const Piece* head, int n_head, double cruise, const Piece* tail,
                      int n_tail) noexcept {
  return detail::finish<false>(start, target, v_end, dir, head, n_head, cruise, tail, n_tail, true);
}

// Distance of the time-optimal change (v, a) -> v1; NaN if the walk does not close.
double change_distance(double v, double a, double v1, const Bounds& b) noexcept {
  detail::PieceBuffer<detail::kMaxChangePieces> room;
  const int n = detail::velocity_change(v, a, v1, b, room.items);
  if (n < 0) return NAN;
  return detail::pieces_distance(v, a, room.items, n);
}

// The switch leaves a residual E(tau) - goal at the rounding level of E, which can be far above
// the rounding of the positions: a hold at a small A- after a small overshoot of a large v_end
// lasts (v_curve - v) / A-, a difference of close absolute velocities, and every ulp of v moves
// the end by v / A- ulp. The residual is taken out of the longest-travelling zero-jerk piece of
// the change (its duration shifts by -residual / v, its end velocity by a · that, which is at the
// level of v's own rounding), so that the profile is continuous in position at the switch.
bool absorb_residual(const KinematicState& x, double goal, Piece* change, int n) noexcept {
  KinematicState s = x;
  int best = -1;
  double best_travel = 0.0;
  double best_v = 0.0;
  // Only pieces before the first v = 0 of the change: anchoring from the end moves the velocities
  // of the pieces before the one shifted, and at v = 0 the bounds change (a shift of 1e-13 there
  // is an acceleration above its bound for a moment).
  bool crossed = false;
  for (int k = 0; k < n && !crossed; ++k) {
    const KinematicState e = detail::advance(s, change[k]);
    crossed = e.v == 0.0 || (e.v < 0.0) != (s.v < 0.0);
    if (change[k].j == 0.0 && !crossed) {
      const double v_mid = s.v + 0.5 * s.a * change[k].t;
      const double travel = std::abs(v_mid) * change[k].t;
      if (travel > best_travel) {
        best = k;
        best_travel = travel;
        best_v = v_mid;
      }
    }
    s = e;
  }
  if (best < 0) return false;
  s = x;
  for (int k = 0; k < n; ++k)
    s = detail::advance(s, change[k]);
  const double residual = s.p - goal;
  const double dt = -residual / best_v;
  const double t = change[best].t + dt;
  // Only a shift within the velocity's rounding level (else the residual is left as it is).
  if (!(t > 0.0 && std::abs(change[best].a_end * dt) <= 1e-12 * std::abs(best_v))) return false;
  change[best].t = t;
  return true;
}

// The switch's residual E(tau) - goal (x the push's state at tau, relative to the start) and the
// rounding it is known to: 1e-11 of the path to the change's end (`push_path`, the push's own up
// to x, and each piece of the change; a push or a run-up that travels far and comes back leaves
// the rounding of that path in E), at least of |goal| + |E| and of the positions' scale
// `p_scale` (max(1, |start|, |target|), as the profile's continuity is judged). A residual within
// it is no jump of E that needs the hold at v_end: a position step of that size is left instead,
// 100 times below what the profile checks allow (a hold at a tiny |v_end| would last r / |v_end|:
// 1.4e23 s for 1.3e-19 mm at 1e-42 mm/s; 5e18 s for 0.57 mm, 1.3e-12 of a run-up of 4.2e11 mm,
// at 1e-19 mm/s).
struct SwitchResidual {
  double r = 0.0;
  double tolerance = 0.0;
};
SwitchResidual switch_residual(const KinematicState& x, double push_path, double goal,
                               double p_scale, const Piece* change, int n) noexcept {
  // Integrated as pieces_distance does (the root search's own E).
  KinematicState s{0.0, x.v, x.a};
  double path = push_path;
  for (int k = 0; k < n; ++k) {
    const KinematicState e = detail::advance_change(s, change[k]);
    path += std::abs(e.p - s.p);
    s = e;
  }
  const double r = x.p + s.p - goal;
  return {r, 1e-11 * std::max({std::abs(goal) + std::abs(r + goal), path, p_scale})};
}

}  // namespace

Profile plan_position(const KinematicState& start, double target, double target_velocity,
                      const Limits& limits) noexcept {
  // The same checks as the three-argument call (its numeric range: a target beyond 1e12 is
  // 0x4222), and an end velocity 0 or within [1e-100, V] (a subnormal one: 0x4221, as
  // plan_velocity's target velocity).
  ErrorCode e = detail::check_plan(start, target, limits);
  if (e == ErrorCode::kNone && !std::isfinite(target_velocity)) {
    e = ErrorCode::kParameterNotFinite;
  }
  if (e == ErrorCode::kNone && (std::abs(target_velocity) > limits.velocity ||
                                !detail::velocity_in_range(target_velocity))) {
    e = ErrorCode::kVelocityNotAllowed;
  }
  if (e == ErrorCode::kNone) e = detail::check_end_velocity(target_velocity, limits);
  if (e != ErrorCode::kNone) return Profile::failure(e);
  if (target_velocity == 0.0) return plan_position(start, target, limits);

  const Bounds bounds{limits.acceleration, limits.deceleration, limits.jerk};
  const double distance = target - start.p;
  const double v_end = target_velocity;

  detail::PieceBuffer<detail::kMaxChangePieces> change_room;
  Piece* change = change_room.items;
  int n_change = detail::velocity_change(start.v, start.a, v_end, bounds, change);
  if (n_change < 0) return Profile::failure(ErrorCode::kPlannerNoSolution);
  const double change_end = detail::pieces_distance(start.v, start.a, change, n_change);
  const double rest = distance - change_end;
  // A target within rounding of where the direct change ends is that end (re-planning from a
  // state sampled on the final change gives that change, as in the three-argument call). Unlike a
  // stop, that end is only known to the rounding of a hold computed from close velocities (a few
  // ulp of v^2 / A), and a target just on the wrong side of it needs a reversal: the dead zone
  // covers that rounding too, capped at 1e-11 of the positions (the end check allows 1e-9).
  const double v_max = std::max(std::abs(start.v), std::abs(v_end));
  const double hold_scale = v_max * (v_max / std::min(limits.acceleration, limits.deceleration));
  const double p_scale = std::max({1.0, std::abs(start.p), std::abs(target)});
  const double dead_zone = std::max(
      64.0 * DBL_EPSILON * std::max({std::abs(start.p), std::abs(target), std::abs(change_end)}),
      std::min(64.0 * DBL_EPSILON * hold_scale, 1e-11 * p_scale));
  if (std::abs(rest) <= dead_zone) {
    absorb_residual({0.0, start.v, start.a}, distance, change, n_change);
    return finish_moving(start, target, v_end, 1.0, change, n_change, 0.0, nullptr, 0);
  }

  // Mirrored so that the target lies ahead (+) of E(0); positions relative to the start.
  const double dir = rest > 0.0 ? 1.0 : -1.0;
  const double goal = dir * distance;
  const double ve = dir * v_end;
  detail::PieceBuffer<detail::kMaxChangePieces> push_room;
  Piece* push = push_room.items;
  const int n_push =
      detail::velocity_change(dir * start.v, dir * start.a, limits.velocity, bounds, push);
  if (n_push < 0) return Profile::failure(ErrorCode::kPlannerNoSolution);

  KinematicState s{0.0, dir * start.v, dir * start.a};
  double push_path = 0.0;  // the distance the push's whole pieces so far travel (both ways)
  double e_here = dir * change_end;  // where the change to ve from s ends
  for (int i = 0; i < n_push; ++i) {
    const KinematicState next = detail::advance(s, push[i]);
    const double e_next = next.p + change_distance(next.v, next.a, ve, bounds);
    if (std::isnan(e_next)) return Profile::failure(ErrorCode::kPlannerNoSolution);
    const double jerk = push[i].j;
    auto f = [&](double tau) {
      const KinematicState x = detail::advance(s, jerk, tau);
      const double d = change_distance(x.v, x.a, ve, bounds);
      return x.p + d - goal;
    };
    double lo = 0.0, hi = push[i].t;
    double r_lo = e_here - goal, r_hi = e_next - goal;  // the residuals at the bracket's ends
    bool found = r_hi >= 0.0;
    if (!found && s.a < 0.0) {
      // A piece that still brings back a start acceleration against the push (a < 0 here)
      // slows the motion down: E(tau) may rise above the goal and fall back below it within the
      // piece (issue 14 item 1, the Bellman suite's seed 3: from v = -V with a = 4.8 against
      // J = 3.3, E rose 0.013 above the goal and fell back; the later root gave a profile 1.7
      // times the optimum). The first crossing is the optimal switch: a bounded scan of the
      // piece (3 inner points; 15 cost 20 % of the planning time of the passing class) finds it.
      for (int k = 1; k < kScanPoints && !found; ++k) {
        const double t_k = push[i].t * (static_cast<double>(k) / kScanPoints);
        const double r_k = f(t_k);
        if (std::isnan(r_k)) return Profile::failure(ErrorCode::kPlannerNoSolution);
        if (r_k >= 0.0) {
          hi = t_k;
          r_hi = r_k;
          found = true;
        } else {
          lo = t_k;
          r_lo = r_k;
        }
      }
    }
    // Whether the search's first point follows the power law from lo (below).
    bool power_first = lo == 0.0;
    if (found && jerk == 0.0 && lo == 0.0 && s.a > 0.0) {
      // A hold whose change to ve begins with the same hold (the push and the change accelerate
      // alike until the change's final ramp): E(tau) is E(0) all along that hold, and a flat
      // stretch gives the secant nothing to go by (fuzz finding P17: A± = 7e-9, J = 1.4e6, the
      // push's hold lasted 2.8e14 s, E was flat over its first 0.571 s and the root at 0.65 s
      // lay beyond; 200 steps ended inside the flat stretch and continuity broke by 1.87e-9).
      // Past that stretch (and past the change's rounding window, where an overshoot of ve is
      // taken as none) E rises again: if it is still short of the goal there by more than an
      // overshoot of rounding size covers, the bracket starts there. If not, the search goes on
      // as before (P10, P12: the hold at ve below).
      detail::PieceBuffer<detail::kMaxChangePieces> along_room;
      const int n_along = detail::velocity_change(s.v, s.a, ve, bounds, along_room.items);
      if (n_along > 0 && along_room.items[0].j == 0.0) {
        const double t_past = along_room.items[0].t + 16.0 * detail::kDecisionTolerance *
                                                          std::max(std::abs(s.v), std::abs(ve)) /
                                                          s.a;
        if (t_past < hi) {
          const double r_past = f(t_past);
          if (std::isnan(r_past)) return Profile::failure(ErrorCode::kPlannerNoSolution);
          // The overshoot of ve that covers the shortfall (to first order, the distance grows at
          // |ve| for the time up and back): one of rounding size is no switch point (P12, the
          // hold at ve below takes the same time to 1e-12), a larger one is.
          const double a_back = ve > 0.0 ? bounds.am : bounds.ap;
          const double overshoot = -r_past / (std::abs(ve) * (1.0 / s.a + 1.0 / a_back));
          if (r_past < 0.0 && overshoot > kSwitchOvershoot * std::abs(ve)) {
            lo = t_past;
            r_lo = r_past;
          }
        }
      }
    }
    if (found) {
      // The switch from push to change lies in [lo, hi]: E(tau) - goal changes sign on it.
      double w_lo = r_lo, w_hi = r_hi;  // the Illinois weights of the bracket's ends
      double tau = hi;
      int side = 0;
      for (int iter = 0; iter < 200; ++iter) {
        if (hi - lo <= 4.0 * DBL_EPSILON * hi) {
          tau = -r_lo <= r_hi ? lo : hi;  // the end with the smaller residual
          break;
        }
        // Regula falsi with the Illinois weighting; a bisection every 8th step bounds the count.
        // The first point follows the power law E - E(0) ~ tau^n the piece typically has (2 on
        // a hold, 4 on a jerk piece, as in position.cpp): on a long piece whose far end lies
        // decades beyond the goal, the secant point crawls from the near end and 200 steps did
        // not reach the root (fuzz finding P14: a hold at A+ = 7.6e-6 towards V = 1000 lasts
        // 1.3e8 s, the root lay at 0.051 s, the search stopped at 3.93 s).
        double x = lo + (hi - lo) * (w_lo / (w_lo - w_hi));
        if (iter == 0 && power_first) {
          const double q = std::sqrt(std::clamp(r_lo / (r_lo - r_hi), 0.0, 1.0));
          x = lo + (hi - lo) * (jerk == 0.0 ? q : std::sqrt(q));
        }
        if (!(x > lo && x < hi) || iter % 8 == 7) x = 0.5 * (lo + hi);
        const double fx = f(x);
        if (std::isnan(fx)) return Profile::failure(ErrorCode::kPlannerNoSolution);
        tau = x;
        if (std::abs(fx) <= kRootTolerance * (std::abs(goal) + std::abs(fx + goal))) break;
        if (fx < 0.0) {
          lo = x;
          r_lo = w_lo = fx;
          if (side == -1) w_hi *= 0.5;
          side = -1;
        } else {
          hi = x;
          r_hi = w_hi = fx;
          if (side == 1) w_lo *= 0.5;
          side = 1;
        }
      }
      KinematicState x = detail::advance(s, jerk, tau);
      n_change = detail::velocity_change(x.v, x.a, ve, bounds, change);
      if (n_change < 0) return Profile::failure(ErrorCode::kPlannerNoSolution);
      if (!absorb_residual(x, goal, change, n_change)) {
        // E(tau) jumps where the change's rounding tolerance takes a state just past the final
        // curve as on it (fuzz findings P10, P12, P21): an overshoot of ve of that size costs a
        // dip of a whose time, at ve, is far more distance than the positions' rounding (with a
        // small A-: v·tol_v / A-). A root inside the jump lands short of the goal from the end of
        // the bracket that stops before it along ve — the lower end when ve > 0, the upper one
        // when ve < 0 (P21, A± = 7e-9: E jumped from 0.032 past the goal to 1.1e-8 short of it,
        // along ve) — and holds ve for the rest (the same distance as the dip to within the
        // overshoot's share, about 1e-13 of the time). A residual within the rounding of E
        // (switch_residual) is left as it is: the Bellman suite's run-ups of 3.8e9 mm leave 1e-7
        // there, and a hold at a tiny |ve| would take forever (P23; P14's problem with its signs
        // turned: 7.8e-25 at |ve| = 3.4e-44, 7.4e19 s).
        const double along = ve > 0.0 ? 1.0 : -1.0;
        const double t_short = ve > 0.0 ? lo : hi;
        SwitchResidual res =
            switch_residual(x, push_path + std::abs(x.p - s.p), goal, p_scale, change, n_change);
        if (along * res.r > res.tolerance && tau != t_short) {
          tau = t_short;
          x = detail::advance(s, jerk, tau);
          n_change = detail::velocity_change(x.v, x.a, ve, bounds, change);
          if (n_change < 0) return Profile::failure(ErrorCode::kPlannerNoSolution);
          // The tolerance of this end's own residual (P17: the one of a search that ended far
          // beyond the goal, 5e-7 there, let a shortfall of 1.9e-9 pass without the hold).
          res =
              switch_residual(x, push_path + std::abs(x.p - s.p), goal, p_scale, change, n_change);
        }
        if (along * res.r < -res.tolerance && n_change < detail::kMaxChangePieces) {
          change[n_change++] = Piece{-res.r / ve, 0.0, 0.0, ve};
        }
      }
      push[i] = Piece{tau, jerk, x.a, NAN};
      return finish_moving(start, target, v_end, dir, push, i + 1, 0.0, change, n_change);
    }
    push_path += std::abs(next.p - s.p);
    s = next;
    e_here = e_next;
  }
  // The push reaches V: cruise for the rest, then the change to ve — from (V, 0) exactly after
  // the push's pieces, from the start itself where the push has none (the start is at V within
  // the walk's rounding, a = 0). The walk's "within rounding" is not transitive: a start within
  // it of V and of ve where V is not within it of ve (fuzz finding P26: v0 = 1.57e11 mm/s, V and
  // ve 0.06 and 0.03 mm/s away at J = 7.2e-9) had its change from V end 1.1e15 mm beyond a goal
  // 2 mm ahead of the start's own E(0) = 0: the cruise was cut to 0 and the anchored change
  // jumped back by that distance. From the start, the change ends at E(0), short of the goal.
  const double v_from = n_push > 0 ? limits.velocity : s.v;
  const double a_from = n_push > 0 ? 0.0 : s.a;
  n_change = detail::velocity_change(v_from, a_from, ve, bounds, change);
  if (n_change < 0) return Profile::failure(ErrorCode::kPlannerNoSolution);
  const double s_end = s.p + detail::pieces_distance(v_from, a_from, change, n_change);
  const double cruise = std::max((goal - s_end) / limits.velocity, 0.0);
  const int n_head = detail::settle_push(push, n_push, s.a, limits.jerk);
  return finish_moving(start, target, v_end, dir, push, n_head, cruise, change, n_change);
}

}  // namespace nc
