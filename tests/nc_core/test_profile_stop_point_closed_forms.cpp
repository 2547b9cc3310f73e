// The closed forms plan_position's switch search uses on the two common shapes of the stop (issue
// 17), against stop_point_along over 300 000 random states, pushes (jerk +J, 0, -J) and bounds of
// the planner's range:
//   - stop_point_rise (a rise to a_meet <= A- and the final ramp): accepted exactly where
//     stop_point_along takes that shape, D within 1e-12 of the stop's own scale of the integrated
//     pieces' value, S' and S'' as stop_point_along's (the same expressions); the push scan's
//     stop_distance_closed is that D there and stop_distance_of's value elsewhere;
//   - the quartic (a rise to A-, a hold, the final ramp): where stop_point_along marks a point
//     `quartic`, S along the push is S(0) + S' h + S'' h^2 / 2 + S''' h^3 / 6 + S'''' h^4 / 24 at
//     every h where stop_has_hold_shape holds, to 1e-10 of the terms it is made of; at points where
//     the stop has left that shape, stop_has_hold_shape says so;
//   - switch_on_rise (the switch search's first point): on a hold or a rise at +J from the draw
//     over a random time, with the stop a rise and the final ramp going forwards at a random point
//     and at the end, it finds that point from the stop point's excess at the end, to 1e-9 of the
//     time (or, where S barely moves over the piece, to 1e-13 of S);
//   - switch_from the piece's start: the same from the stop point's shortfall at the start, with
//     the stop a rise and the ramp at the start and at the point (the end may have left the shape);
//     where the stop at the point has left it, no start.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "profile/stop_point.hpp"
#include "profile_problems.hpp"

namespace {

struct Draw {
  nc::Limits limits;
  double v;
  double a;
  double g;
  nc::detail::StopBounds stop_bounds() const {
    return nc::detail::StopBounds(
        nc::detail::Bounds{limits.acceleration, limits.deceleration, limits.jerk});
  }
};

Draw draw(profile_problems::Rng& rng) {
  Draw d;
  d.limits = profile_problems::random_limits(rng);
  d.v = rng.sign() * rng.log_uniform(1e-3, 1e5);
  d.a = rng.sign() * std::max(d.limits.acceleration, d.limits.deceleration) * rng.uniform(0.0, 1.2);
  const double u = rng.uniform();
  d.g = u < 0.3 ? 0.0 : (u < 0.65 ? d.limits.jerk : -d.limits.jerk);
  return d;
}

// Calls visit(draw, its stop bounds, rng) for 300 000 draws from `seed`.
template <class Visit>
void for_each_draw(std::uint64_t seed, Visit&& visit) {
  profile_problems::Rng rng(seed);
  for (int k = 0; k < 300'000; ++k) {
    const Draw d = draw(rng);
    visit(d, d.stop_bounds(), rng);
  }
}

// A push piece for the switch tests: the draw's push at +J (a hold where the draw's push is 0 and
// a > 0; false for the others), its length a random share of the stop's time scale, and a random
// point on it.
struct Piece {
  double g = 0.0;
  double length = 0.0;
  double tau = 0.0;
};
bool draw_piece(const Draw& d, profile_problems::Rng& rng, Piece& piece) {
  piece.g = d.g == 0.0 ? 0.0 : d.limits.jerk;
  if (piece.g == 0.0 && !(d.a > 0.0)) return false;
  const double span =
      std::max(d.limits.deceleration / d.limits.jerk, std::abs(d.v) / d.limits.deceleration);
  piece.length = span * rng.log_uniform(1e-6, 1.0);
  piece.tau = piece.length * rng.uniform(0.0, 1.0);
  return true;
}

// for_each_draw() over the draws that have a Piece (draw_piece(), from the same generator).
template <class Visit>
void for_each_piece(std::uint64_t seed, Visit&& visit) {
  for_each_draw(seed,
                [&](const Draw& d, const nc::detail::StopBounds& b, profile_problems::Rng& rng) {
                  Piece piece;
                  if (draw_piece(d, rng, piece)) visit(d, b, piece);
                });
}

// The switch tests' tally of the points a closed form gives for a piece's root: missed (none in
// the piece), found, and off (neither within 1e-9 of the piece's time of the root, nor, where S
// barely moves over the piece and the time is only known to S's rounding, a point whose S is the
// root's to 1e-13 of `s_scale`). `stop_point(t, out)` gives S at t and whether it has the shape.
struct SwitchTally {
  long found = 0;
  long missed = 0;
  long off = 0;
  template <class StopPoint>
  void judge(double x, const Piece& piece, double s_root, double s_scale, StopPoint&& stop_point) {
    if (!(x > 0.0 && x < piece.length)) {
      ++missed;
      return;
    }
    ++found;
    double s_x = 0.0;
    if (!(std::abs(x - piece.tau) <= 1e-9 * piece.length) &&
        !(stop_point(x, s_x) && std::abs(s_x - s_root) <= 1e-13 * s_scale)) {
      ++off;
    }
  }
};

// The state at t along a piece of jerk g from the draw's state (p relative to the piece's start).
struct Along {
  double p;
  double v;
  double a;
};
Along along_piece(const Draw& d, double g, double t) {
  return {t * (d.v + t * (0.5 * d.a + t * g / 6.0)), d.v + t * (d.a + 0.5 * g * t), d.a + g * t};
}

// Whether the stop from `s` is a rise and the final ramp with the motion going on forwards (its
// point into `rise`).
bool rises_forwards(const Along& s, double jerk, double g, const nc::detail::StopBounds& b,
                    nc::detail::StopAlong& rise) {
  return nc::detail::natural_velocity(s.v, s.a, jerk) > 0.0 &&
         nc::detail::stop_point_rise(s.v, s.a, g, b, rise);
}

}  // namespace

