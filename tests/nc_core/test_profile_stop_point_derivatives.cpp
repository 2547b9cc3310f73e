// The stop point along a push with written-out derivatives (stop_point_along, issue 17) against
// the jet arithmetic it replaces in plan_position's root finding: over 300 000 random states,
// pushes (jerk +J, 0, -J) and bounds of the planner's range, the stop distance is
// stop_distance_of's bit for bit (the profile does not change), S' and S'' agree with
// v + D' and a + D'' of stop_distance_of<Jet> to 1e-6 of the terms they are made of (the jets
// lose more than that only where those terms cancel), and a push at +J in the stop's frame
// (the stop's own rise) leaves S exactly in place (S' = 0) on the written-out shapes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "profile/stop_point.hpp"
#include "profile_problems.hpp"

TEST_CASE("stop_point_along: the stop distance bit for bit, its derivatives as the jets'",
          "[profile][stop_point]") {
  using nc::detail::Jet;
  profile_problems::Rng rng(0x57095EEDull);
  long distance_differs = 0, slope_differs = 0, curvature_differs = 0, rise_moves = 0;
  long rises = 0;
  for (int k = 0; k < 300'000; ++k) {
    const nc::Limits l = profile_problems::random_limits(rng);
    const nc::detail::Bounds bounds{l.acceleration, l.deceleration, l.jerk};
    const nc::detail::StopBounds b(bounds);
    const double v = rng.sign() * rng.log_uniform(1e-3, 1e5);
    double a = rng.sign() * std::max(l.acceleration, l.deceleration) * rng.uniform(0.0, 1.2);
    if (rng.chance(0.2)) a = rng.sign() * l.deceleration;  // at A- (the stop's hold, no rise)
    const double u = rng.uniform();
    const double g = u < 0.3 ? 0.0 : (u < 0.65 ? l.jerk : -l.jerk);

    const Jet jet = nc::detail::stop_distance_of(Jet{v, a, g}, Jet{a, g, 0.0}, b);
    const nc::detail::StopAlong along = nc::detail::stop_point_along(v, a, g, b);
    if (along.distance != jet.x) ++distance_differs;
    const double slope = v + jet.d;
    const double curvature = a + jet.dd;
    const double slope_scale = std::abs(along.d) + std::abs(v) + a * a / l.jerk;
    const double curvature_scale =
        std::abs(along.dd) + std::abs(a) + std::abs(g) + std::abs(v * g) / l.deceleration;
    if (!(std::abs(along.d - slope) <= 1e-6 * slope_scale)) ++slope_differs;
    if (!(std::abs(along.dd - curvature) <= 1e-6 * curvature_scale)) ++curvature_differs;
    // In the stop's mirrored frame (s = -1 when the natural velocity is > 0) a push at +J is
    // the stop's own rise, on the written-out shapes (a below A-, not on the final curve).
    const double s = nc::detail::natural_velocity(v, a, l.jerk) > 0.0 ? -1.0 : 1.0;
    const double meet2 = 0.5 * (a * a - 2.0 * l.jerk * (s * v));
    if (s * g == l.jerk && s * a < l.deceleration &&
        meet2 > 1e-12 * (a * a + l.jerk * std::abs(v))) {
      ++rises;
      if (along.d != 0.0) ++rise_moves;
    }
  }
  CHECK(distance_differs == 0);
  CHECK(slope_differs == 0);
  CHECK(curvature_differs == 0);
  CHECK(rises > 10'000);
  CHECK(rise_moves == 0);
}
