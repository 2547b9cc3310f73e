// The master-axis job: a PTP command's kind and number, its goal and online state (job_goal.hpp)
// and its running table (job_table.hpp) — the seed's "runtime table" (seed 000 §2.1) and what the
// online functions keep with it (seed 000 §2.2 … §2.4).
//
// Online functions (override, new end position, new velocity) install a new table into the
// running job with replan(): same job, same command number, sampled from k = 0 again, starting
// at table.state() — the set state the job output last — so the set values stay continuous. A
// table that is not "final" is a rest for override 0: it brings the axis to rest on its path and
// then holds; the job does not end there but waits for the override to rise.
//
// Brake phase (seed 000 §2.2, §2.4): the final deceleration of a positioning table to its target,
// i.e. the trailing part of the table in which |v| only falls, found once per table
// (brake_start()). A Halt or Stop planned in the brake phase counts as braking as a whole
// (mark_brake_phase()), so that no later stop sharpens it.
//
// A passing table (BufferMode blending, docs/behaviour.md "BufferMode") ends at its target with a
// velocity. The buffered command takes over in the cycle whose sample passes that end: it is
// planned from the table's end state and sampled from the time since that end (a time offset),
// so the pass is exact.
//
// The three parts are public members: start(), replan(), clear() and follow() keep them
// consistent; the online functions read them and change the goal and online state in place.
// Cycle functions only: noexcept, no allocation.
#pragma once

#include <cstdint>

#include "axis/job_goal.hpp"
#include "axis/job_table.hpp"
#include "nc_core/profile.hpp"

namespace nc::detail {

class MasterJob {
 public:
  // Takes over a planned profile; the previous job is forgotten. Goal and online state start
  // afresh (JobGoal::start, JobOnline::start).
  void start(JobKind kind, uint16_t number, const Profile& profile, double target,
             double target_velocity, const Limits& limits) noexcept;
  void clear() noexcept;
  // A new table for the running job, planned from table.state(). `final`: it ends at the job's
  // goal (false: a rest for override 0).
  void replan(const Profile& profile, bool final) noexcept;
  // Online decoupling: this job (a copy of the head's) goes on through `chain`. Number, goal and
  // a pending activation are transformed; `limits` (the velocity already |total factor| × the
  // head's) replaces the limits; `override_value` is the axis's own and counts as handled.
  void follow(const DecouplingChain& chain, uint16_t number, const Limits& limits,
              uint32_t override_value) noexcept;

  // The set values of the next cycle (their jerk: table.jerk()). Call once per cycle while
  // kind() != kNone.
  KinematicState advance(double cycle_time) noexcept {
    return table.advance(kind_, final_, cycle_time);
  }
  // A passing table whose end falls within the next cycle.
  bool passes_in_next_cycle(double cycle_time) const noexcept;

  JobKind kind() const noexcept { return kind_; }
  void set_kind(JobKind kind) noexcept { kind_ = kind; }
  bool active() const noexcept { return kind_ != JobKind::kNone; }
  bool is_motion() const noexcept {
    return kind_ == JobKind::kPosition || kind_ == JobKind::kVelocity;
  }
  uint16_t number() const noexcept { return number_; }
  // A positioning whose table passes its target with a velocity (blending).
  bool passing() const noexcept { return kind_ == JobKind::kPosition && table.holds_velocity(); }
  // The running table ends at the job's goal (false: a rest for override 0).
  bool final_table() const noexcept { return final_; }
  // The final deceleration to the target has begun (positioning tables, and a Halt / Stop
  // planned in one). Judged at the state output last.
  bool in_brake_phase(double cycle_time) const noexcept;
  // The whole running table counts as brake phase (a Halt / Stop planned in one).
  void mark_brake_phase() noexcept {
    has_brake_phase_ = true;
    brake_start_ = 0.0;
  }

 private:
  JobKind kind_ = JobKind::kNone;
  uint16_t number_ = 0;
  bool final_ = true;
  bool has_brake_phase_ = false;
  double brake_start_ = 0.0;

 public:
  // The online state and the table's header follow the kind, the goal (which a steady cycle does
  // not read) comes last: what a cycle reads is one run of lines from the job's start
  // (docs/performance.md "Eighth pass").
  JobOnline online{};
  JobTable table{};
  JobGoal goal{};
};

// The limits a new job or the error ramp runs with from the set state `from` (fuzz findings K4,
// K5): its own, unless ramping from's acceleration to 0 at its J would pass `max_velocity` while
// the running job's J is larger; then that J (override.cpp).
Limits with_running_jerk(const Limits& limits, const KinematicState& from, const MasterJob& running,
                         double max_velocity) noexcept;

}  // namespace nc::detail
