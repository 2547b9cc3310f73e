// The running table of a master-axis job and where its sampling stands: the seed's "runtime
// table" (seed 000 §2.1, "Procedure"), part of MasterJob (master_job.hpp).
//
// A table is one planned Profile sampled once per NC cycle at t = k·T + offset, k = 1, 2, …
// since it was installed (k = 0 is the set state it started from). Sampling by product, never by
// summing T, keeps the end exact and the runs repeatable. When k·T reaches the duration the
// table outputs its exact final state and, if it is the job's final table, the set-value
// generation has ended. A velocity table never ends: past its end the profile extrapolates the
// hold. A passing table (BufferMode blending) goes on at its end velocity the same way.
//
// Online decoupling (SPEC C4, seed 000 §3.2.3): a former slave's copy of its head's table runs
// through a chain of affine levels (p = f·p + o, v = f·v, a = f·a), the arithmetic its slave
// links did, so it goes on bit for bit; the next install drops the chain.
//
// Cycle functions only: noexcept, no allocation.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "nc_core/profile.hpp"
#include "profile/profile_sample.hpp"

namespace nc::detail {

enum class JobKind : uint8_t {
  kNone,           // no job: the set values hold
  kPosition,       // MoveAbsolute / MoveRelative / MoveModulo
  kVelocity,       // MoveVelocity (continuous motion)
  kHalt,           // MC_Halt
  kStop,           // MC_Stop (locks the axis)
  kEmergencyStop,  // the axis's error ramp (no command number)
};

// Start time of the final deceleration of a table that ends at rest: the trailing segments on
// which |v| does not grow (a constant-velocity segment ends the run); 0 for an empty table.
double brake_start(const Profile& profile) noexcept;
// The highest path velocity |v| of a table (at segment ends and where a = 0 inside a segment).
double peak_speed(const Profile& profile) noexcept;
// The table holds or touches the path velocity `level` (|v| = level with a = 0) somewhere:
// "the new velocity level is achievable" of seed 000 §2.2 / §2.4.
bool reaches_level(const Profile& profile, double level) noexcept;
// The level a table planned with velocity limit V reaches: V when it reaches V (up to
// rounding), otherwise its peak — seed 000 §2.2's level "calculated and possibly reduced at the
// start".
double reduced_level(const Profile& profile, double velocity) noexcept;
// The table never moves against `direction` (+1 / -1): |v| along it is >= 0 everywhere, up to
// rounding (a blend's pass must not overshoot and return).
bool moves_only_along(const Profile& profile, double direction) noexcept;

// The affine levels between a head job's table and a decoupled slave, applied head first.
struct DecouplingChain {
  static constexpr std::size_t kMaxLevels = 8;
  struct Level {
    double factor = 1.0;
    double offset = 0.0;
  };
  Level levels[kMaxLevels];
  std::size_t count = 0;

  // False when full (a cascade deeper than kMaxLevels / 2 axes).
  bool push(double factor, double offset) noexcept {
    if (count == kMaxLevels) return false;
    levels[count++] = Level{factor, offset};
    return true;
  }
  double total_factor() const noexcept {
    double f = 1.0;
    for (std::size_t i = 0; i < count; ++i)
      f *= levels[i].factor;
    return f;
  }
  double position(double p) const noexcept {
    for (std::size_t i = 0; i < count; ++i)
      p = levels[i].factor * p + levels[i].offset;
    return p;
  }
  KinematicState state(KinematicState s) const noexcept {
    for (std::size_t i = 0; i < count; ++i) {
      s = KinematicState{levels[i].factor * s.p + levels[i].offset, levels[i].factor * s.v,
                         levels[i].factor * s.a};
    }
    return s;
  }
  double velocity(double v) const noexcept {
    for (std::size_t i = 0; i < count; ++i)
      v = levels[i].factor * v;
    return v;
  }
};

class JobTable {
 public:
  // Takes over a planned profile, sampled from k = 0 at its start state.
  void install(const Profile& profile) noexcept;
  // No table: nothing ended or reached.
  void clear() noexcept;
  // Online decoupling: the output so far and all later samples go through `chain` (after the
  // table's own chain).
  void follow(const DecouplingChain& chain) noexcept;
  // Right after install(): the table's t = 0 lies `offset` s after the last sample (offset <= 0:
  // the table began between two cycles), so sample k is taken at k·T + offset.
  void set_time_offset(double offset) noexcept {
    offset_ = offset;
    steady_until_ = 0;
  }
  // The time of the last sample on the table's clock (k·T + offset).
  double sample_time(double cycle_time) const noexcept {
    return static_cast<double>(k_) * cycle_time + offset_;
  }
  // The table's end state (a pass: the target at its pass velocity), its duration, and whether
  // it ends with a velocity.
  KinematicState end_state() const noexcept { return profile_.final_state(); }
  double duration() const noexcept { return profile_.duration(); }
  bool holds_velocity() const noexcept { return profile_.holds_velocity(); }

