// The planners' direct access to the Profile they build (internal). Profile's builder functions
// (reset, append, close) are written once here; a planner builds through a ProfileWriter, which
// keeps the running end state in locals (registers) and stores the profile's fields at close.
#pragma once

#include <cmath>
#include <cstddef>

#include "nc_core/profile.hpp"
#include "profile/kinematics.hpp"

namespace nc::detail {

class ProfileWriter {
 public:
  // A Profile for a ProfileWriter(profile, start) to build: its fields are left for the writer
  // (the constructor, close() or fail() sets each before the profile is handed out).
  static Profile begin() noexcept { return Profile(ProfileBuild{}); }
  // The same with the start state and the exact final state set, for ProfileWriter(profile,
  // ProfileBuild{}) and close_at_end(): the profile finish() builds.
  static Profile begin(const KinematicState& start, const KinematicState& end) noexcept {
    return Profile(ProfileBuild{}, start, end);
  }
  // Starts `profile` at `start` (Profile::reset).
  ProfileWriter(Profile& profile, const KinematicState& start) noexcept
      : profile_(profile), end_(start) {
    profile.start_ = start;
    profile.error_ = ErrorCode::kNone;
    profile.cursor_ = 0;
  }
  // Starts a profile from begin(start, end) at its start state.
  ProfileWriter(Profile& profile, ProfileBuild) noexcept : profile_(profile), end_(profile.start_) {
    profile.error_ = ErrorCode::kNone;
    profile.cursor_ = 0;
  }
  // Continues a profile that Profile::append is building.
  explicit ProfileWriter(Profile& profile) noexcept
      : profile_(profile),
        count_(profile.segments_.count),
        duration_(profile.duration_),
        end_(profile.end_) {}

  // Profile::append: exact_a / exact_v replace the integrated end values unless NaN.
  bool append(double duration, double jerk, double exact_a, double exact_v) noexcept {
    if (!(duration > 0.0)) return true;
    if (!put(duration, jerk)) return false;
    end_ = advance(end_, jerk, duration);
    if (!std::isnan(exact_a)) end_.a = exact_a;
    if (!std::isnan(exact_v)) end_.v = exact_v;
    duration_ += duration;
    return true;
  }
  // append() for a piece of positive duration whose end acceleration is given (every piece of a
  // velocity change): the same segment and end state, without the tests for those two.
  bool append_change_piece(double duration, double jerk, double exact_a, double exact_v) noexcept {
    if (!put(duration, jerk)) return false;
    end_ = advance(end_, jerk, duration);
    end_.a = exact_a;
    if (!std::isnan(exact_v)) end_.v = exact_v;
    duration_ += duration;
    return true;
  }
  // A piece mirrored by `dir` (+1 or -1).
  bool append(const Piece& piece, double dir) noexcept {
    return append(piece.t, dir * piece.j, dir * piece.a_end, dir * piece.v_end);
  }

  // A segment that Profile::anchor_to_end will place (it is at or after the anchored part's first
  // segment): the anchor recomputes its p, and its v unless that is an exact 0, back from the exact
  // end, so only a and the time are integrated here (issue 17: the tail was integrated twice). The
  // segments after it start at p = NaN and at the piece's exact v (NaN where it gives none), which
  // the anchor replaces; the running end state is the exact end given to close().
  bool append_anchored(double duration, double jerk, double exact_a, double exact_v) noexcept {
    if (!(duration > 0.0)) return true;
    if (!put(duration, jerk)) return false;
    end_.a = std::isnan(exact_a) ? end_.a + jerk * duration : exact_a;
    end_.p = NAN;
    end_.v = exact_v;
    duration_ += duration;
    anchored_ = true;
    return true;
  }
  bool append_anchored(const Piece& piece, double dir) noexcept {
    return append_anchored(piece.t, dir * piece.j, dir * piece.a_end, dir * piece.v_end);
  }

  // Makes `profile` what Profile::failure(code) returns, in place (no assignment of a whole
  // Profile on the planners' return path).
  static void fail(Profile& profile, ErrorCode code) noexcept {
    profile.segments_.count = 0;
    profile.duration_ = 0.0;
    profile.start_ = KinematicState{};
    profile.final_ = KinematicState{};
    profile.end_ = KinematicState{};
    profile.error_ = code;
    profile.holds_velocity_ = false;
    profile.cursor_ = 0;
  }

  // Profile::anchor_to_end, inline for the planners (issue 17: a call into profile.cpp before).
  static void anchor_to_end(Profile& profile, std::size_t first) noexcept {
    // The first segment keeps the start state itself.
    if (first == 0) first = 1;
    // Velocities first (back from the final one), then positions from those: a state sampled on
    // the tail is then consistent with the exact end to the rounding of its own values, not of the
    // largest values the profile went through before. A segment built to start at v = 0 exactly
    // (a crossing of v = 0, set exactly by the planner) keeps that start: back from a large final
    // velocity the crossing would carry that velocity's rounding, and a long hold before it would
    // multiply it into the positions (fuzz finding P18: 1 ulp of 600 mm/s, 1.1e-13, over a hold at
    // A- = 3.6e-9 of 9500 s moved the switch by 1.08e-9 mm).
    double next_p = profile.final_.p;
    double next_v = profile.final_.v;
    for (std::size_t i = profile.segments_.count; i > first; --i) {
      Segment& seg = profile.segments_.items[i - 1];
      const double t = seg.duration;
      if (seg.v != 0.0) seg.v = next_v - t * (seg.a + 0.5 * seg.j * t);
      seg.p = next_p - t * (seg.v + t * (0.5 * seg.a + t * (seg.j / 6.0)));
      next_v = seg.v;
      next_p = seg.p;
    }
  }

  std::size_t count() const noexcept { return count_; }
  const KinematicState& end_state() const noexcept { return end_; }

  // Stores the running state into the profile (all Profile::append needs between calls).
  void store() const noexcept {
    profile_.segments_.count = count_;
    profile_.duration_ = duration_;
    profile_.end_ = end_;
  }
  // Profile::close: the final state is `exact_end` if given, else the integrated end (after
  // append_anchored, the running end state too).
  void close(const KinematicState* exact_end, bool holds_velocity) const noexcept {
    store();
    if (anchored_ && exact_end != nullptr) profile_.end_ = *exact_end;
    profile_.final_ = exact_end != nullptr ? *exact_end : end_;
    profile_.holds_velocity_ = holds_velocity;
  }
  // close(&end, holds_velocity) for a profile from begin(start, end), whose final state (and, after
  // append_anchored, running end state) is that end already.
  void close_at_end(bool holds_velocity) const noexcept {
    profile_.segments_.count = count_;
    profile_.duration_ = duration_;
    if (!anchored_) profile_.end_ = end_;
    profile_.holds_velocity_ = holds_velocity;
  }

 private:
  Profile& profile_;
  // The next segment, from the running end state and time (whole-object assignment: begins the
  // element's lifetime in the uncleared storage); false when the profile is full. The caller
  // then moves the end state and the time on.
  bool put(double duration, double jerk) noexcept {
    if (count_ == Profile::kMaxSegments) return false;
    profile_.segments_.items[count_++] = Segment{duration_, duration, end_.p, end_.v, end_.a, jerk};
    return true;
  }

  std::size_t count_ = 0;
  double duration_ = 0.0;
  KinematicState end_;
  bool anchored_ = false;  // append_anchored was used
};

}  // namespace nc::detail
