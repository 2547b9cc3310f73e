// The seed's Dynamics figures I-III (seed 000 §2.1): rest-to-rest moves whose durations the seed
// states. Each figure runs in both directions and from several start positions; the duration must
// match to 1e-9 relative, the end state must be exact, and the limits must hold at every segment
// boundary (exactly, per segment) and at every 1 ms sample.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "nc_core/profile.hpp"
#include "profile_checks.hpp"

namespace {

using nc::KinematicState;
using nc::Limits;
using nc::Profile;

struct Figure {
  const char* name;
  Limits limits;
  double distance;       // mm, from the seed's "from 0.0 mm to ... mm"
  double duration;       // s, stated by the seed
  double peak_velocity;  // mm/s, V where it is reached, otherwise the largest reachable
};

// Peak velocities where V is not reached follow from distance = vp·(vp/A + A/J) (symmetric
// trapezoidal ramps): Dynamics 2.1: vp² + 1250·vp - 5e6 = 0; Dynamics 3.3: vp² + 500·vp - 4e6 = 0.
const Figure kFigures[] = {
    {"Dynamics 1.1", {2000.0, 5000.0, 5000.0, 50000.0}, 1000.0, 1.0, 2000.0},
    {"Dynamics 1.2", {2000.0, 5000.0, 10000.0, 50000.0}, 1000.0, 0.95, 2000.0},
    {"Dynamics 1.3", {2000.0, 15000.0, 15000.0, 50000.0}, 1000.0, 0.9, 2000.0},
    {"Dynamics 2.1",
     {2000.0, 5000.0, 5000.0, 20000.0},
     1000.0,
     1.178708781,
     0.5 * (-1250.0 + std::sqrt(1250.0 * 1250.0 + 2e7))},
    {"Dynamics 2.2", {2000.0, 5000.0, 5000.0, 50000.0}, 1000.0, 1.0, 2000.0},
    {"Dynamics 2.3", {2000.0, 5000.0, 5000.0, 100000.0}, 1000.0, 0.95, 2000.0},
    {"Dynamics 3.1", {1500.0, 5000.0, 5000.0, 50000.0}, 800.0, 0.933333333, 1500.0},
    {"Dynamics 3.2", {1750.0, 5000.0, 5000.0, 50000.0}, 800.0, 0.907142857, 1750.0},
    {"Dynamics 3.3",
     {2000.0, 5000.0, 5000.0, 50000.0},
     800.0,
     0.906225775,
     0.5 * (-500.0 + std::sqrt(500.0 * 500.0 + 16e6))},
};

const double kStartPositions[] = {0.0, 12345.678901, -98765.4321, 1e5 + 0.125};

// The largest |v| of a profile, exactly: segment ends and the zero of a inside a segment.
double peak_speed(const Profile& prof) {
  double peak = 0.0;
  for (std::size_t i = 0; i < prof.segment_count(); ++i) {
    const nc::Segment& s = prof.segment(i);
    peak = std::max(peak, std::fabs(profile_checks::advance(s, s.duration).v));
    peak = std::max(peak, std::fabs(s.v));
    if (s.j != 0.0) {
      const double tau = -s.a / s.j;
      if (tau > 0.0 && tau < s.duration)
        peak = std::max(peak, std::fabs(profile_checks::advance(s, tau).v));
    }
  }
  return peak;
}

// Runs one figure from p0 in direction `sign` and checks everything the figure states.
void check_figure(const Figure& fig, double p0, double sign) {
  const KinematicState start{p0, 0.0, 0.0};
  const double target = p0 + sign * fig.distance;
  const Limits& l = fig.limits;
  INFO(fig.name << " from " << p0 << " to " << target);
  const Profile prof = nc::plan_position(start, target, l);
  REQUIRE(prof.ok());

  // Duration as the seed states it (its 9 digits are within 1e-9 relative of the exact value).
  CHECK(prof.duration() == Approx(fig.duration).epsilon(1e-9));

  // End state exact: the final state is the target at rest, and at(T) and later return it.
  CHECK(prof.final_state().p == target);
  CHECK(prof.final_state().v == 0.0);
  CHECK(prof.final_state().a == 0.0);
  CHECK(prof.at(prof.duration()).p == target);
  CHECK(prof.at(prof.duration() + 1.0).p == target);
  CHECK(prof.at(prof.duration() + 1.0).v == 0.0);

  // Limits at every segment boundary and inside every segment, continuity, integrated end.
  const profile_checks::Finding f = profile_checks::check_position_profile(prof, start, target, l);
  INFO(profile_checks::to_string(f));
  CHECK(f.ok());

  // The velocity peak is V where the figure reaches it, otherwise the largest reachable one.
  CHECK(peak_speed(prof) == Approx(fig.peak_velocity).epsilon(1e-9));

  // Every 1 ms sample (the NC cycle): within V and the path-relative acceleration bound, moving
  // only toward the target (no overshoot, no reversal), never outside [p0, target].
  const double tol = profile_checks::end_position_tolerance(start, target);
  int bad_samples = 0;
  double last_progress = 0.0;
  const int samples = static_cast<int>(std::ceil(prof.duration() / 1e-3)) + 1;
  for (int k = 0; k <= samples; ++k) {
    const double t = 1e-3 * k;
    const KinematicState x = prof.at(t);
    const double progress = sign * (x.p - p0);
    const bool good =
        profile_checks::finite(x) && std::fabs(x.v) <= l.velocity * (1.0 + 1e-9) &&
        std::fabs(x.a) <= profile_checks::acceleration_bound(x.v, x.a, l) * (1.0 + 1e-9) &&
        sign * x.v >= -1e-9 * l.velocity && progress >= last_progress - tol &&
        progress <= fig.distance + tol;
    if (!good && bad_samples++ < 3) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "sample t=%.17g p=%.17g v=%.17g a=%.17g", t, x.p, x.v, x.a);
      FAIL_CHECK(buf);
    }
    last_progress = progress;
  }
  CHECK(bad_samples == 0);
}