  // The next cycle's set values of a job of `kind` (`final`: this table ends the job). Call once
  // per cycle.
  KinematicState advance(JobKind kind, bool final, double cycle_time) noexcept;
  // A sample time this close below the duration counts as the end: k·T and a planned duration
  // that are equal on paper may differ in the last bits.
  static constexpr double kEndTolerance = 1e-9;  // s
  double jerk() const noexcept { return jerk_; }
  // The set state output last (the table's start state right after install()).
  KinematicState state() const noexcept { return state_; }
  // The final table has reached its end: its final state is output.
  bool generation_ended() const noexcept { return ended_; }
  // A velocity table holds its (non-zero) constant velocity.
  bool velocity_reached() const noexcept { return reached_; }
  // Levels of the online-decoupling chain in force (0: the table is the axis's own).
  std::size_t chain_depth() const noexcept { return chain_.count; }

 private:
  friend class SteadyLane;  // reads the sampling state, keeps steady_until_ (steady_lane.hpp)

  uint64_t k_ = 0;
  double offset_ = 0.0;  // s; see set_time_offset()
  bool ended_ = false;
  bool reached_ = false;
  // chain_ has levels (chain_.count != 0): a sample reads this, in the header's line, instead of
  // the count behind the profile (one cache line fewer per cycle).
  bool chained_ = false;
  // The samples up to k = steady_until_ lie inside the current segment, before the end: the
  // steady lane takes the next one while k_ < steady_until_ (0: none). Set by SteadyLane::enter(),
  // 0 again on every change of the table (steady_lane.hpp).
  uint32_t steady_until_ = 0;
  double jerk_ = 0.0;
  KinematicState state_{};
  Profile profile_{};        // a cycle reads its header (first) and one segment, not all of it
  DecouplingChain chain_{};  // empty except after an online decoupling, until the next install

  // s through the chain (without levels s itself, as the chain's loop gives it; so the jerk too).
  KinematicState through_chain(const KinematicState& s) const noexcept {
    return chained_ ? chain_.state(s) : s;
  }
};

// Inline: the set-value phase of every moving axis calls it in every cycle.
inline KinematicState JobTable::advance(JobKind kind, bool final, double cycle_time) noexcept {
  const auto passing = [&]() noexcept {
    return kind == JobKind::kPosition && profile_.holds_velocity();
  };
  if (ended_ && !passing()) {
    jerk_ = 0.0;
    state_ = through_chain(profile_.final_state());
    return state_;
  }
  ++k_;
  const double t = sample_time(cycle_time);
  const double end = profile_.duration();
  const bool at_end = t >= end - kEndTolerance * std::max(1.0, end);
  if (kind == JobKind::kVelocity) {
    // The hold goes on past the end of the profile: at() extrapolates it. A hold at 0 (override
    // 0) is not "reached": InVelocity means moving at the commanded level.
    if (at_end) reached_ = profile_.final_state().v != 0.0;
    double jerk = 0.0;
    const KinematicState sample = profile_.at(t, jerk);
    jerk_ = at_end ? 0.0 : (chained_ ? chain_.velocity(jerk) : jerk);
    state_ = through_chain(sample);
    return state_;
  }
  if (at_end) {
    // A rest for override 0 holds its end but does not end the job.
    ended_ = final;
    jerk_ = 0.0;
    // A pass goes on at its velocity.
    state_ = through_chain(passing() ? profile_.at(t) : profile_.final_state());
    return state_;
  }
  double jerk = 0.0;
  // One search for p, v, a and j, inline (Profile::at(t, jerk)).
  const KinematicState sample = ProfileSample::at(profile_, t, jerk);
  jerk_ = chained_ ? chain_.velocity(jerk) : jerk;
  state_ = through_chain(sample);
  return state_;
}

}  // namespace nc::detail
