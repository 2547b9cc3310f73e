// What one axis publishes to the other axes of its kernel in a cycle: the only thing one axis may
// read of another (a slave its master's set values, a group its members' errors).
//
// In a cycle in which some axis reads another (couplings, the HLI stage), the phases write it as
// they go: the target, path and set values in the set-value phase (so a slave, computed after its
// master, reads the master's values of the same cycle), everything again in the monitor phase for
// the group reactions. Otherwise the cycle writes only the group reaction (and a C8 master's
// filtered values). Between cycles Kernel::snapshot() fills it in with the axis as the cycle left
// it. Plain data.
#pragma once

#include <cstdint>

#include "plc_interface/error_code.hpp"

namespace nc {

// Aligned to a cache line (120 bytes padded to 128): each on two lines of its own.
struct alignas(64) AxisSnapshot {
  double set_position = 0.0;
  double set_velocity = 0.0;
  double set_acceleration = 0.0;
  double set_jerk = 0.0;
  double target_position = 0.0;  // NcToPlc.TargetPos / TargetVelo of this cycle (a slave: its
  double target_velocity = 0.0;  // master's, transformed by factor and offset)
  // The basic path the axis's superpositions ride on (its job, or a slave's master's path):
  bool path_running = false;      // its set-value generation runs
  bool path_stopping = false;     // it is a halt, stop or error ramp
  bool path_positioning = false;  // it is a positioning (target_position is its end)
  bool path_has_target = false;   // it ends at target_position (positioning or stop)
  double actual_position = 0.0;
  double actual_velocity = 0.0;
  double actual_acceleration = 0.0;
  plc::ErrorCode error = plc::ErrorCode::kNone;  // the axis's latched error
  bool error_event = false;                      // the error was raised in this cycle
  bool group_reaction_due = false;  // the group reaction of the axis's own error acts now (C7)
  bool controller_enabled = false;
  bool feed_enabled_plus = false;
  bool feed_enabled_minus = false;
  // SPEC C8: while the axis drives its slaves by its actual values, they follow its filtered
  // actual position instead of its set values (the set values above stay its own: the HLI
  // stage reads them). Written in the set-value phase, by the axis's GroupErrors.
  bool slaves_follow_actual = false;
  double filtered_position = 0.0;
  double filtered_velocity = 0.0;
  double filtered_acceleration = 0.0;

  // What a slave follows of this axis (SPEC C1, C6, C8).
  double followed_position() const noexcept {
    return slaves_follow_actual ? filtered_position : set_position;
  }
  double followed_velocity() const noexcept {
    return slaves_follow_actual ? filtered_velocity : set_velocity;
  }
  double followed_acceleration() const noexcept {
    return slaves_follow_actual ? filtered_acceleration : set_acceleration;
  }
  double followed_jerk() const noexcept { return slaves_follow_actual ? 0.0 : set_jerk; }
};

}  // namespace nc
