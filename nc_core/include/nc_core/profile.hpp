// The planner: time-optimal jerk-limited motion profiles, as pure functions.
//
// Kinematic state in, limits in, a Profile out. Nothing here knows of axes, cycles or time since
// start; the master-axis job (seed 000 §2.1 "runtime table") owns a Profile and samples it.
// All functions are cycle functions: noexcept, no allocation. Invalid inputs give a Profile with
// ok() == false and an ErrorCode, never a NaN.
//
// Limits are path-relative (seed 000 §2.1, SPEC B2): while |v| grows |a| <= acceleration (A+),
// while |v| shrinks |a| <= deceleration (A-), always |v| <= velocity (V) and |da/dt| <= jerk (J).
// One exception of rounding size: a state whose ramp to a = 0 at J would pass the end velocity by
// less than 1e-13 of the motion's own scale lands on it with one ramp whose jerk is above J by at
// most about 4e-13 (relative), instead of a reversal of that size (every state on that ramp then
// plans the same ramp, so re-planning gives the rest of the profile).
#pragma once

#include <cstddef>
#include <limits>

#include "plc_interface/error_code.hpp"

namespace nc {

using ErrorCode = plc::ErrorCode;

namespace detail {
class ProfileWriter;  // the planners' inline builder (nc_core/src/profile/profile_writer.hpp)
class ProfileSample;  // at() inline for the cycle's sample (nc_core/src/profile/profile_sample.hpp)
struct ProfileBuild {};  // tag of the Profile a ProfileWriter starts (internal)
}  // namespace detail

struct KinematicState {
  double p = 0.0;
  double v = 0.0;
  double a = 0.0;
};

struct Limits {
  double velocity = 0.0;      // V  > 0
  double acceleration = 0.0;  // A+ > 0
  double deceleration = 0.0;  // A- > 0
  double jerk = 0.0;          // J  > 0
};

// One piece of constant jerk: its start time, length and the state at its start.
struct Segment {
  double t0 = 0.0;
  double duration = 0.0;
  double p = 0.0;
  double v = 0.0;
  double a = 0.0;
  double j = 0.0;
};

namespace detail {

// The segments of a Profile (internal): a fixed capacity that is not cleared on construction
// (planning would pay for clearing all of it; only [0, count) is ever written before it is read),
// copied by the segments in use only (a velocity change has at most a handful of the capacity).
class SegmentTable {
 public:
  static constexpr std::size_t kCapacity = 24;

  SegmentTable() noexcept : count(0) {}
  explicit SegmentTable(ProfileBuild) noexcept {}  // count left to the ProfileWriter
  SegmentTable(const SegmentTable& other) noexcept;
  SegmentTable& operator=(const SegmentTable& other) noexcept;
  ~SegmentTable() = default;

  std::size_t count;  // first: with the Profile's header on the line of the first segment
  union {
    Segment items[kCapacity];
  };
};

}  // namespace detail

// A fixed-capacity sequence of constant-jerk segments starting at t = 0, as the planners return it.
// Copies move only the segments in use. The planners build it through an internal writer
// (nc_core/src/profile/profile_writer.hpp); reset/append/close/anchor_to_end are the same builder
// for code outside the planner that joins profiles.
class Profile {
 public:
  static constexpr std::size_t kMaxSegments = detail::SegmentTable::kCapacity;

  // Empty: no segments, duration 0, ok(), the start and final states at rest at 0.
  Profile() noexcept
      : duration_(0.0), cursor_(0), error_(ErrorCode::kNone), holds_velocity_(false) {}

  static Profile failure(ErrorCode code) noexcept;

  bool ok() const noexcept { return error_ == ErrorCode::kNone; }
  ErrorCode error() const noexcept { return error_; }
  double duration() const noexcept { return duration_; }

  // State at time t; t < 0 gives the start state, t >= duration() the final state (for a
  // velocity profile, see holds_velocity()). Exact at segment boundaries: each segment stores its
  // start state, its first half is evaluated forward from it and its second half back from the
  // next segment's start (or the exact final state), so at(T - tiny) approaches the target.
  // at() and jerk_at() go on from the segment of the previous call (O(1) when sampled cycle by
  // cycle; any order of t gives the same results): const, but not for concurrent calls on one
  // Profile.
  KinematicState at(double t) const noexcept;
  double jerk_at(double t) const noexcept;
  // at(t), with jerk_at(t) into `jerk`: one segment search for both (the per-cycle sample).
  KinematicState at(double t, double& jerk) const noexcept;
  KinematicState start_state() const noexcept { return start_; }
  KinematicState final_state() const noexcept { return final_; }
  // True for plan_velocity's profiles: past the end the motion goes on at the final velocity
  // (continuous motion holds its velocity), so at(t) extrapolates p = p_end + v_end (t - T).
  bool holds_velocity() const noexcept { return holds_velocity_; }

