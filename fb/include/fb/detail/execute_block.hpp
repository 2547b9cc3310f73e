// The PLCopen output rules of an Execute-type block, written once for every such block.
//
// A block with an Execute input owns an ExecuteBlock and calls it once per block call with its
// Execute input and a function that builds the command from the inputs. The ExecuteBlock does
// the rest, as Tc2_MC2's "general rules for MC function blocks" describe them:
//  - the command is built (inputs latched) and posted only on a rising edge of Execute, and only
//    when the block is not busy: a rising edge while Busy starts nothing;
//  - a falling Execute never aborts the command;
//  - Busy, Done, Error and CommandAborted are mutually exclusive, and so are Active, Done, Error
//    and CommandAborted; Active only while the axis executes this block's command number;
//  - a command the NC keeps in its buffer (kBuffered, BufferMode) is Busy but not Active;
//  - a result (Done, Error, CommandAborted) stays while Execute stays high; a result reached
//    after Execute fell is shown for exactly one call; then the outputs reset.
// One documented exception, opted into by MC_GearIn (issue 9): with kRetriggerWhileReached a
// rising edge while the NC answers kReached (InGear) posts a new command, whose outcome the block
// follows from then on (the factor change of SPEC C2 by the same instance).
// Cycle functions only: no allocation, no exceptions, no I/O.
#pragma once

#include <cstdint>

#include "plc_interface/axis_ref.hpp"
#include "plc_interface/command.hpp"
#include "plc_interface/error_code.hpp"

namespace fb::detail {

// What a block's start function returns on a rising edge: the command to post, or an error the
// block found itself (then nothing is posted and the block shows Error with that code).
struct Start {
  plc::Command command{};
  plc::ErrorCode error = plc::ErrorCode::kNone;
};

inline Start refuse(plc::ErrorCode code) noexcept {
  return Start{plc::Command{}, code};
}

// The outputs every Execute-type block takes its own from.
struct ExecuteOutputs {
  bool busy = false;
  bool active = false;   // busy, and NcToPlc.CmdNo is this block's command
  bool reached = false;  // busy, and the NC answers kReached (InVelocity, InGear, …)
  bool done = false;
  bool aborted = false;
  bool error = false;
  uint32_t error_id = 0;  // non-zero only with error
};

class ExecuteBlock {
 public:
  enum class Retrigger : uint8_t { kNever, kWhileReached };

  ExecuteBlock() = default;
  explicit ExecuteBlock(Retrigger retrigger) noexcept : retrigger_(retrigger) {}

  // Runs the rules once. `make_start` is called (at most once) only when a command starts.
  template <class MakeStart>
  ExecuteOutputs operator()(bool execute, plc::AXIS_REF& axis, MakeStart&& make_start) noexcept {
    if (begin_call(execute)) start_with(axis, make_start);
    return end_call(axis);
  }

  // Number of the command this block posted last (0: none yet).
  uint16_t command_number() const noexcept { return number_; }

 private:
  enum class Phase : uint8_t { kIdle, kBusy, kResult };
  enum class Outcome : uint8_t { kDone, kAborted, kError };

  // Edge detection and the reset of a result already shown; true when a command is to start.
  bool begin_call(bool execute) noexcept;
  void start(plc::AXIS_REF& axis, const Start& start) noexcept;
  // start(axis, make_start()) out of line: the command (about 100 bytes) is built on this call's
  // frame, not on the frame of every call of the block.
  template <class MakeStart>
  [[gnu::noinline]] void start_with(plc::AXIS_REF& axis, MakeStart& make_start) noexcept {
    start(axis, make_start());
  }
  // Follows the NC's answer and forms the outputs.
  ExecuteOutputs end_call(const plc::AXIS_REF& axis) noexcept;
  // The NC's answer ends the command (kDone, kAborted, kError), or its slot was reused (kFree).
  void end_command(const plc::CommandAnswer& answer) noexcept;
  void finish(Outcome outcome, uint32_t error_id) noexcept;

  Phase phase_ = Phase::kIdle;
  Outcome outcome_ = Outcome::kDone;
  bool previous_execute_ = false;
  uint16_t number_ = 0;
  uint32_t error_id_ = 0;
  Retrigger retrigger_ = Retrigger::kNever;
  bool reached_ = false;  // the last answer followed was kReached
};

// begin_call() and end_call() are inline, the ends of a command out of line (end_command): a busy
// block runs both in every PLC cycle, and inline its outputs stay in registers instead of being
// packed into a returned struct (issue 8: MC_Power + MC_MoveAbsolute 188.5 → 139.6 instructions
// per axis-cycle with the mailbox's answer() inline too, docs/performance.md).
inline bool ExecuteBlock::begin_call(bool execute) noexcept {
  const bool rising = execute && !previous_execute_;
  previous_execute_ = execute;
  // A result is always shown in the call that reaches it, so here it has been shown: it stays
  // only while Execute stays high (a new rising edge also clears it and starts again).
  if (phase_ == Phase::kResult && (!execute || rising)) phase_ = Phase::kIdle;
  if (rising && phase_ == Phase::kBusy && reached_ && retrigger_ == Retrigger::kWhileReached) {
    return true;
  }
  return rising && phase_ == Phase::kIdle;
}

inline ExecuteOutputs ExecuteBlock::end_call(const plc::AXIS_REF& axis) noexcept {
  ExecuteOutputs out;
  reached_ = false;
  if (phase_ == Phase::kBusy) {
    const plc::CommandAnswer answer = axis.Mailbox.answer(number_);
    switch (answer.state) {
      case plc::CommandState::kPosted:
      case plc::CommandState::kBuffered:  // waiting behind the running command: not Active
        out.busy = true;
        break;
      case plc::CommandState::kActive:
      case plc::CommandState::kReached:
        reached_ = answer.state == plc::CommandState::kReached;
        out.busy = true;
        out.active = axis.NcToPlc.CmdNo == number_;
        out.reached = reached_;
        break;
      default:
        end_command(answer);
        break;
    }
  }
  if (phase_ == Phase::kResult) {
    out.done = outcome_ == Outcome::kDone;
    out.aborted = outcome_ == Outcome::kAborted;
    out.error = outcome_ == Outcome::kError;
    out.error_id = error_id_;
  }
  return out;
}

// The command of a move-type block (positions, dynamics, buffer mode); 0 dynamics = axis default.
struct MotionInputs {
  double position = 0.0;
  double velocity = 0.0;
  double acceleration = 0.0;
  double deceleration = 0.0;
  double jerk = 0.0;
  int32_t direction = 0;
  int32_t buffer_mode = 0;
};

// Builds the Start of a move or halt command with its BufferMode (a value outside MC_BufferMode is
// refused locally with kBufferModeNotSupported, nothing posted). Motion parameters are passed as
// they are: the NC validates them and answers with its own code. A buffered command is answered
// kBuffered while it waits (the block is Busy, not Active) and kActive when it takes over.
Start motion_start(plc::CommandType type, const MotionInputs& inputs) noexcept;

}  // namespace fb::detail
