// plan_position: time-optimal motion from any state to rest at a target.
//
// The time-optimal profile is "push, then stop": push = the time-optimal velocity change towards
// ±V (then cruise at ±V), continued for a time tau; stop = the shortest stop from the state
// reached. The point S(tau) where that stop ends moves monotonically towards the push direction,
// so the direction is the side of the target relative to the shortest stop from the start, and
// tau is the root of S(tau) = target: first bracketed between the push's piece boundaries, then
// solved by second-order steps on exact derivatives (profile/root.hpp, profile/stop_point.hpp).
// From rest the same profile comes in closed form (profile/rest_to_rest.hpp). Seed 000 §2.1's 7
// phases are the rest-to-rest special case (push = phases 1-3 up to the switch, cruise = phase 4,
// stop = phases 5-7); a target the axis cannot stop before gives a push in the opposite direction,
// i.e. one continuous profile reversing through v = 0. Start states outside the limits are brought
// back by the push itself (it is a velocity change to ±V and so returns inside the bounds at
// maximum jerk without undershoot). Everything after the push is anchored back from the exact
// target, so both ends of a profile are exact relative to their own values even after a long
// excursion.
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "nc_core/profile.hpp"
#include "profile/finish.hpp"
#include "profile/profile_writer.hpp"
#include "profile/push_scan.hpp"
#include "profile/rest_to_rest.hpp"
#include "profile/root.hpp"
#include "profile/stop_change.hpp"
#include "profile/stop_point.hpp"
#include "profile/validate.hpp"
#include "profile/velocity_walk.hpp"

