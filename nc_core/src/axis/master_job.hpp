// The master-axis job: the seed's "runtime table" (seed 000 §2.1, "Procedure").
//
// A job owns one planned Profile and samples it once per NC cycle at t = k·T, k = 1, 2, … since
// the cycle in which it was accepted (k = 0 is the set state it started from, i.e. the previous
// cycle's set values). Sampling by product, never by summing T, keeps the end exact and the runs
// repeatable. When k·T reaches the profile's duration the job outputs the profile's exact final
// state and its set-value generation has ended. A velocity job never ends: it has "reached" its
// velocity and goes on extrapolating the hold.
//
// Cycle functions only: noexcept, no allocation.
#pragma once

#include <cstdint>

#include "nc_core/profile.hpp"

namespace nc::detail {

enum class JobKind : uint8_t {
  kNone,           // no job: the set values hold
  kPosition,       // MoveAbsolute / MoveRelative
  kVelocity,       // MoveVelocity (continuous motion)
  kHalt,           // MC_Halt
  kStop,           // MC_Stop (locks the axis)
  kEmergencyStop,  // the axis's error ramp (no command number)
};

class MasterJob {
 public:
  // Takes over a planned profile; the previous job is forgotten.
  void start(JobKind kind, uint16_t number, const Profile& profile, double target,
             double target_velocity, const Limits& limits) noexcept;
  void clear() noexcept;

  // The set values of the next cycle. Call once per cycle while kind() != kNone.
  KinematicState advance(double cycle_time) noexcept;
  double jerk() const noexcept { return jerk_; }

  JobKind kind() const noexcept { return kind_; }
  bool active() const noexcept { return kind_ != JobKind::kNone; }
  bool is_motion() const noexcept {
    return kind_ == JobKind::kPosition || kind_ == JobKind::kVelocity;
  }
  uint16_t number() const noexcept { return number_; }
  // Set-value generation has ended (positioning, halt, stop): the final state is output.
  bool generation_ended() const noexcept { return ended_; }
  // A velocity job's constant velocity is reached.
  bool velocity_reached() const noexcept { return reached_; }
  double target() const noexcept { return target_; }
  double target_velocity() const noexcept { return target_velocity_; }
  const Limits& limits() const noexcept { return limits_; }
  uint64_t cycles() const noexcept { return k_; }

  // PlcToNc.Override as last read (0 … 1'000'000). Held for the override functions (issue 4).
  void set_override(uint32_t value) noexcept { override_ = value; }
  uint32_t override_value() const noexcept { return override_; }

 private:
  Profile profile_{};
  JobKind kind_ = JobKind::kNone;
  uint16_t number_ = 0;
  uint64_t k_ = 0;
  bool ended_ = false;
  bool reached_ = false;
  double target_ = 0.0;
  double target_velocity_ = 0.0;
  double jerk_ = 0.0;
  Limits limits_{};
  uint32_t override_ = 1'000'000;
};

}  // namespace nc::detail
