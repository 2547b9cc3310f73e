// The NC's default homing sequence (MC_Home with MC_DefaultHoming, SPEC F): one more set-value
// source of a servo axis (set_value_source.hpp, kHomingJob). TwinCAT NC's sequence:
//  1. towards the cam: continuous motion in the cam search direction at the velocity towards
//     the cam, until the PLC's cam signal (PlcToNc.ControlDWord bit 5, MC_Home.bCalibrationCam)
//     is seen;
//  2. off the cam: from there straight on to the velocity off the cam in the sync search
//     direction (the profile reverses when that direction is the other one), until the cam
//     signal falls after it has been seen;
//  3. sync pulse: the first encoder zero pulse beyond the position at that edge in the sync
//     direction (one every sync_pulse_distance mm of the raw encoder); with no sync pulse
//     (distance 0) the cam edge itself is the reference;
//  4. at the reference the position is set (Step::shift: the reference point becomes the home
//     position, set and actual move together), the axis is referenced, and it stops on its
//     deceleration; the job is finished at rest.
// The travel of steps 1 and 2-3 is each bounded by the search distance (0x4F20, 0x4F22).
// Motion is planned with the planner (plan_velocity, plan_stop) and sampled by a MasterJob.
// start() and advance() are cycle functions: noexcept, no allocation.
#pragma once

#include <cstdint>

#include "axis/master_job.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/profile.hpp"
#include "plc_interface/error_code.hpp"

namespace nc::detail {

class HomingJob {
 public:
  // What the axis gives the job each cycle.
  struct Inputs {
    bool cam = false;              // the PLC's cam signal as the NC samples it this cycle
    double raw_position = 0.0;     // the encoder's raw position (before any position setting)
    double actual_position = 0.0;  // the displayed actual position
    double offset = 0.0;           // displayed − raw, as set by earlier position settings
  };
  // What the job gives the axis each cycle.
  struct Step {
    KinematicState state{};  // set values, after the shift below
    double jerk = 0.0;
    bool referenced = false;  // this cycle the reference was found and the position set
    double shift = 0.0;       // with `referenced`: every displayed position moves by this
    ErrorCode error = ErrorCode::kNone;
  };

  // Starts from the set state `from` towards the cam; `home` is where the reference lands. The
  // whole sequence runs with the axis's A+, A- and `jerk` (the axis's J, or the larger J of an
  // aborted motion, fuzz finding K8). False when the planner refuses (the job stays idle).
  bool start(uint16_t number, const KinematicState& from, double home, const AxisConfig& config,
             double jerk, Profile& scratch) noexcept;
  Step advance(const Inputs& in, double cycle_time, Profile& scratch) noexcept;
  void clear() noexcept { phase_ = Phase::kIdle; }

  bool active() const noexcept { return phase_ != Phase::kIdle; }
  // Stopped at rest after the reference: the command is done.
  bool finished() const noexcept {
    return phase_ == Phase::kStopping && motion_.table.generation_ended();
  }
  uint16_t number() const noexcept { return number_; }
  // The motion that samples the sequence (its limits: the running jerk for what aborts it).
  const MasterJob& motion() const noexcept { return motion_; }

 private:
  enum class Phase : uint8_t { kIdle, kTowardsCam, kOffCam, kSyncPulse, kStopping };

  // The next cycles continue from `from` at `velocity` (signed) or stop (`stop`).
  bool plan(const KinematicState& from, double velocity, bool stop, Profile& scratch) noexcept;

  Phase phase_ = Phase::kIdle;  // first: the axis's steady cycle reads only this (active())
  MasterJob motion_{};
  uint16_t number_ = 0;
  double home_ = 0.0;
  double cam_direction_ = 1.0;
  double sync_direction_ = -1.0;
  double velocity_off_cam_ = 0.0;
  double pulse_distance_ = 0.0;
  double search_distance_ = 0.0;
  Limits limits_{};
  double travel_ = 0.0;         // path travelled in the current search (steps 1, or 2-3)
  double last_position_ = 0.0;  // set position output last
  bool cam_seen_ = false;       // step 2: the cam signal was high
  double pulse_ = 0.0;          // step 3: the raw position of the awaited sync pulse
};

}  // namespace nc::detail
