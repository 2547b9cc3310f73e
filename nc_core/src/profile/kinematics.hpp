// Constant-jerk kinematics shared by the planner's steps (internal).
#pragma once

#include <cmath>

#include "nc_core/profile.hpp"

namespace nc::detail {

// The state after moving for time t with constant jerk j from s.
inline KinematicState advance(const KinematicState& s, double j, double t) noexcept {
  return KinematicState{s.p + t * (s.v + t * (0.5 * s.a + t * (j / 6.0))),
                        s.v + t * (s.a + 0.5 * j * t), s.a + j * t};
}

// One constant-jerk piece of a plan before it becomes a Profile segment.
struct Piece {
  double t = 0.0;
  double j = 0.0;
  double a_end = NAN;  // exact acceleration at the end where known (else NaN)
  double v_end = NAN;  // exact velocity at the end where known (else NaN)
};

// Room for N pieces, not filled on construction (a planner writes each piece before reading
// it; clearing the room costs as much as a short plan's arithmetic).
template <int N>
struct PieceBuffer {
  PieceBuffer() noexcept {}  // user-provided: leaves the pieces unwritten
  union {
    Piece items[N];
  };
};

// The acceleration limits of a plan (path-relative, seed 000 §2.1) and the jerk.
struct Bounds {
  double ap = 0.0;  // A+: bound on |a| while |v| grows
  double am = 0.0;  // A-: bound on |a| while |v| shrinks
  double j = 0.0;   // J
};

// The state at the end of a piece, with the exactly known end values set the way
// Profile::append sets them (planning and the built profile round identically).
inline KinematicState advance(const KinematicState& s, const Piece& piece) noexcept {
  KinematicState e = advance(s, piece.j, piece.t);
  if (!std::isnan(piece.a_end)) e.a = piece.a_end;
  if (!std::isnan(piece.v_end)) e.v = piece.v_end;
  return e;
}

// advance(s, piece) for a piece of a velocity change (velocity_change.hpp), whose end acceleration
// is always given: the same state without testing a_end.
inline KinematicState advance_change(const KinematicState& s, const Piece& piece) noexcept {
  KinematicState e = advance(s, piece.j, piece.t);
  e.a = piece.a_end;
  if (!std::isnan(piece.v_end)) e.v = piece.v_end;
  return e;
}

}  // namespace nc::detail
