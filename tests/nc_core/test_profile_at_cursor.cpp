// Profile::at() and jerk_at() go on from the segment of their previous call (issue 8 item 5: a
// cycle-by-cycle sampling is O(1)). The cursor must not change a single bit: for every t, in any
// order of calls (forwards as the NC samples, backwards, random, at every segment start, before
// the start, past the end, NaN), the state is the one today's scan back from the last segment
// gives. That scan is written out below as the reference. Copies and assignments keep the
// segments in use and sample identically.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "nc_core/profile.hpp"
#include "profile_problems.hpp"

namespace {

using nc::KinematicState;
using nc::Profile;
using profile_problems::Rng;

#ifdef NCSDK_SANITIZED
constexpr long kProblems = 300;
#else
constexpr long kProblems = 3'000;
#endif
constexpr int kSamples = 97;

// The same constant-jerk expression as the planner's (profile/kinematics.hpp), so that bits agree.
KinematicState advance(const KinematicState& s, double j, double t) {
  return KinematicState{s.p + t * (s.v + t * (0.5 * s.a + t * (j / 6.0))),
                        s.v + t * (s.a + 0.5 * j * t), s.a + j * t};
}

// The segment holding t by a scan back from the last segment (at() before the cursor).
std::size_t scan(const Profile& prof, double t) {
  std::size_t i = prof.segment_count() - 1;
  while (i > 0 && prof.segment(i).t0 > t)
    --i;
  return i;
}

KinematicState reference_at(const Profile& prof, double t) {
  const double T = prof.duration();
  const KinematicState f = prof.final_state();
  if (t >= T) {
    if (!prof.holds_velocity()) return f;
    return KinematicState{f.p + f.v * (t - T), f.v, 0.0};
  }
  if (!(t > 0.0)) return prof.start_state();
  const std::size_t i = scan(prof, t);
  const nc::Segment& seg = prof.segment(i);
  const double tau = t - seg.t0;
  if (tau <= 0.5 * seg.duration) return advance({seg.p, seg.v, seg.a}, seg.j, tau);
  const bool last = i + 1 == prof.segment_count();
  const KinematicState end =
      last ? f
           : KinematicState{prof.segment(i + 1).p, prof.segment(i + 1).v, prof.segment(i + 1).a};
  const double t_end = last ? T : prof.segment(i + 1).t0;
  return advance(end, seg.j, std::min(t - t_end, 0.0));
}

double reference_jerk(const Profile& prof, double t) {
  if (prof.segment_count() == 0 || t < 0.0 || t >= prof.duration()) return 0.0;
  return prof.segment(scan(prof, t)).j;
}

// Bitwise equality (so -0.0 != 0.0 and NaNs of one pattern are equal).
bool same_bits(double x, double y) {
  return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y);
}
bool same_bits(const KinematicState& x, const KinematicState& y) {
  return same_bits(x.p, y.p) && same_bits(x.v, y.v) && same_bits(x.a, y.a);
}
bool same_bits(const nc::Segment& x, const nc::Segment& y) {
  return same_bits(x.t0, y.t0) && same_bits(x.duration, y.duration) && same_bits(x.p, y.p) &&
         same_bits(x.v, y.v) && same_bits(x.a, y.a) && same_bits(x.j, y.j);
}

// Sampling times: a cycle grid (the NC's order), every segment start, outside the profile, NaN.
std::vector<double> sample_times(const Profile& prof) {
  const double T = prof.duration();
  std::vector<double> ts;
  for (int k = 0; k <= kSamples + 2; ++k)
    ts.push_back(static_cast<double>(k) * T / kSamples);
  for (std::size_t i = 0; i < prof.segment_count(); ++i) {
    ts.push_back(prof.segment(i).t0);
    ts.push_back(prof.segment(i).t0 + 0.5 * prof.segment(i).duration);
  }
  ts.push_back(-1.0);
  ts.push_back(0.0);
  ts.push_back(T);
  ts.push_back(2.0 * T + 1.0);
  ts.push_back(NAN);
  return ts;
}