  std::size_t segment_count() const noexcept { return segments_.count; }
  const Segment& segment(std::size_t i) const noexcept { return segments_.items[i]; }

  // Builder: start at a state, append constant-jerk pieces, then close.
  void reset(const KinematicState& start) noexcept;
  // Appends a piece (false when full; zero lengths skipped). exact_a / exact_v, unless NaN, are
  // the end acceleration / velocity the caller knows exactly (a bound, 0, V), set instead of the
  // integrated value so that rounding does not drift along long holds.
  bool append(double duration, double jerk,
              double exact_a = std::numeric_limits<double>::quiet_NaN(),
              double exact_v = std::numeric_limits<double>::quiet_NaN()) noexcept;
  // Ends the profile; when `exact_end` is given, the final state is set to it (removing the
  // rounding of the integration) — the planners pass the exact target state.
  void close(const KinematicState* exact_end = nullptr, bool holds_velocity = false) noexcept;
  // Re-anchors the velocities and positions of segments [first, end) backwards from the final
  // state, so that the end of a profile is exact relative to its target even after a long
  // excursion (rounding then stays relative to the values near each end). Call after close().
  void anchor_to_end(std::size_t first) noexcept;

 private:
  friend class detail::ProfileWriter;
  friend class detail::ProfileSample;

  // The profile a ProfileWriter starts (ProfileWriter::begin): the header's fields and the segment
  // count are left to the writer, which sets each of them before the profile is handed out (issue
  // 17: the empty profile's fields, stored and then overwritten, cost about 11 stores per plan).
  // The second form also sets the start and the exact final state where the planner knows both.
  explicit Profile(detail::ProfileBuild) noexcept : segments_(detail::ProfileBuild{}) {}
  Profile(detail::ProfileBuild, const KinematicState& start, const KinematicState& end) noexcept
      : segments_(detail::ProfileBuild{}), start_(start), final_(end), end_(end) {}

  // What at() reads first, then the segments: a cycle's sample touches the header's line and the
  // segment's, not the end of the table.
  // Set by the default constructor; the writer's constructor leaves them to the writer.
  double duration_;
  mutable std::size_t cursor_;  // the segment of the last at() / jerk_at()
  ErrorCode error_;
  bool holds_velocity_;
  detail::SegmentTable segments_;
  KinematicState start_{};
  KinematicState final_{};
  KinematicState end_{};  // the running end state while building (integrated from the last piece)
};

// From any state to rest at `target` in the least time. Start states outside the limits are
// first brought back inside them as fast as the limits allow (|v| > V lands on V from above,
// without undershoot); targets the axis cannot stop before produce one continuous profile that
// reverses through v = 0. The final state is exactly (target, 0, 0). A target within 64 ulp of
// max(|p|, |target|, stop distance) of the shortest stop's end is that end (the shortest stop):
// re-planning from a state sampled on a final ramp must not turn rounding into extra motion.
Profile plan_position(const KinematicState& start, double target, const Limits& limits) noexcept;

// The same to (target, target_velocity, 0), target_velocity signed (issue 14: a target passed at
// a velocity; 0 is the call above, bit for bit). |target_velocity| > V gives kVelocityNotAllowed,
// a non-finite one kParameterNotFinite. Every end state is reached: a target behind the point
// where the direct change to target_velocity ends gives a push the other way first (below the
// end velocity, through v = 0 if needed: a run-up backwards). The final state is exactly
// (target, target_velocity, 0); past duration() at(t) goes on at that velocity (holds_velocity()
// is true when target_velocity != 0). The optimal duration jumps where the direct change ends
// (beyond it only a reversal reaches the target): a target within that point's rounding (up to
// 1e-11 of the positions) is taken as it; re-plan a passing profile only when the target changes.
Profile plan_position(const KinematicState& start, double target, double target_velocity,
                      const Limits& limits) noexcept;

// From any state to the constant velocity `velocity` (either sign, |velocity| <= V, otherwise
// kVelocityNotAllowed), then hold it. A lower level is reached from above without undershoot.
// duration() is the time until the velocity is reached; past it at(t) extrapolates at the held
// velocity (holds_velocity() is true).
Profile plan_velocity(const KinematicState& start, double velocity, const Limits& limits) noexcept;

// The shortest stop from any state with deceleration limit `deceleration` and jerk `jerk`. Where
// an overshoot through v = 0 cannot be avoided, `deceleration` also bounds |a| beyond it.
Profile plan_stop(const KinematicState& start, double deceleration, double jerk) noexcept;

}  // namespace nc