namespace nc {
namespace {

using detail::Bounds;
using detail::Piece;

// How exactly the switch point is solved, relative to the positions involved. The tail is anchored
// at the target, so the residual only shows as a jump of this relative size at the switch (the
// checks allow 1e-9); solving much tighter costs iterations without changing the profile.
constexpr double kRootTolerance = 1e-13;

// Closes at rest on the target (profile/finish.hpp).
Profile finish(const KinematicState& start, double target, double dir, const Piece* head,
               int n_head, double cruise, const Piece* tail, int n_tail) noexcept {
  return detail::finish(start, target, 0.0, dir, head, n_head, cruise, tail, n_tail, false);
}

// Closes at rest on the target after the head and a cruise with the stop from (v, a) (mirrored
// frame): the stop's pieces go straight into the profile's anchored tail (issue 17: they were
// written to an array first; the same pieces, appended the same way).
Profile finish_stop(const KinematicState& start, double target, double dir, const Piece* head,
                    int n_head, double cruise, double v, double a, const Bounds& bounds) noexcept {
  return detail::finish_with(
      start, target, 0.0, dir, head, n_head, cruise,
      [&](detail::ProfileWriter& writer) {
        detail::AnchoredSink sink{writer, dir};
        detail::stop_change(v, a, bounds, sink);
      },
      false);
}

// plan_position from a moving start (inputs checked). Flattened (issue 17): the start's stop
// distance, the push walk with its scan (walk::change here, not velocity_change's entry, so that
// the scan's state is not handed across a call), the switch search with its stop points and the
// profile's assembly in one body. Apart from the rest-to-rest path, which so does not pay for
// its frame.
[[gnu::flatten, gnu::noinline]] Profile from_moving(const KinematicState& start, double target,
                                                    const Limits& limits, const Bounds& bounds,
                                                    double distance) noexcept {
  const detail::StopBounds stop_bounds(bounds);
  const double stop_distance = detail::stop_distance_of(start.v, start.a, stop_bounds);
  const double rest = distance - stop_distance;
  // A target within rounding of the shortest stop's end is that end: re-planning from a state
  // sampled on a profile's final stop (absolute positions carry rounding of a few ulp) must give
  // that same stop, not a tiny push whose duration grows with the cube root of the rounding.
  const double dead_zone =
      64.0 * DBL_EPSILON * std::max({std::abs(start.p), std::abs(target), std::abs(stop_distance)});
  if (std::abs(rest) <= dead_zone) {
    detail::PieceBuffer<detail::kMaxChangePieces> stop_room;
    const int n_stop = detail::velocity_change(start.v, start.a, 0.0, bounds, stop_room.items);
    return finish(start, target, 1.0, stop_room.items, n_stop, 0.0, nullptr, 0);
  }

  // Work mirrored so that the target lies ahead (+) of the shortest stop, positions relative to
  // the start (no cancellation against a large absolute position).
  const double dir = rest > 0.0 ? 1.0 : -1.0;
  const double goal = dir * distance;
  detail::PieceBuffer<detail::kMaxChangePieces> push_room;
  Piece* push = push_room.items;
  // The push, walked until the piece whose end's stop reaches the goal (profile/push_scan.hpp).
  detail::PushScan scan{
      push, {0.0, dir * start.v, dir * start.a}, dir * stop_distance, goal, stop_bounds};
  const int n_push =
      detail::walk::change(dir * start.v, dir * start.a, limits.velocity, bounds, scan);
  if (n_push < 0) return Profile::failure(ErrorCode::kPlannerNoSolution);
  const KinematicState s = scan.s;
  if (scan.found) {
    // The switch from push to stop lies in piece i.
    const int i = n_push - 1;
    const double s_here = scan.s_here;  // S at the piece's start
    const double s_next = scan.s_next;  // S at its end
    const double jerk = push[i].j;
    // S(tau) - goal with its derivatives: p' = v, v' = a, a' = jerk along the push.
    const double jerk6 = jerk / 6.0;
    double frame = 0.0;      // the stop's mirror sign at the last evaluation
    double model_tol = 0.0;  // f's tolerance there
    auto fd = [&](double tau) {
      const double a_t = s.a + jerk * tau;
      const double v_t = s.v + tau * (s.a + (0.5 * jerk) * tau);
      const double p_t = s.p + tau * (s.v + tau * (0.5 * s.a + tau * jerk6));
      const detail::StopAlong d = detail::stop_point_along(v_t, a_t, jerk, stop_bounds);
      frame = d.frame;
      model_tol = kRootTolerance * (std::abs(p_t) + std::abs(d.distance) + goal);
      return detail::RootPoint{
          p_t + d.distance - goal, d.d, d.dd, model_tol, d.d3, d.d4, d.quartic};
    };
    // Whether the quartic model of the last point gives f at tau closely enough to return tau
    // unevaluated: the stop there keeps the model's shape (same mirror sign), and the model's own
    // error — its residual, up to half the tolerance where it was taken, and that point's
    // rounding, a fiftieth of it — stays within about twice the tolerance at tau (where S = goal,
    // so |D| = |goal - p|): 2e-13 of the positions. A model taken far beyond the root carries the
    // far point's rounding into it (fuzz finding P25: from 2.6e7 s down to 0.44 s over a hold at
    // A+ = 3.2e-5 with positions of 4e18 mm, the switch 250 mm off); there f is evaluated again.
    auto model_holds = [&](double tau) {
      const double a_t = s.a + jerk * tau;
      const double v_t = s.v + tau * (s.a + (0.5 * jerk) * tau);
      if (!detail::stop_has_hold_shape(v_t, a_t, frame, stop_bounds)) return false;
      const double p_t = s.p + tau * (s.v + tau * (0.5 * s.a + tau * jerk6));
      return model_tol <= 4.0 * kRootTolerance * (std::abs(p_t) + std::abs(goal - p_t) + goal);
    };
    // A start acceleration against the push beyond A- (a < -A-, the motion still forwards:
    // v_nat > 0) is brought back by the stop at +J, as the push's first ramp does: along that
    // ramp S(tau) stays S(0) until a is back at A-. The search starts at the end of that flat
    // stretch, where S begins to rise (fuzz finding P19: A- = J = 3.5e-9, a = -2 A-; from
    // tau = 0 the power law below saw S rise from a point 1.01 s away, and 100 steps
    // alternated between both ends of the bracket and stopped 2.1e-9 short of the goal).
    double lo = 0.0;
    double f_lo = s_here - goal;
    // (The rare test first: the piece's jerk is the problem's own decision, and as the first test
    // its branch was mispredicted on 40 % of the switch searches by callgrind's predictor.)
    if (s.a < -stop_bounds.am_limit && jerk > 0.0 &&
        detail::natural_velocity(s.v, s.a, jerk) > 0.0) {
      const double t_flat = (-stop_bounds.am_limit - s.a) / jerk;
      if (t_flat < push[i].t) {
        const double f_flat = fd(t_flat).f;
        if (f_flat < 0.0) {
          lo = t_flat;
          f_lo = f_flat;
        }
      }
    }
    // Start at the switch in closed form where the stop at the piece's start (or else at its end)
    // is a rise and the final ramp up to the switch (stop_point.hpp, switch_in_piece: on the
    // benchmark set 1.07 evaluations per root; 1.39 from the end alone, 1.65 instead of 3.28 on
    // jerk pieces and 1.68 instead of 2.15 on holds before that). Elsewhere start where
    // S - S(lo) = c (tau - lo)^n would meet the goal, with the exponent it typically has over a
    // piece: 2 on a hold (a constant), 4 on a jerk piece (2.5 evaluations per root instead of 3.4
    // from the secant point). The root finder also uses that power law when its local model
    // misleads it.
    double x0 = lo == 0.0
                    ? detail::switch_in_piece(s, push[i].t, jerk, f_lo, s_next - goal, stop_bounds)
                    : NAN;
    if (!(x0 > 0.0 && x0 < push[i].t)) {
      const double r0 = std::clamp(
          lo == 0.0 ? (goal - s_here) / (s_next - s_here) : -f_lo / ((s_next - goal) - f_lo), 0.0,
          1.0);
      const double q0 = std::sqrt(r0);
      x0 = lo + (push[i].t - lo) * (jerk == 0.0 ? q0 : std::sqrt(q0));
    }
    // Where the stop is a rise and the final ramp, the search runs on its closed form
    // (stop_point_rise) with the root finder's steps; at the first point of another shape, or a
    // step out of the bracket, the general search takes over from there.
    double hi = push[i].t;
    double t_at = x0;
    double tau = NAN;
    double last_step = 0.0;
    for (int k = 0; k < 8; ++k) {
      const double a_t = s.a + jerk * t_at;
      const double v_t = s.v + t_at * (s.a + (0.5 * jerk) * t_at);
      const double p_t = s.p + t_at * (s.v + t_at * (0.5 * s.a + t_at * jerk6));
      detail::RisePoint rise;
      if (!rise.at(v_t, a_t, stop_bounds)) break;
      const double f = p_t + rise.distance - goal;
      const double tol = kRootTolerance * (std::abs(p_t) + std::abs(rise.distance) + goal);
      if (std::abs(f) <= tol) {
        tau = t_at;
        break;
      }
      detail::StopAlong d{};
      rise.slopes(jerk, stop_bounds, d);
      if (f < 0.0) {
        lo = t_at;
        f_lo = f;
      } else {
        hi = t_at;
      }
      if (!(d.d > 0.0)) break;
      const double disc = d.d * d.d - 2.0 * f * d.dd;
      const double step = disc >= 0.0 ? -2.0 * f / (d.d + std::sqrt(disc)) : -f / d.d;
      const double next = t_at + step;
      if (!(next > lo && next < hi)) break;
      if (last_step != 0.0) {
        // root.hpp's acceptance: the model's error shrinks with the cube of the step.
        const double r = std::abs(step / last_step);
        if (std::abs(f) * r * r * r <= 0.125 * tol) {
          tau = next;
          break;
        }
      }
      last_step = step;
      t_at = next;
    }
    if (std::isnan(tau)) tau = detail::find_root_quadratic(fd, model_holds, lo, hi, t_at, f_lo);
    const KinematicState x = detail::advance(s, jerk, tau);
    push[i] = Piece{tau, jerk, x.a, NAN};
    return finish_stop(start, target, dir, push, i + 1, 0.0, x.v, x.a, bounds);
  }
  // The push reaches V: cruise for the rest, then stop from (V, 0). Where that stop ends without
  // the cruise is the scan's last stop point (the stop from the push's end, (V, 0) exactly, or
  // from the start when it is at V within rounding): it is not integrated again from the pieces.
  const double cruise = (goal - scan.s_here) / limits.velocity;
  const int n_head = detail::settle_push(push, n_push, s.a, limits.jerk);
  return finish_stop(start, target, dir, push, n_head, cruise, limits.velocity, 0.0, bounds);
}

}  // namespace

// Flattened (issue 17): the checks and the rest-to-rest profile's assembly inlined.
[[gnu::flatten]] Profile plan_position(const KinematicState& start, double target,
                                       const Limits& limits) noexcept {
  const ErrorCode e = detail::check_plan(start, target, limits);
  if (e != ErrorCode::kNone) return Profile::failure(e);

  const Bounds bounds{limits.acceleration, limits.deceleration, limits.jerk};
  const double distance = target - start.p;

  if (start.v == 0.0 && start.a == 0.0) {
    // From rest: the same profile in closed form, its pieces straight into the profile.
    const detail::RestToRest rest(distance, limits.velocity, bounds);
    return detail::finish_around(
        start, target, 0.0,
        [&](detail::ProfileWriter& writer) {
          rest.up([&](const Piece& piece) { writer.append(piece, 1.0); });
        },
        0.0,
        [&](detail::ProfileWriter& writer) {
          rest.down([&](const Piece& piece) { writer.append_anchored(piece, 1.0); });
        },
        false);
  }

  return from_moving(start, target, limits, bounds, distance);
}

}  // namespace nc