struct Mismatches {
  long at = 0;
  long jerk = 0;
};

void compare_in_order(const Profile& prof, const std::vector<double>& ts, Mismatches& m) {
  for (double t : ts) {
    if (!same_bits(prof.at(t), reference_at(prof, t))) ++m.at;
    if (!same_bits(prof.jerk_at(t), reference_jerk(prof, t))) ++m.jerk;
  }
}

void compare_all_orders(const Profile& prof, Rng& rng, Mismatches& m) {
  std::vector<double> ts = sample_times(prof);
  compare_in_order(prof, ts, m);  // forwards (the cursor follows)
  const std::vector<double> backwards(ts.rbegin(), ts.rend());
  compare_in_order(prof, backwards, m);
  for (std::size_t i = ts.size(); i > 1; --i) {  // a random order (Fisher-Yates)
    const auto j = static_cast<std::size_t>(rng.uniform() * static_cast<double>(i));
    std::swap(ts[i - 1], ts[j < i ? j : i - 1]);
  }
  compare_in_order(prof, ts, m);
  // A copy (assigned with the cursor somewhere in the middle) samples the same.
  Profile copy;
  copy = prof;
  compare_in_order(copy, ts, m);
}

}  // namespace

TEST_CASE("at() and jerk_at() give today's bits for every t in any order of calls",
          "[profile][at]") {
  const uint64_t seed = profile_problems::suite_seed(0xA7C0ull);
  Rng rng(seed);
  Mismatches m;
  long profiles = 0;
  for (long k = 0; k < kProblems; ++k) {
    const profile_problems::Problem pr = profile_problems::random_position_problem(rng, 0.3);
    const Profile position = nc::plan_position(pr.start, pr.target, pr.limits);
    const double v1 = rng.uniform(-pr.limits.velocity, pr.limits.velocity);
    const Profile velocity = nc::plan_velocity(pr.start, v1, pr.limits);
    const Profile stop = nc::plan_stop(pr.start, pr.limits.deceleration, pr.limits.jerk);
    for (const Profile* prof : {&position, &velocity, &stop}) {
      REQUIRE(prof->ok());
      if (prof->segment_count() == 0) continue;
      ++profiles;
      compare_all_orders(*prof, rng, m);
    }
  }
  INFO("seed " << seed << ", " << profiles << " profiles");
  CHECK(profiles > 2 * kProblems);
  CHECK(m.at == 0);
  CHECK(m.jerk == 0);
}

TEST_CASE("a copied or assigned profile has the same segments, ends and samples", "[profile][at]") {
  const nc::Limits l{2000.0, 10000.0, 8000.0, 50000.0};
  const Profile a = nc::plan_position({3.0, 150.0, -900.0}, 640.0, l);
  REQUIRE(a.segment_count() >= 4);
  Profile b = nc::plan_velocity({0.0, 0.0, 0.0}, -400.0, l);  // fewer segments, then overwritten
  REQUIRE(b.segment_count() < a.segment_count());
  b = a;
  const Profile c(a);
  const Profile* copies[] = {&b, &c};
  for (const Profile* x : copies) {
    REQUIRE(x->segment_count() == a.segment_count());
    for (std::size_t i = 0; i < a.segment_count(); ++i) {
      CHECK(same_bits(x->segment(i), a.segment(i)));
    }
    CHECK(same_bits(x->duration(), a.duration()));
    CHECK(same_bits(x->final_state(), a.final_state()));
    CHECK(same_bits(x->start_state(), a.start_state()));
    CHECK(x->holds_velocity() == a.holds_velocity());
    CHECK(x->ok());
    for (int k = 0; k <= 50; ++k) {
      const double t = a.duration() * k / 50.0;
      CHECK(same_bits(x->at(t), a.at(t)));
    }
  }
  const Profile failed = Profile::failure(nc::ErrorCode::kJerkNotAllowed);
  b = failed;
  CHECK_FALSE(b.ok());
  CHECK(b.error() == nc::ErrorCode::kJerkNotAllowed);
  CHECK(b.segment_count() == 0);
}
