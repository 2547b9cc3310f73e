// Step 1 of every plan: the time-optimal change from a state (v0, a0) to a velocity v1 with
// a = 0 (internal). plan_velocity is this step plus a hold; plan_stop is it with v1 = 0;
// plan_position uses it for the push towards ±V and for the stop at the target.
#pragma once

#include <cmath>

#include "profile/kinematics.hpp"
#include "profile/profile_writer.hpp"

namespace nc::detail {

// At most this many pieces: bring a back under its bound, rise, hold, ramp down before v = 0
// (A+ < A-), hold, rise again after v = 0 (A- < A+), hold, final ramp — plus slack.
inline constexpr int kMaxChangePieces = 10;

// Relative tolerance of the walk's decisions (at a bound, on a curve, v_nat = v1): values within
// it of a boundary are taken as on it, so re-planning from a sampled state follows the same path.
inline constexpr double kDecisionTolerance = 1e-13;

// The velocity at which a reaches 0 when it is brought there with maximum jerk. Every caller
// compares it (with 0 or a velocity): |a| as std::abs (one mask; issue 17: the select of -a or a
// took five instructions per call, about a dozen calls per plan) differs from that select only in
// the sign of a zero result, which no comparison sees.
inline double natural_velocity(double v, double a, double jerk) noexcept {
  return v + a * std::abs(a) / (2.0 * jerk);
}

// Writes the pieces of the time-optimal change (v0, a0) -> (v1, 0) to `out` (capacity
// kMaxChangePieces) and returns their number, or -1 if the walk did not close (never expected).
// Every piece has t > 0 and its end acceleration (a_end); its end velocity where exactly known.
// Time-optimal: at every instant a is as large towards the needed sign as the path-relative
// bounds, the bound change at v = 0 and the final ramp allow. Start values outside the bounds are
// brought back at maximum jerk; the end velocity is never over- or undershot.
int velocity_change(double v0, double a0, double v1, const Bounds& bounds, Piece* out) noexcept;
// (plan_velocity and plan_stop append the pieces straight to their profile, plan_position hands
// them to its push scan, which may stop the walk early: walk::change with a walk::WriterSink or a
// PushScan, profile/velocity_walk.hpp, inlined into those planners.)

// Distance travelled along `pieces` of a velocity change (each gives its end acceleration: every
// piece velocity_change writes does) from velocity v0 and acceleration a0.
double pieces_distance(double v0, double a0, const Piece* pieces, int count) noexcept;

}  // namespace nc::detail
