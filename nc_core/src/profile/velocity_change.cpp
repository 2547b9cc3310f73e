// The time-optimal velocity change's entries (profile/velocity_walk.hpp walks it).
#include "profile/velocity_change.hpp"

#include "profile/velocity_walk.hpp"

namespace nc::detail {

// Flattened (issue 17): the walk and its sink inlined into one body, without the calls between
// them (the end-velocity planner's changes: 7989 -> 7713 instructions per plan passing at a
// velocity; the same operations, the same pieces bit for bit).
[[gnu::flatten]] int velocity_change(double v0, double a0, double v1, const Bounds& bounds,
                                     Piece* out) noexcept {
  walk::ArraySink sink{out};
  return walk::change(v0, a0, v1, bounds, sink);
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
