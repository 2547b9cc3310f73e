// Position compensation of one axis (seed 000 §2.5, SPEC B7): the running MC_MoveSuperImposed.
//
// The extra motion is the compensation trapezoid (nc_core/trapezoid.hpp) over the time
// T = L / VP, run in time, its velocity scaled by s = min(1, |v| / VP), v being the basic
// motion's set velocity (SPEC B7 decision): per NC cycle the trapezoid's increment is taken times
// the mean s of the cycle. So the full D is done while |v| >= VP, less while the basic motion is
// slower (override, stop), and the extra velocity falls to 0 wherever the basic motion stands.
// What is not done is counted as `lost_`, so with s = 1 throughout the offset is exactly the
// trapezoid's distance (no running sum of increments).
//
// D is relative to the direction of travel (positive = makes up, negative = falls behind; the
// vendor's MC_MoveSuperImposed documents the same): `direction` (+1 / -1) turns it into axis
// coordinates.
//
// Value type; cycle functions only (noexcept, no allocation).
#pragma once

#include <cstdint>

#include "nc_core/profile.hpp"
#include "nc_core/trapezoid.hpp"

namespace nc::detail {

// The start parameters of seed 000 §2.5 ("Start parameters"): D != 0, L > 0, VP > 0, VK > 0,
// AK+ > 0, AK- > 0. First broken rule: D not finite kPositionNotFinite, another not finite
// kParameterNotFinite, D == 0 kCompensationParametersInvalid, L 0x4270, VK / VP 0x4271,
// AK+ / AK- 0x4272; |D| and each of the others must also lie in [1e-9, 1e12] (the planner's
// numeric range, profile/validate.hpp), else the same codes.
ErrorCode check_compensation(double distance, double length, double process_velocity,
                             double velocity_diff, double acceleration,
                             double deceleration) noexcept;

class Compensation {
 public:
  // Plans the compensation over `length` (already limited to the remaining distance) and starts
  // it; nothing changes on an error. `speed` is the basic motion's |v| at the start; the
  // trapezoid is sampled at k·cycle_time, k = 1, 2, … from the next advance() on.
  ErrorCode start(uint16_t number, double distance, double length, double process_velocity,
                  double velocity_diff, double acceleration, double deceleration, double direction,
                  double speed, double cycle_time) noexcept;

  // One NC cycle: the extra (p, v, a) in axis coordinates, given the basic motion's set velocity
  // and acceleration of this cycle.
  KinematicState advance(double base_velocity, double base_acceleration,
                         double cycle_time) noexcept;

  // Compensation stop (seed 000 §2.5): the extra velocity ramps down at once with the closing
  // slope and D is replaced by what is reached. kCompensationStopNotAllowed in the braking phase.
  ErrorCode request_stop() noexcept;
  // Ends the compensation (state kept for publishing); returns its final offset (axis coords).
  double finish() noexcept;

  bool running() const noexcept { return running_; }
  bool stop_requested() const noexcept { return stop_requested_; }
  // The trapezoid's time T has passed: the compensation is complete (as far as it goes).
  bool time_over() const noexcept { return time_over_; }
  uint16_t number() const noexcept { return number_; }

  // The extra motion of the last cycle, axis coordinates.
  const KinematicState& state() const noexcept { return state_; }
  // The offset expected at the end if |v| stays >= VP (axis coordinates).
  double planned_offset() const noexcept { return direction_ * trapezoid_.distance(); }
  // Travel-relative values (the sign convention of D), kept after the end for NcToPlc:
  double done() const noexcept { return direction_ * state_.p; }  // compensated so far
  double length() const noexcept { return length_; }              // L in use
  double velocity_diff() const noexcept { return trapezoid_.peak_velocity(); }  // signed peak
  // Less than the requested D is (or will be) done: the planned D is smaller, or the end came
  // with less than D (velocity scaling, compensation stop, end of path).
  bool planned_incomplete() const noexcept { return !trapezoid_.complete(); }
  bool incomplete() const noexcept;

 private:
  // What every cycle reads (running(), and for NcToPlc done(), length(), velocity_diff()) first.
  bool running_ = false;
  bool stop_requested_ = false;
  bool time_over_ = false;
  uint16_t number_ = 0;
  double direction_ = 1.0;
  double length_ = 0.0;
  KinematicState state_{};
  Trapezoid trapezoid_{};   // its peak velocity first
  double requested_ = 0.0;  // D as commanded (travel-relative)
  double process_velocity_ = 1.0;
  double lost_ = 0.0;  // trapezoid distance not done because s < 1 (travel-relative)
  double previous_scale_ = 1.0;
  double previous_p_ = 0.0;  // trapezoid position at the previous sample
  uint64_t k_ = 0;           // cycles since the start; the trapezoid is sampled at k·T
  double cycle_time_ = 0.0;
};

}  // namespace nc::detail
