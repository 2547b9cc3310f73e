// The master-axis job: the seed's "runtime table" (seed 000 §2.1, "Procedure") and what the
// online functions keep with it (seed 000 §2.2 … §2.4).
//
// A job owns one planned Profile and samples it once per NC cycle at t = k·T, k = 1, 2, … since
// the cycle in which the table was installed (k = 0 is the set state it started from, i.e. the
// previous cycle's set values). Sampling by product, never by summing T, keeps the end exact and
// the runs repeatable. When k·T reaches the profile's duration the job outputs the profile's exact
// final state and its set-value generation has ended. A velocity job never ends: it has "reached"
// its velocity and goes on extrapolating the hold.
//
// Online functions (override, new end position, new velocity) install a new table into the
// running job with replan(): same job, same command number, sampled from k = 0 again, starting
// at state() — the set state the job output last — so the set values stay continuous. A table
// that is not "final" is a rest for override 0: it brings the axis to rest on its path and then
// holds; the job does not end there but waits for the override to rise.
//
// Brake phase (seed 000 §2.2, §2.4): the final deceleration of a positioning table to its target,
// i.e. the trailing part of the table in which |v| only falls (down to rest at the target). It is
// found once per table (brake_start()); in_brake_phase() is true from its start on. A Halt or
// Stop planned in the brake phase is marked as braking too (mark_brake_phase()), so that no later
// stop sharpens it (seed 000 §2.2: no emergency stop in the brake phase).
//
// Online decoupling (SPEC C4, seed 000 §3.2.3): the former slave takes a copy of the job at the
// head of its cascade and runs it through a chain of affine levels (p = f·p + o, v = f·v,
// a = f·a), the same arithmetic its slave links did, so it goes on bit for bit as it would have
// as a slave; the first replan (override, stop, new end position) drops the chain.
//
// A passing table (BufferMode blending, docs/behaviour.md "BufferMode") ends at its target with a
// velocity. The buffered command takes over in the cycle whose sample passes that end: it is
// planned from the table's end state and sampled from the time since that end (a time offset),
// so the pass is exact. Past its end a pass left alone goes on at its velocity (the profile
// extrapolates).
//
// Cycle functions only: noexcept, no allocation.
#pragma once

#include <cstddef>
#include <cstdint>

#include "nc_core/profile.hpp"
#include "plc_interface/axis_ref.hpp"

namespace nc::detail {

enum class JobKind : uint8_t {
  kNone,           // no job: the set values hold
  kPosition,       // MoveAbsolute / MoveRelative / MoveModulo
  kVelocity,       // MoveVelocity (continuous motion)
  kHalt,           // MC_Halt
  kStop,           // MC_Stop (locks the axis)
  kEmergencyStop,  // the axis's error ramp (no command number)
};

// A new velocity waiting for its activation position (seed 000 §2.4, cases 1 and 5), or an
// instantaneous one suspended while the table is in its brake phase.
struct Activation {
  bool armed = false;
  bool immediate = false;  // due at once (case 2); waits only while in the brake phase
  double position = 0.0;   // APos
  double direction = 0.0;  // +1 / -1: due once the set position passes APos moving this way
  double velocity = 0.0;   // VNew
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
// PlcToNc.Override as a factor 0 … 1 (exactly 1 at 1'000'000).
inline double override_factor(uint32_t override_value) noexcept {
  return static_cast<double>(override_value) / static_cast<double>(plc::kOverrideFull);
}

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

class MasterJob {
 public:
  // Takes over a planned profile; the previous job is forgotten. The online data start from
  // the limits: user and reduced velocity = limits.velocity, direction from target_velocity
  // (+1 when 0), no pending activation, the current override counts as handled.
  void start(JobKind kind, uint16_t number, const Profile& profile, double target,
             double target_velocity, const Limits& limits) noexcept;
  void clear() noexcept;
  // A new table for the running job, planned from state(). `final`: it ends at the job's goal
  // (false: a rest for override 0).
  void replan(const Profile& profile, bool final) noexcept;
  // Online decoupling: this job (a copy of the head's) goes on through `chain`. Number, target,
  // levels, direction and a pending activation are transformed; `limits` (the velocity already
  // |total factor| × the head's) replaces the limits; `override_value` is the axis's own and
  // counts as handled (the table goes on unchanged).
  void follow(const DecouplingChain& chain, uint16_t number, const Limits& limits,
              uint32_t override_value) noexcept;
  // The whole running table counts as brake phase (a Halt / Stop planned in one).
  void mark_brake_phase() noexcept;
  // Right after start(): the table's t = 0 lies `offset` s after the last sample (offset <= 0:
  // the table began between two cycles), so sample k is taken at k·T + offset.
  void set_time_offset(double offset) noexcept { offset_ = offset; }
  // The time of the last sample on the running table's clock (k·T + offset).
  double sample_time(double cycle_time) const noexcept {
    return static_cast<double>(k_) * cycle_time + offset_;
  }
  // A passing table whose end falls within the next cycle.
  bool passes_in_next_cycle(double cycle_time) const noexcept;
  // The running table's end state (a pass: the target at its pass velocity).
  KinematicState table_end() const noexcept { return profile_.final_state(); }
  double table_duration() const noexcept { return profile_.duration(); }

