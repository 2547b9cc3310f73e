// What the online functions of a master-axis job change (seed 000 §2.2 … §2.4), parts of
// MasterJob (master_job.hpp): the goal and velocity levels (JobGoal), and the override and a
// pending velocity activation (JobOnline). A new table for the running job keeps both; a new job
// starts them afresh.
//
// Cycle functions only: noexcept, no allocation.
#pragma once

#include <cstdint>

#include "axis/job_table.hpp"
#include "nc_core/profile.hpp"
#include "plc_interface/axis_ref.hpp"

namespace nc::detail {

// PlcToNc.Override as a factor 0 … 1 (exactly 1 at 1'000'000).
inline double override_factor(uint32_t override_value) noexcept {
  return static_cast<double>(override_value) / static_cast<double>(plc::kOverrideFull);
}

// A new velocity waiting for its activation position (seed 000 §2.4, cases 1 and 5), or an
// instantaneous one suspended while the table is in its brake phase.
struct Activation {
  bool armed = false;
  bool immediate = false;  // due at once (case 2); waits only while in the brake phase
  double position = 0.0;   // APos
  double direction = 0.0;  // +1 / -1: due once the set position passes APos moving this way
  double velocity = 0.0;   // VNew
};

// The job's goal: target, target velocity, limits, the user's velocity V (limits().velocity),
// the level reduced at the start (seed 000 §2.2 override types 1 and 3) and the direction.
class JobGoal {
 public:
  // A new job: reduced level = limits.velocity, direction from target_velocity (+1 when 0).
  void start(double target, double target_velocity, const Limits& limits) noexcept {
    target_ = target;
    target_velocity_ = target_velocity;
    limits_ = limits;
    reduced_velocity_ = limits.velocity;
    direction_ = target_velocity < 0.0 ? -1.0 : 1.0;
  }
  // Online decoupling: target, levels and direction through `chain`; `limits` replace the limits.
  void follow(const DecouplingChain& chain, const Limits& limits) noexcept;

  double target() const noexcept { return target_; }
  void set_target(double target) noexcept { target_ = target; }
  double target_velocity() const noexcept { return target_velocity_; }
  void set_target_velocity(double velocity) noexcept { target_velocity_ = velocity; }
  const Limits& limits() const noexcept { return limits_; }
  // The user's velocity V (limits().velocity follows it), the reduced level and the direction
  // of travel (+1 / -1).
  void set_levels(double user_velocity, double reduced_velocity, double direction) noexcept {
    limits_.velocity = user_velocity;
    reduced_velocity_ = reduced_velocity;
    direction_ = direction < 0.0 ? -1.0 : 1.0;
  }
  double user_velocity() const noexcept { return limits_.velocity; }
  double reduced_velocity() const noexcept { return reduced_velocity_; }
  double direction() const noexcept { return direction_; }

 private:
  double target_ = 0.0;
  double target_velocity_ = 0.0;
  Limits limits_{};
  double reduced_velocity_ = 0.0;
  double direction_ = 1.0;
};

// PlcToNc.Override as last read and as answered, and a pending velocity activation.
class JobOnline {
 public:
  // A new job: the current override counts as handled, no pending activation.
  void start() noexcept {
    handled_override_ = override_;
    activation_ = Activation{};
  }
  // Online decoupling: a pending activation through `chain`; the axis's own `override_value`
  // counts as handled (the table goes on unchanged).
  void follow(const DecouplingChain& chain, uint32_t override_value) noexcept;

  // PlcToNc.Override, last valid value read (0 … 1'000'000); kept across jobs.
  void set_override(uint32_t value) noexcept { override_ = value; }
  uint32_t override_value() const noexcept { return override_; }
  // The override value the running table has answered (applied, or refused and not retried).
  void set_handled_override(uint32_t value) noexcept { handled_override_ = value; }
  uint32_t handled_override() const noexcept { return handled_override_; }
  Activation& activation() noexcept { return activation_; }
  const Activation& activation() const noexcept { return activation_; }

 private:
  uint32_t override_ = plc::kOverrideFull;
  uint32_t handled_override_ = plc::kOverrideFull;
  Activation activation_{};
};

}  // namespace nc::detail
