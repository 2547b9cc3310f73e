// The planners' last line of defence against overflow (profile/finish.hpp, issue 17): a profile
// with a number that is not finite is never handed out (kPlannerNoSolution). finish() no longer
// tests every segment's values but the head's forward end, the first anchored segment's p and the
// total duration; a value that overflows or is NaN anywhere in the head or in the anchored tail
// must still reach one of them (the head and the tail are each integrated along a chain).
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "profile/finish.hpp"

namespace {

using nc::detail::Piece;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Plans start -> rest at `target` through `head`, a cruise and `tail` (each a single piece list).
nc::Profile build(const Piece* head, int n_head, double cruise, const Piece* tail, int n_tail) {
  const nc::KinematicState start{0.0, 1.0, 0.0};
  return nc::detail::finish(start, 5.0, 0.0, 1.0, head, n_head, cruise, tail, n_tail, false);
}

}  // namespace

TEST_CASE("finish: a finite profile is handed out", "[profile][finish]") {
  const Piece head[] = {{1.0, 1.0, kNaN, kNaN}, {1.0, -1.0, 0.0, kNaN}};
  const Piece tail[] = {{1.0, -1.0, kNaN, kNaN}, {1.0, 1.0, 0.0, 0.0}};
  const nc::Profile p = build(head, 2, 0.5, tail, 2);
  CHECK(p.ok());
  CHECK(p.segment_count() == 5);
}

TEST_CASE("finish: an overflow or NaN in the head fails the plan", "[profile][finish]") {
  const Piece tail[] = {{1.0, -1.0, kNaN, kNaN}, {1.0, 1.0, 0.0, 0.0}};
  // p overflows at the end of the first piece (t^3 / 6 = inf); the next piece starts from it.
  const Piece overflow[] = {{1e300, 1.0, kNaN, kNaN}, {1.0, -1.0, 0.0, kNaN}};
  CHECK(build(overflow, 2, 0.0, tail, 2).error() == nc::ErrorCode::kPlannerNoSolution);
  // ...and as the head's last piece, whose end only the running state holds.
  CHECK(build(overflow, 1, 0.0, tail, 2).error() == nc::ErrorCode::kPlannerNoSolution);
  // A NaN jerk in the first piece, its end a and v given exactly (only p carries it on).
  const Piece nan_jerk[] = {{1.0, kNaN, 1.0, 1.5}, {1.0, -1.0, 0.0, kNaN}};
  CHECK(build(nan_jerk, 2, 0.0, tail, 2).error() == nc::ErrorCode::kPlannerNoSolution);
}

TEST_CASE("finish: an overflow or NaN in the anchored tail fails the plan", "[profile][finish]") {
  const Piece head[] = {{1.0, 1.0, kNaN, kNaN}};
  // The anchor's v and p overflow back from the exact end over a piece of 1e300 s.
  const Piece long_tail[] = {{1.0, -1.0, kNaN, kNaN}, {1e300, 1.0, 0.0, 0.0}};
  CHECK(build(head, 1, 0.0, long_tail, 2).error() == nc::ErrorCode::kPlannerNoSolution);
  // A NaN jerk in the last piece, whose end values are exact: the anchor carries it back in p.
  const Piece nan_tail[] = {{1.0, -1.0, kNaN, kNaN}, {1.0, kNaN, 0.0, 0.0}};
  CHECK(build(head, 1, 0.5, nan_tail, 2).error() == nc::ErrorCode::kPlannerNoSolution);
  // Without a head the first segment keeps the start state; a NaN jerk there reaches the next
  // segment's a (integrated), which the anchor carries into its p.
  const Piece nan_first[] = {{1.0, kNaN, kNaN, kNaN}, {1.0, 1.0, 0.0, 0.0}};
  CHECK(build(nullptr, 0, 0.0, nan_first, 2).error() == nc::ErrorCode::kPlannerNoSolution);
  // An infinite cruise.
  const Piece tail[] = {{1.0, -1.0, kNaN, kNaN}, {1.0, 1.0, 0.0, 0.0}};
  CHECK(build(head, 1, std::numeric_limits<double>::infinity(), tail, 2).error() ==
        nc::ErrorCode::kPlannerNoSolution);
}
