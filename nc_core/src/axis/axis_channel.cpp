#include "axis/axis_channel.hpp"

namespace nc::detail {

namespace {

using plc::CommandState;

constexpr plc::ErrorCode kWarningCodes[] = {
    plc::ErrorCode::kMovementSmallerThanIncrement, plc::ErrorCode::kOverrideNotAllowed,
    plc::ErrorCode::kCompensationIncomplete, plc::ErrorCode::kAccBoundBelowStability,
    plc::ErrorCode::kGearRatio1NotTaken};

}  // namespace

bool AxisChannel::runs(uint16_t job_number) const noexcept {
  return job_number != 0 && job_number == cmd_no_ &&
         (cmd_state_ == CommandState::kActive || cmd_state_ == CommandState::kReached);
}

void AxisChannel::take_over(uint16_t number, uint16_t running_job) noexcept {
  if (runs(running_job)) answer_current(CommandState::kAborted);
  cmd_no_ = number;
  answer_current(CommandState::kActive);
}

void AxisChannel::answer_current(plc::CommandState state, uint32_t code) noexcept {
  cmd_state_ = state;
  warnings.changed = true;  // changed()
  ref_.Mailbox.set_answer(cmd_no_, state, code);
}

bool AxisChannel::raise(plc::ErrorCode code) noexcept {
  if (error_ != plc::ErrorCode::kNone) return false;
  error_ = code;
  warnings.changed = true;  // changed()
  return true;
}

uint32_t AxisWarnings::code() const noexcept {
  if (bits_ == 0) return 0;
  if ((bits_ & warning_bit(last_)) != 0) return plc::to_id(kWarningCodes[static_cast<int>(last_)]);
  // The last one was cleared: the first of those still latched.
  for (unsigned i = 0; i < 3; ++i) {
    if ((bits_ & (1U << i)) != 0) return plc::to_id(kWarningCodes[i]);
  }
  return 0;
}

}  // namespace nc::detail