void check_figures(int first, int last) {
  for (int i = first; i <= last; ++i) {
    for (double p0 : kStartPositions) {
      check_figure(kFigures[i], p0, +1.0);
      check_figure(kFigures[i], p0, -1.0);
    }
  }
}

}  // namespace

TEST_CASE("Dynamics I: larger acceleration limits give 1.0 s, 0.95 s (A- 10000) and 0.9 s",
          "[profile][seed]") {
  check_figures(0, 2);
}

TEST_CASE("Dynamics II: jerk 20000, 50000, 100000 give 1.178708781 s, 1.0 s and 0.95 s",
          "[profile][seed]") {
  check_figures(3, 5);
}

TEST_CASE(
    "Dynamics III: V 1500, 1750, 2000 over 800 mm give 0.933333333, 0.907142857, "
    "0.906225775 s",
    "[profile][seed]") {
  check_figures(6, 8);
}

TEST_CASE("Dynamics 1.2: the asymmetric deceleration shortens only the braking phase",
          "[profile][seed]") {
  // A+ 5000 over 0 → 2000 mm/s: 0.4 s + 0.1 s; A- 10000 over 2000 → 0: 0.2 s + 0.2 s; the
  // remaining 100 mm at 2000 mm/s: 0.05 s. So v = 2000 from t = 0.5 to t = 0.55.
  const Limits l{2000.0, 5000.0, 10000.0, 50000.0};
  const Profile prof = nc::plan_position({0.0, 0.0, 0.0}, 1000.0, l);
  REQUIRE(prof.ok());
  const KinematicState cruise_start = prof.at(0.5);
  const KinematicState cruise_end = prof.at(0.55);
  CHECK(cruise_start.v == Approx(2000.0).epsilon(1e-9));
  CHECK(cruise_start.p == Approx(500.0).epsilon(1e-9));
  CHECK(cruise_end.v == Approx(2000.0).epsilon(1e-9));
  CHECK(cruise_end.p == Approx(600.0).epsilon(1e-9));
  // Deceleration reaches -A- = -10000 at 0.55 + 0.2 s and holds it (A-²/J = 2000 = V: just).
  CHECK(prof.at(0.75).a == Approx(-10000.0).epsilon(1e-9));
  CHECK(prof.at(0.3).a == Approx(5000.0).epsilon(1e-9));
}
