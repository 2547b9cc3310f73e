// plan_position's scan along the push (internal): the sink the push's velocity change is walked
// into. It follows the push piece by piece, with the point S where the shortest stop from each
// piece's end ends, and stops the walk at the first piece whose end reaches the goal (the switch
// lies in it): the rest of the push towards ±V is not walked (issue 17). The pieces are those of
// the whole walk (bit for bit); S is stop_distance_closed's (the rise-and-ramp stop in closed
// form).
#pragma once

#include "profile/kinematics.hpp"
#include "profile/stop_point.hpp"

namespace nc::detail {

struct PushScan {
  Piece* pieces;     // room for kMaxChangePieces
  KinematicState s;  // the start of the current piece (after the last piece when not found)
  double s_here;     // S at s
  double goal;
  const StopBounds& stop;
  double s_next = 0.0;  // S at the end of the piece holding the switch
  int count = 0;        // pieces so far; the last one holds the switch when found
  bool found = false;

  void put(const Piece& piece) noexcept {
    pieces[count++] = piece;
    const KinematicState next = advance_change(s, piece);
    const double s_end = next.p + stop_distance_closed(next.v, next.a, stop);
    if (s_end >= goal) {
      s_next = s_end;
      found = true;
      return;
    }
    s = next;
    s_here = s_end;
  }
  bool stopped() const noexcept { return found; }
};

}  // namespace nc::detail
