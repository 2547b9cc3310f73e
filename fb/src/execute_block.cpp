#include "fb/detail/execute_block.hpp"

#include "fb/types.hpp"

namespace fb::detail {

bool ExecuteBlock::begin_call(bool execute) noexcept {
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

void ExecuteBlock::start(plc::AXIS_REF& axis, const Start& start) noexcept {
  if (start.error != plc::ErrorCode::kNone) {
    finish(Outcome::kError, plc::to_id(start.error));
    return;
  }
  const uint16_t number = axis.Mailbox.post(start.command);
  if (number == 0) {
    finish(Outcome::kError, plc::to_id(plc::ErrorCode::kMailboxFull));
    return;
  }
  number_ = number;
  phase_ = Phase::kBusy;
  reached_ = false;
}

void ExecuteBlock::finish(Outcome outcome, uint32_t error_id) noexcept {
  phase_ = Phase::kResult;
  outcome_ = outcome;
  error_id_ = outcome == Outcome::kError ? error_id : 0;
}

ExecuteOutputs ExecuteBlock::end_call(const plc::AXIS_REF& axis) noexcept {
  ExecuteOutputs out;
  reached_ = false;
  if (phase_ == Phase::kBusy) {
    const plc::CommandAnswer answer = axis.Mailbox.answer(number_);
    reached_ = answer.state == plc::CommandState::kReached;
    switch (answer.state) {
      case plc::CommandState::kPosted:
      case plc::CommandState::kBuffered:  // waiting behind the running command: not Active
        out.busy = true;
        break;
      case plc::CommandState::kActive:
      case plc::CommandState::kReached:
        out.busy = true;
        out.active = axis.NcToPlc.CmdNo == number_;
        out.reached = answer.state == plc::CommandState::kReached;
        break;
      case plc::CommandState::kDone:
        finish(Outcome::kDone, 0);
        break;
      case plc::CommandState::kAborted:
        finish(Outcome::kAborted, 0);
        break;
      case plc::CommandState::kError:
        finish(Outcome::kError, answer.error_code);
        break;
      case plc::CommandState::kFree:
        // The answer slot was reused: more than CommandMailbox::kAnswerSlots newer commands on
        // this axis while the block was not called. Its outcome is unknown.
        finish(Outcome::kError, plc::to_id(plc::ErrorCode::kUnknownCommand));
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

Start motion_start(plc::CommandType type, const MotionInputs& inputs) noexcept {
  if (inputs.buffer_mode < MC_Aborting || inputs.buffer_mode > MC_BlendingHigh) {
    return refuse(plc::ErrorCode::kBufferModeNotSupported);
  }
  Start start;
  start.command.type = type;
  start.command.position = inputs.position;
  start.command.velocity = inputs.velocity;
  start.command.acceleration = inputs.acceleration;
  start.command.deceleration = inputs.deceleration;
  start.command.jerk = inputs.jerk;
  start.command.direction = inputs.direction;
  start.command.buffer_mode = inputs.buffer_mode;
  return start;
}

}  // namespace fb::detail
