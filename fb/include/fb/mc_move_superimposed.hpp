// MC_MoveSuperImposed: position compensation — an extra distance D travelled over the length L on
// top of the running (basic) motion, without interrupting it (seed 000 §2.5, SPEC B7).
//
// Execute-type block (rules in fb/detail/execute_block.hpp). Inputs map onto the seed's start
// parameters: Distance = D (≠ 0, may be negative), VelocityDiff = VK, Acceleration = AK+,
// Deceleration = AK-, VelocityProcess = VP, Length = L (all > 0). The NC validates them and plans
// the compensation trapezoid; the block shows the NC's code. The basic motion keeps its command
// number (NcToPlc.CmdNo) and its block stays Active: the compensation is a job beside it, so
// Active here means "the NC runs this compensation" (its answer is kActive).
// Done when the NC reports the compensation finished; CommandAborted when it ended early
// (compensation stop, end of path, another start). Warning / WarningID show the NC's warning
// 0x4243 "compensation incomplete" when the largest feasible D is done instead of D; they follow
// the result (shown while Busy and with the result, reset with it).
// ActualDistance = the compensation distance travelled so far (NcToPlc.CompensationDistance),
// ActualLength and ActualVelocityDiff = the length and peak extra velocity the NC actually plans
// (NcToPlc.CompensationLength / CompensationVelocityDiff). They are read while the compensation
// runs and in the call that sees its result, and kept until the next start.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_MoveSuperImposed {
 public:
  // Inputs (latched on the rising edge of Execute).
  bool Execute = false;
  double Distance = 0.0;         // mm, D: extra distance (≠ 0; < 0 falls behind)
  double VelocityDiff = 0.0;     // mm/s, VK: largest extra velocity (> 0)
  double Acceleration = 0.0;     // mm/s², AK+ (> 0)
  double Deceleration = 0.0;     // mm/s², AK- (> 0)
  double VelocityProcess = 0.0;  // mm/s, VP: the velocity VK refers to (> 0)
  double Length = 0.0;           // mm, L: compensation length (> 0)

  // Outputs.
  bool Done = false;
  bool Busy = false;
  bool Active = false;
  bool CommandAborted = false;
  bool Error = false;
  uint32_t ErrorID = 0;
  bool Warning = false;
  uint32_t WarningID = 0;
  double ActualDistance = 0.0;      // mm, compensation travelled so far (signed)
  double ActualLength = 0.0;        // mm, compensation length the NC uses
  double ActualVelocityDiff = 0.0;  // mm/s, peak extra velocity the NC plans (signed)

  // Cycle function: runs the block once.
  void operator()(plc::AXIS_REF& axis) noexcept;

  uint16_t command_number() const noexcept { return block_.command_number(); }

 private:
  detail::ExecuteBlock block_;
  uint16_t seen_number_ = 0;  // command whose Actual* values are shown
};

}  // namespace fb