  // The set values of the next cycle. Call once per cycle while kind() != kNone.
  KinematicState advance(double cycle_time) noexcept;
  double jerk() const noexcept { return jerk_; }
  // The set state output last (the table's start state right after start() / replan()).
  KinematicState state() const noexcept { return state_; }

  JobKind kind() const noexcept { return kind_; }
  void set_kind(JobKind kind) noexcept { kind_ = kind; }
  bool active() const noexcept { return kind_ != JobKind::kNone; }
  bool is_motion() const noexcept {
    return kind_ == JobKind::kPosition || kind_ == JobKind::kVelocity;
  }
  uint16_t number() const noexcept { return number_; }
  // A positioning whose table passes its target with a velocity (blending).
  bool passing() const noexcept { return kind_ == JobKind::kPosition && profile_.holds_velocity(); }
  // Set-value generation has ended (positioning, halt, stop): the final state is output.
  bool generation_ended() const noexcept { return ended_; }
  // A velocity job holds its (non-zero) constant velocity.
  bool velocity_reached() const noexcept { return reached_; }
  // The running table ends at the job's goal (false: a rest for override 0).
  bool final_table() const noexcept { return final_; }
  // The final deceleration to the target has begun (positioning tables, and a Halt / Stop
  // planned in one). Judged at the state output last.
  bool in_brake_phase(double cycle_time) const noexcept;
  double target() const noexcept { return target_; }
  double target_velocity() const noexcept { return target_velocity_; }
  const Limits& limits() const noexcept { return limits_; }
  uint64_t cycles() const noexcept { return k_; }
  // Levels of the online-decoupling chain in force (0: the table is the axis's own).
  std::size_t chain_depth() const noexcept { return chain_.count; }

  void set_target(double target) noexcept { target_ = target; }
  void set_target_velocity(double velocity) noexcept { target_velocity_ = velocity; }
  // The user's velocity V (limits().velocity follows it), the level reduced at the start (seed
  // 000 §2.2 override types 1 and 3) and the direction of travel (+1 / -1).
  void set_levels(double user_velocity, double reduced_velocity, double direction) noexcept;
  double user_velocity() const noexcept { return limits_.velocity; }
  double reduced_velocity() const noexcept { return reduced_velocity_; }
  double direction() const noexcept { return direction_; }

  // PlcToNc.Override, last valid value read (0 … 1'000'000); kept across jobs.
  void set_override(uint32_t value) noexcept { override_ = value; }
  uint32_t override_value() const noexcept { return override_; }
  // The override value the running table has answered (applied, or refused and not retried).
  void set_handled_override(uint32_t value) noexcept { handled_override_ = value; }
  uint32_t handled_override() const noexcept { return handled_override_; }

  Activation& activation() noexcept { return activation_; }
  const Activation& activation() const noexcept { return activation_; }

 private:
  void install(const Profile& profile, bool final) noexcept;

  JobKind kind_ = JobKind::kNone;
  uint16_t number_ = 0;
  uint64_t k_ = 0;
  double offset_ = 0.0;  // s; see set_time_offset()
  bool ended_ = false;
  bool reached_ = false;
  bool final_ = true;
  double brake_start_ = 0.0;
  bool has_brake_phase_ = false;
  double target_ = 0.0;
  double target_velocity_ = 0.0;
  double jerk_ = 0.0;
  KinematicState state_{};
  Limits limits_{};
  double reduced_velocity_ = 0.0;
  double direction_ = 1.0;
  uint32_t override_ = plc::kOverrideFull;
  uint32_t handled_override_ = plc::kOverrideFull;
  Activation activation_{};
  DecouplingChain chain_{};  // empty except after an online decoupling, until the first replan
  Profile profile_{};        // last: a cycle reads its header and one segment, not all of it
};

// The limits a new job or the error ramp runs with from the set state `from` (fuzz findings K4,
// K5): its own, unless ramping from's acceleration to 0 at its J would pass `max_velocity` while
// the running job's J is larger; then that J (override.cpp).
Limits with_running_jerk(const Limits& limits, const KinematicState& from, const MasterJob& running,
                         double max_velocity) noexcept;

}  // namespace nc::detail
