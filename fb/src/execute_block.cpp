#include "fb/detail/execute_block.hpp"

#include "fb/types.hpp"

namespace fb::detail {

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

void ExecuteBlock::end_command(const plc::CommandAnswer& answer) noexcept {
  switch (answer.state) {
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
    case plc::CommandState::kPosted:
    case plc::CommandState::kBuffered:
    case plc::CommandState::kActive:
    case plc::CommandState::kReached:
      break;  // still running: end_call() shows it
  }
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
