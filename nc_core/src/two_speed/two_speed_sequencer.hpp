// The set-value side of a two-speed (rapid/creep) axis (SPEC E1-E5, seed 004): from a start (or a
// stop), the override and the actual position each NC cycle it produces the 12-byte drive image,
// nAxisState and the end of the positioning. It commands contactors, not a set position.
//
// Sequence of one leg: brake off (21) → brake_release_delay → rapid or creep by start velocity and
// override (21, main travel) → at the creep distance before the leg's end rapid off (22) →
// rapid_to_creep_delay → creep (23) → at the braking distance creep off (24) →
// brake_incidence_delay → brake on (20) and Done. With the looping distance a target reached in
// the "wrong" direction gets a first leg to target + looping_distance and a creep return leg.
// A stop creeps for creep_distance_stop from where it is called, then brakes. docs/behaviour.md
// "Two-speed axis" gives every choice (what is skipped, what a stop does in each phase).
//
// The constructor is set-up (may throw ConfigError). Everything else is a cycle function:
// noexcept, no allocation. Per NC cycle the owner calls the commands it received (start, stop,
// set_override, set_enabled), then step() with the encoder's actual position.
#pragma once

#include <cstdint>

#include "nc_core/axis_config.hpp"
#include "plc_interface/error_code.hpp"
#include "plc_interface/two_speed.hpp"
#include "two_speed/two_speed_leg.hpp"

namespace nc::detail {

// What ended in this cycle.
enum class TwoSpeedEvent : uint8_t {
  kNone,
  kDone,     // positioning complete: brake on at its end
  kStopped,  // stop complete: brake on
  kError,    // positioning ended with an error: brake on at once; see TwoSpeedCycle::error
};

struct TwoSpeedCycle {
  plc::TwoSpeedAxisState state = plc::TwoSpeedAxisState::kInactive;  // nAxisState
  TwoSpeedEvent event = TwoSpeedEvent::kNone;
  plc::ErrorCode error = plc::ErrorCode::kNone;
};

class TwoSpeedSequencer {
 public:
  // Set-up: checks the two-speed rules (validate_two_speed); starts disabled, brake on, state 0.
  explicit TwoSpeedSequencer(const AxisConfig& config);

  // Controller enable. Disabling ends a running positioning or stop at once (no event: the
  // owner answers the command), brake on, nAxisState 0 until the next start.
  void set_enabled(bool enabled) noexcept;
  // Ends a running positioning or stop at once (brake on, nAxisState 20), e.g. on an axis error.
  void abort() noexcept;

  // A positioning to `target` (absolute) with start velocity `velocity`, the axis standing at
  // `actual_position`. Refusals (nothing changes): not enabled 0x4356, busy 0x424E, target not
  // finite 0x4F01, velocity not finite 0x4F02, velocity <= 0 0x4231, actual not finite 0x4F0B,
  // |target - actual| <= braking distance of that direction 0x4F0C.
  plc::ErrorCode start(double target, double velocity, double actual_position) noexcept;
  // Stop (MC_Stop / MC_Halt): creep for creep_distance_stop from `actual_position`, then brake.
  // At rest it completes in the next step(). Refused only when not enabled (0x4356).
  plc::ErrorCode stop(double actual_position) noexcept;
  // PlcToNc.Override, 0 … 1'000'000; acts only in the main travel phase. Above 100 %: 0x4238,
  // the last valid value stays.
  plc::ErrorCode set_override(uint32_t value) noexcept { return leg_.set_override(value); }

  // One NC cycle: `actual_position` is the encoder's value at its start, dt the cycle time (> 0).
  TwoSpeedCycle step(double actual_position, double dt) noexcept;

  const plc::NCTOIO_DRIVE_TWO_SPEED& image() const noexcept { return image_; }
  plc::TwoSpeedAxisState state() const noexcept;
  bool busy() const noexcept { return phase_ != Phase::kRest; }  // positioning or stop running
  bool stopping() const noexcept { return busy() && leg_.stopping(); }
  double target() const noexcept { return leg_.target(); }  // of the last accepted start

 private:
  enum class Phase : uint8_t {
    kRest,
    kBrakeRelease,
    kMainTravel,
    kHighToLowDelay,
    kCreep,
    kBrakeIncidence
  };

  void enter(Phase phase) noexcept;
  // Moves through as many phases as this cycle completes; returns what ended.
  TwoSpeedCycle advance(double p) noexcept;
  void write_image() noexcept;

  TwoSpeedLeg leg_;
  MainTravelSpeed main_speed_{};
  plc::NCTOIO_DRIVE_TWO_SPEED image_{};

  Phase phase_ = Phase::kRest;
  bool enabled_ = false;
  bool started_ = false;  // a start since the enable: nAxisState 20 at rest rather than 0
  bool fresh_ = false;    // phase entered by start()/stop(): the next step() is its first cycle
  double elapsed_ = 0.0;  // s in the present phase, counted at each step() after its first
  TwoSpeedEvent pending_ = TwoSpeedEvent::kNone;  // a stop at rest, shown by the next step()
};

}  // namespace nc::detail
