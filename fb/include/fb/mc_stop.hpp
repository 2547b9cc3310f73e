// MC_Stop: stops the axis and locks it against motion commands (seed 000 §2.3; Tc2_MC2 MC_Stop).
//
// Execute-type block (rules in fb/detail/execute_block.hpp). The NC brakes, answers Done at
// standstill, and refuses every motion command (0x42EF) while the lock holds. The lock is this
// block's: it posts the release (kStopRelease) exactly once, as soon as its Execute is low AND
// it has been Done — so a stop cannot be undone while the PLC still holds Execute. After an
// Error or CommandAborted no release is posted (MC_Reset unlocks the axis; a later MC_Stop
// holds its own lock). Done, Busy, Error and CommandAborted stay mutually exclusive; while a
// release waits for room in a full mailbox, the block shows Busy.
// Deceleration or Jerk of 0 mean those of the running motion (the NC substitutes them).
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_Stop {
 public:
  // Inputs (latched on the rising edge of Execute).
  bool Execute = false;
  double Deceleration = 0.0;  // mm/s², 0 = default
  double Jerk = 0.0;          // mm/s³, 0 = default

  // Outputs.
  bool Done = false;
  bool Busy = false;
  bool Active = false;
  bool CommandAborted = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(plc::AXIS_REF& axis) noexcept;

  uint16_t command_number() const noexcept { return block_.command_number(); }

 private:
  detail::ExecuteBlock block_;
  bool holding_lock_ = false;     // Done seen: the release is owed once Execute is low
  bool release_pending_ = false;  // release owed but the mailbox was full
};

}  // namespace fb
