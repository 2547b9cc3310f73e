// MC_NewPosAndVelo: a new end position and a new velocity for the positioning that runs, the new
// velocity taking effect from an activation position on (seed 000 §2.4 "New velocity and new end
// position"; EPos = NewPos, VNew = NewVelo, APos = ActivationPos).
//
// Execute-type block (rules in fb/detail/execute_block.hpp), posting kNewPosAndVelo with
// position = NewPos, velocity = NewVelo, activation_position = ActivationPos. The NC sorts the
// running motion into the seed's six cases (where the axis is relative to APos and EPos, in
// the direction of travel) and acts on them. The block shows the NC's answer for its command:
// Done when the NC reports it done, CommandAborted when another command took over first, Error
// with the NC's code when refused — NewPos NaN/±inf (0x4F01), NewVelo or ActivationPos NaN/±inf
// (0x4F02), NewVelo ≤ 0 (0x4231) or above the max velocity (0x4221), NewPos outside the
// software limits (0x4222), during position compensation, on an axis in error (0x4F06). The
// block checks nothing itself. Like Tc2's MC_NewPosAndVelo it has no Active output.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_NewPosAndVelo {
 public:
  // Inputs (latched on the rising edge of Execute).
  bool Execute = false;
  double NewPos = 0.0;         // mm, EPos: the new end position
  double NewVelo = 0.0;        // mm/s, VNew: > 0, at most the max velocity
  double ActivationPos = 0.0;  // mm, APos: VNew takes effect once the axis has crossed it

  // Outputs.
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(plc::AXIS_REF& axis) noexcept;

  // Number of the command posted last (0: none); for traces and tests.
  uint16_t command_number() const noexcept { return block_.command_number(); }

 private:
  detail::ExecuteBlock block_;
};

}  // namespace fb
