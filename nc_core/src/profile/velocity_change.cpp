// The time-optimal velocity change's entries (profile/velocity_walk.hpp walks it).
#include "profile/velocity_change.hpp"

#include "profile/push_scan.hpp"
#include "profile/velocity_walk.hpp"

namespace nc::detail {

// Each entry is flattened (issue 17): the walk, its sink and what they call (the push scan's
// stop points, stop_distance_of among them) are inlined into one body per sink, without the calls
// between them. Measured with callgrind (planner_instructions, instructions per plan): any state
// to rest 1647.7 -> 1584.7, to a velocity 601 -> 577, passing at a velocity 7989 -> 7713; the
// same operations, so the same profiles bit for bit.
[[gnu::flatten]] int velocity_change(double v0, double a0, double v1, const Bounds& bounds,
                                     Piece* out) noexcept {
  walk::ArraySink sink{out};
  return walk::change(v0, a0, v1, bounds, sink);
}

[[gnu::flatten]] int velocity_change(double v0, double a0, double v1, const Bounds& bounds,
                                     PushScan& scan) noexcept {
  return walk::change(v0, a0, v1, bounds, scan);
}

double pieces_distance(double v0, double a0, const Piece* pieces, int count) noexcept {
  KinematicState s{0.0, v0, a0};
  // Integrated exactly as Profile::append does (same snapping), so that a root found on these
  // distances is a root of the profile that is built.
  for (int i = 0; i < count; ++i)
    s = advance_change(s, pieces[i]);
  return s.p;
}

}  // namespace nc::detail