TEST_CASE("stop_point_rise: the rise-and-ramp stop point in closed form, where that is the shape",
          "[profile][stop_point]") {
  long rises = 0, shape_differs = 0, distance_differs = 0, slope_differs = 0, plain_differs = 0;
  for_each_draw(0xC105EDull, [&](const Draw& d, const nc::detail::StopBounds& b,
                                 profile_problems::Rng&) {
    nc::detail::StopAlong rise{0.0, 0.0, 0.0};
    const bool on_rise = nc::detail::stop_point_rise(d.v, d.a, d.g, b, rise);
    const nc::detail::StopAlong along = nc::detail::stop_point_along(d.v, d.a, d.g, b);
    // stop_point_along's rise shape, by its own decisions (mirrored frame s).
    const double s = nc::detail::natural_velocity(d.v, d.a, d.limits.jerk) > 0.0 ? -1.0 : 1.0;
    const double vm = s * d.v;
    const double am = s * d.a;
    const double meet2 = 0.5 * (am * am - 2.0 * d.limits.jerk * vm);
    const bool expected =
        !(am > b.am_limit) &&
        meet2 > nc::detail::kStopRel * (am * am + 2.0 * d.limits.jerk * std::abs(vm)) &&
        std::sqrt(meet2) <= d.limits.deceleration && (std::sqrt(meet2) - am) / d.limits.jerk > 0.0;
    if (on_rise != expected) ++shape_differs;
    const double closed = nc::detail::stop_distance_closed(d.v, d.a, b);
    const double integrated = nc::detail::stop_distance_of(d.v, d.a, b);
    if (!expected && closed != integrated) ++plain_differs;
    if (!on_rise || !expected) return;
    ++rises;
    const double m = std::sqrt(meet2);
    const double scale = std::pow(std::abs(am) + m, 3) / (d.limits.jerk * d.limits.jerk);
    if (!(std::abs(rise.distance - along.distance) <= 1e-12 * scale)) ++distance_differs;
    if (closed != rise.distance) ++plain_differs;
    const double tol_d = 1e-14 * (std::abs(along.d) + std::abs(along.dd));
    if (!(std::abs(rise.d - along.d) <= tol_d &&
          std::abs(rise.dd - along.dd) <= 1e-14 * std::abs(along.dd) + tol_d)) {
      ++slope_differs;
    }
  });
  CHECK(rises > 30'000);
  CHECK(shape_differs == 0);
  CHECK(distance_differs == 0);
  CHECK(slope_differs == 0);
  CHECK(plain_differs == 0);
}

TEST_CASE("stop_point_along: on the rise-hold-ramp stop S is the quartic of its four derivatives",
          "[profile][stop_point]") {
  long quartics = 0, compared = 0, off = 0, left_shape = 0, wrong = 0;
  for_each_draw(
      0x4A271Cull, [&](const Draw& d, const nc::detail::StopBounds& b, profile_problems::Rng& rng) {
        const nc::detail::StopAlong at0 = nc::detail::stop_point_along(d.v, d.a, d.g, b);
        if (!at0.quartic) return;
        ++quartics;
        if (!nc::detail::stop_has_hold_shape(d.v, d.a, at0.frame, b)) ++wrong;
        // Steps along the push up to the time scale of the stop itself (A- / J) and of the velocity
        // (|v| / A-).
        const double span =
            std::max(d.limits.deceleration / d.limits.jerk, std::abs(d.v) / d.limits.deceleration);
        for (int i = 0; i < 4; ++i) {
          const double h = rng.sign() * span * rng.log_uniform(1e-6, 1.0);
          const double a_h = d.a + d.g * h;
          const double v_h = d.v + h * (d.a + 0.5 * d.g * h);
          const double p_h = h * (d.v + h * (0.5 * d.a + h * d.g / 6.0));
          if (!nc::detail::stop_has_hold_shape(v_h, a_h, at0.frame, b)) {
            // Off the shape stop_point_along does not mark the point quartic in that frame.
            const nc::detail::StopAlong there = nc::detail::stop_point_along(v_h, a_h, d.g, b);
            if (there.quartic && there.frame == at0.frame) ++left_shape;
            continue;
          }
          ++compared;
          const double exact = p_h + nc::detail::stop_point_along(v_h, a_h, d.g, b).distance;
          const double t1 = at0.d * h;
          const double t2 = at0.dd * h * h / 2.0;
          const double t3 = at0.d3 * h * h * h / 6.0;
          const double t4 = at0.d4 * h * h * h * h / 24.0;
          const double poly = at0.distance + t1 + t2 + t3 + t4;
          const double scale = std::abs(at0.distance) + std::abs(t1) + std::abs(t2) + std::abs(t3) +
                               std::abs(t4) + std::abs(p_h) + std::abs(exact);
          if (!(std::abs(poly - exact) <= 1e-10 * scale)) ++off;
        }
      });
  CHECK(quartics > 20'000);
  CHECK(compared > 20'000);
  CHECK(wrong == 0);
  CHECK(left_shape == 0);
  CHECK(off == 0);
}

TEST_CASE("switch_on_rise: the switch on a hold or a rise where the stop is a rise and the ramp",
          "[profile][stop_point]") {
  SwitchTally tally;
  for_each_piece(
      0x5EED5Eull, [&](const Draw& d, const nc::detail::StopBounds& b, const Piece& piece) {
        const double g = piece.g, t_piece = piece.length, tau = piece.tau;
        // S (relative to the piece's start) where the stop is a rise and the ramp, going forwards.
        auto stop_point = [&](double t, double& out) {
          const Along s = along_piece(d, g, t);
          nc::detail::StopAlong along{0.0, 0.0, 0.0};
          if (!rises_forwards(s, d.limits.jerk, g, b, along)) return false;
          out = s.p + along.distance;
          return true;
        };
        double s_root = 0.0, s_end = 0.0;
        if (!stop_point(tau, s_root) || !stop_point(t_piece, s_end) || !(s_end >= s_root)) return;
        const double x = nc::detail::switch_on_rise({0.0, d.v, d.a}, t_piece, g, s_end - s_root, b);
        tally.judge(x, piece, s_root, std::abs(s_end), stop_point);
      });
  CHECK(tally.found > 20'000);
  CHECK(tally.missed < tally.found / 100);
  CHECK(tally.off == 0);
}

TEST_CASE("switch_from the piece's start: the switch where the start and the root have the shape",
          "[profile][stop_point]") {
  SwitchTally tally;
  long beyond = 0, beyond_taken = 0;
  for_each_piece(0x57A27ull, [&](const Draw& d, const nc::detail::StopBounds& b,
                                 const Piece& piece) {
    const double g = piece.g, t_piece = piece.length, tau = piece.tau;
    // S (relative to the piece's start), and whether the stop there is a rise and the ramp
    // going forwards.
    auto stop_point = [&](double t, double& out) {
      const Along s = along_piece(d, g, t);
      nc::detail::StopAlong rise{0.0, 0.0, 0.0};
      const bool shape = rises_forwards(s, d.limits.jerk, g, b, rise);
      out = s.p + nc::detail::stop_point_along(s.v, s.a, g, b).distance;
      return shape;
    };
    double s_start = 0.0, s_root = 0.0;
    if (!stop_point(0.0, s_start)) return;
    const bool root_shape = stop_point(tau, s_root);
    if (!(s_root > s_start)) return;
    const double x = nc::detail::switch_from({0.0, d.v, d.a}, 0.0, g, s_start - s_root, false, b);
    if (!root_shape) {
      // The stop has left the shape before the root (a rise to A- and a hold there): no start,
      // or one at the root all the same (within rounding of the shape's boundary).
      ++beyond;
      if (x == x && !(std::abs(x - tau) <= 1e-6 * t_piece)) ++beyond_taken;
      return;
    }
    tally.judge(x, piece, s_root, std::abs(s_start) + std::abs(s_root), stop_point);
  });
  CHECK(tally.found > 20'000);
  CHECK(tally.missed < tally.found / 100);
  CHECK(tally.off == 0);
  CHECK(beyond > 1'000);
  CHECK(beyond_taken == 0);
}
