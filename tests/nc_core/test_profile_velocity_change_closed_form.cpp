// The velocity change where no bound change at v = 0 lies ahead (issue 17: written in closed form
// by velocity_change's upward walk), against the textbook shapes of seed 000 §2.1 computed here
// on their own, over 400 000 random changes of the planner's range. In the frame where the change
// is upward (v -> w > v_nat), with the bound C (A+ while |v| grows, A- while it shrinks) and the
// meeting acceleration m = sqrt(a^2 / 2 + J (w - v)):
//   - m <= C: a rise at +J to m, the final ramp at -J (2 pieces);
//   - m > C: a rise at +J to C (none when a starts at C), a hold at C up to the final curve
//     w - C^2 / 2J, the final ramp C / J (3 pieces, 2 from the bound).
// Each piece's jerk exactly, its duration within 1e-9 of the whole change's duration, the end
// exactly (w, 0) as the last piece gives it and within 1e-9 of it when the pieces are integrated.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "profile/velocity_change.hpp"
#include "profile_problems.hpp"

namespace {

struct Expected {
  int count = 0;
  double t[3] = {0.0, 0.0, 0.0};
  double j[3] = {0.0, 0.0, 0.0};
  int shape = 0;  // 0 rise-ramp, 1 rise-hold-ramp, 2 hold-ramp
};

}  // namespace

TEST_CASE("velocity_change without a bound change ahead gives the textbook shapes",
          "[profile][velocity_change]") {
  profile_problems::Rng rng(profile_problems::suite_seed(0x5EEDC10ull));
  long kept = 0, shapes[3] = {0, 0, 0};
  long count_differs = 0, jerk_differs = 0, time_differs = 0, end_differs = 0;
  for (int k = 0; k < 400'000; ++k) {
    const nc::Limits l = profile_problems::random_limits(rng);
    const double jerk = l.jerk;
    const double sign_v = rng.sign();
    const double v1 = sign_v * rng.uniform(0.02, 1.0) * l.velocity;
    const double v0 = sign_v * rng.uniform(0.02, 1.0) * l.velocity;
    double a0 = rng.sign() * rng.uniform(0.0, 1.0) * std::min(l.acceleration, l.deceleration);
    // The upward frame (exact: multiplication by +-1).
    const double s = v1 >= nc::detail::natural_velocity(v0, a0, jerk) ? 1.0 : -1.0;
    const double cap = s * v0 > 0.0 ? l.acceleration : l.deceleration;
    if (rng.chance(0.1)) a0 = s * cap;  // starts at the bound: hold, then the final ramp
    if (v1 < nc::detail::natural_velocity(v0, a0, jerk) ? s > 0.0 : s < 0.0) continue;
    const double v = s * v0;
    const double a = s * a0;
    const double w = s * v1;
    // No crossing of v = 0 (v and w on one side, and a rise from a < 0 keeps v off 0).
    if (v > 0.0 && a < 0.0 && !(a * a < 0.999 * 2.0 * jerk * v)) continue;
    if (!(v * w > 0.0)) continue;
    const double scale = std::max({std::abs(v), std::abs(w), a * a / jerk});
    if (v < 0.0 && !(w < -1e-3 * scale)) continue;
    const double m2 = 0.5 * a * a + jerk * (w - v);
    if (!(m2 > 0.0)) continue;
    const double m = std::sqrt(m2);
    // Away from the decisions' edges (on the final curve, meeting the bound).
    if (a > 0.0 && m - a <= 1e-6 * m) continue;
    if (std::abs(m - cap) <= 1e-6 * cap) continue;
    Expected e;
    if (m <= cap) {
      e = Expected{2, {(m - a) / jerk, m / jerk, 0.0}, {jerk, -jerk, 0.0}, 0};
    } else {
      const double v_cap = v + (cap * cap - a * a) / (2.0 * jerk);
      const double hold = (w - cap * cap / (2.0 * jerk) - v_cap) / cap;
      if (a == cap) {
        e = Expected{2, {hold, cap / jerk, 0.0}, {0.0, -jerk, 0.0}, 2};
      } else {
        e = Expected{3, {(cap - a) / jerk, hold, cap / jerk}, {jerk, 0.0, -jerk}, 1};
      }
    }
    double total = 0.0;
    for (int i = 0; i < e.count; ++i)
      total += e.t[i];
    if (std::min({e.t[0], e.t[1], e.count == 3 ? e.t[2] : 1.0}) <= 1e-6 * total) continue;
    ++kept;
    ++shapes[e.shape];

    nc::detail::Piece pieces[nc::detail::kMaxChangePieces];
    const int n =
        nc::detail::velocity_change(v0, a0, v1, {l.acceleration, l.deceleration, jerk}, pieces);
    if (n != e.count) {
      ++count_differs;
      continue;
    }
    nc::KinematicState x{0.0, v0, a0};
    for (int i = 0; i < n; ++i) {
      if (pieces[i].j != s * e.j[i]) ++jerk_differs;
      if (!(std::abs(pieces[i].t - e.t[i]) <= 1e-9 * total)) ++time_differs;
      x = nc::KinematicState{0.0, x.v + pieces[i].t * (x.a + 0.5 * pieces[i].j * pieces[i].t),
                             x.a + pieces[i].j * pieces[i].t};
    }
    const double v_scale = std::max(std::abs(v0), std::abs(v1)) + a0 * a0 / jerk;
    if (pieces[n - 1].v_end != v1 || pieces[n - 1].a_end != 0.0 ||
        !(std::abs(x.v - v1) <= 1e-9 * v_scale) || !(std::abs(x.a) <= 1e-9 * cap)) {
      ++end_differs;
    }
  }
  INFO("kept " << kept << ": rise-ramp " << shapes[0] << ", rise-hold-ramp " << shapes[1]
               << ", hold-ramp " << shapes[2]);
  CHECK(shapes[0] > 20'000);
  CHECK(shapes[1] > 20'000);
  CHECK(shapes[2] > 2'000);
  CHECK(count_differs == 0);
  CHECK(jerk_differs == 0);
  CHECK(time_differs == 0);
  CHECK(end_differs == 0);
}
