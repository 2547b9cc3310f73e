// The steady lane of the kernel's loop (docs/performance.md "Ninth pass"): the commonest steady
// state — a positioning's table sampled inside one segment, enabled, no error, nothing rare — has
// in most cycles nothing to decide. At the end of a cycle of the full bodies, enter() looks at
// everything a cycle of that state could decide on from the NC's side and, when none of it can
// fire before then, gives the job's table a horizon: up to which sample the set values stay in
// the current segment and short of the table's end. While the horizon lasts and the PLC's side
// is as the last cycle saw it (ServoPhases::cycle_alone: an empty mailbox, the same ControlDWord
// and Override, no event), the cycle samples that segment, controls, drives, watches the
// following error and publishes (ServoPhases::lane): the same results as the full bodies.
//
// What enter() asks, each as the full bodies would decide it in every cycle of the horizon:
// - the job: a positioning (not a pass, not ended, no decoupling chain), no homing, no
//   superposition or C8 filter (EventImage::rare), no buffered command, no C7 delay, its override
//   handled and read unchanged, no velocity activation armed: phase (a) and finish_job() do
//   nothing;
// - the controller and both feed enables on, no axis error, no hand velocity: check_enables()
//   raises nothing whatever the sign of v;
// - the samples: k·T + offset inside the segment of the last sample (the cursor) and short of the
//   end tolerance: the table's advance() takes its inner path on that segment;
// - the software limits: every position the segment's samples can reach (a bound from both of
//   its ends) lies within them, so run_monitors() raises no limit error; the windows rest (the
//   job runs).
// The following error is watched in every lane cycle (Monitors::lag_within()); when it would
// count, the cycle goes on with the full monitors.
//
// Internal; a friend of JobTable. Cycle functions: noexcept, no allocation.
#pragma once

#include <cstdint>

#include "axis/axis_core.hpp"
#include "axis/job_table.hpp"
#include "profile/profile_sample.hpp"

namespace nc::detail {

class SteadyLane {
 public:
  // After a cycle of the full bodies of cycle_alone(): the horizon of `a`'s table, or none.
  static void enter(AxisCore& a) noexcept;
  // The horizon's bound as enter() computes it now: the last sample k it covers (0: none).
  static uint32_t horizon(const AxisCore& a) noexcept;
  // The check of a check build (-DNCSDK_CHECK_EVENT_IMAGE) before a lane cycle: the horizon kept
  // is the one horizon() finds now, and the next sample as Profile::at() gives it (the full
  // path's) is the lane's, in the same segment, and passes no software limit.
  static bool lane_holds(const AxisCore& a) noexcept;
  // The next sample is within the horizon.
  static bool next(const JobTable& table) noexcept { return table.k_ < table.steady_until_; }
  // The table's next sample, as JobTable::advance() gives it within the horizon (its jerk:
  // table.jerk()).
  static KinematicState advance(JobTable& table, double cycle_time) noexcept {
    ++table.k_;
    const double t = table.sample_time(cycle_time);
    double jerk = 0.0;
    table.state_ =
        ProfileSample::in_segment(table.profile_, ProfileSample::cursor(table.profile_), t, jerk);
    table.jerk_ = jerk;
    return table.state_;
  }
  // Asks for the cache lines of the table's next sample as the lane takes it (the cursor's
  // segment, ProfileSample::prefetch_segment): the kernel's loop, ahead (servo_axis.hpp).
  [[gnu::always_inline]] static void prefetch(const JobTable& table) noexcept {
    ProfileSample::prefetch_segment(table.profile_, ProfileSample::cursor(table.profile_));
  }
  // No horizon (the kernel's other paths, which enter() does not follow).
  static void leave(JobTable& table) noexcept { table.steady_until_ = 0; }
};

}  // namespace nc::detail
