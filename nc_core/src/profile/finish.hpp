// The last step of plan_position (both calls): the profile from its pieces (internal).
#pragma once

#include <cmath>

#include "nc_core/profile.hpp"
#include "profile/kinematics.hpp"
#include "profile/profile_writer.hpp"
#include "profile/validate.hpp"

namespace nc::detail {

// The push before a cruise at V (mirrored frame): velocity_change takes a start within its
// rounding tolerance of (V, 0) as there and gives no piece, but a cruise must hold a = 0 — a start
// acceleration of rounding size carried through a long cruise moves the position by a·t²/2 (fuzz
// finding P3: a = -1.5e-23 for 1.8e19 s, 2.5e15 mm). One ramp at J takes such an a to 0 exactly.
// Returns the push's new piece count.
inline int settle_push(Piece* push, int n_push, double a, double jerk) noexcept {
  if (n_push != 0 || a == 0.0) return n_push;
  push[0] = Piece{std::abs(a) / jerk, a > 0.0 ? -jerk : jerk, 0.0, NAN};
  return 1;
}

// After the head that `writer` has appended (ProfileWriter::append) to a profile from
// ProfileWriter::begin(start, end) (kInlineAnchor) or begin() (otherwise): appends a cruise and the
// tail that `append_tail` appends to the writer it is given (ProfileWriter::append_anchored), and
// closes exactly on `end` = (target, v_end, 0), holding v_end past the end when `holds`. Everything
// after the head is anchored back from that exact end, so both ends are exact relative to their own
// values. kInlineAnchor: the anchoring inlined (ProfileWriter::anchor_to_end) or called
// (Profile::anchor_to_end; the end-velocity planner, where inlining it cost 27 instructions per
// plan).
template <bool kInlineAnchor, class AppendTail>
inline void finish_tail(Profile& profile, ProfileWriter& writer, const KinematicState& end,
                        double cruise, const AppendTail& append_tail, bool holds) noexcept {
  // The head is integrated forward: each segment's p takes the previous one's t, p, v, a and j,
  // so a value that is not finite anywhere in the head leaves the head's end p not finite.
  const double head_end_p = writer.end_state().p;
  const std::size_t tail_start = writer.count();
  writer.append_anchored(cruise, 0.0, NAN, NAN);
  append_tail(writer);
  if constexpr (kInlineAnchor) {
    writer.close_at_end(holds);
    ProfileWriter::anchor_to_end(profile, tail_start);
  } else {
    writer.close(&end, holds);
    profile.anchor_to_end(tail_start);
  }
  // The tail is integrated backward from the exact end the same way, down to the first segment
  // the anchor placed. The last line of defence against overflow with extreme (finite) inputs, a
  // profile whose numbers are not all finite is never handed out: the head's end, that p and the
  // total duration stand for a test of every segment's values (issue 17: it was a loop over them).
  const std::size_t first = tail_start > 0 ? tail_start : 1;
  const double tail_start_p = first < profile.segment_count() ? profile.segment(first).p : 0.0;
  if (!std::isfinite(head_end_p + tail_start_p + profile.duration())) {
    ProfileWriter::fail(profile, ErrorCode::kPlannerNoSolution);
  }
}

// The profile from `start`: the head pieces (mirrored back by `dir`), then finish_tail. The start
// and the exact end are set on construction (issue 17: stored once, not first cleared) where the
// anchoring is inlined; the end-velocity planner's many calls build as before (its plans took 8
// instructions more with the end set first).
template <bool kInlineAnchor = true, class AppendTail>
inline Profile finish_with(const KinematicState& start, double target, double v_end, double dir,
                           const Piece* head, int n_head, double cruise,
                           const AppendTail& append_tail, bool holds) noexcept {
  const KinematicState end{target, v_end, 0.0};
  // One returned object (no copy of the profile on return).
  Profile profile = kInlineAnchor ? ProfileWriter::begin(start, end) : ProfileWriter::begin();
  ProfileWriter writer =
      kInlineAnchor ? ProfileWriter(profile, ProfileBuild{}) : ProfileWriter(profile, start);
  for (int i = 0; i < n_head; ++i)
    writer.append(head[i], dir);
  finish_tail<kInlineAnchor>(profile, writer, end, cruise, append_tail, holds);
  return profile;
}

// The same with the head that `append_head` appends to the writer it is given: rest to rest's
// pieces as it computes them (issue 17: they went to an array first).
template <class AppendHead, class AppendTail>
inline Profile finish_around(const KinematicState& start, double target, double v_end,
                             const AppendHead& append_head, double cruise,
                             const AppendTail& append_tail, bool holds) noexcept {
  const KinematicState end{target, v_end, 0.0};
  Profile profile = ProfileWriter::begin(start, end);
  ProfileWriter writer(profile, ProfileBuild{});
  append_head(writer);
  finish_tail<true>(profile, writer, end, cruise, append_tail, holds);
  return profile;
}

// finish_with for a tail of pieces (mirrored back by `dir`).
template <bool kInlineAnchor = true>
inline Profile finish(const KinematicState& start, double target, double v_end, double dir,
                      const Piece* head, int n_head, double cruise, const Piece* tail, int n_tail,
                      bool holds) noexcept {
  return finish_with<kInlineAnchor>(
      start, target, v_end, dir, head, n_head, cruise,
      [&](ProfileWriter& writer) {
        for (int i = 0; i < n_tail; ++i)
          writer.append_anchored(tail[i], dir);
      },
      holds);
}

// A sink of pieces (stop_change, velocity_change.cpp's sinks) that appends them to a profile's
// anchored tail, mirrored back by `dir`.
struct AnchoredSink {
  ProfileWriter& writer;
  double dir;
  void put(const Piece& piece) noexcept { writer.append_anchored(piece, dir); }
};

}  // namespace nc::detail
