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
  ref_.Mailbox.set_answer(cmd_no_, state, code);
}

bool AxisChannel::raise(plc::ErrorCode code) noexcept {
  if (error_ != plc::ErrorCode::kNone) return false;
  error_ = code;
  return true;
}

void AxisChannel::clear_warnings_except(Warning keep) noexcept {
  warnings_ = static_cast<uint8_t>(warnings_ & warning_bit(keep));
}

uint32_t AxisChannel::warning_code() const noexcept {
  if (warnings_ == 0) return 0;
  if ((warnings_ & warning_bit(last_warning_)) != 0)
    return plc::to_id(kWarningCodes[static_cast<int>(last_warning_)]);
  // The last one was cleared: the first of those still latched.
  for (unsigned i = 0; i < 3; ++i) {
    if ((warnings_ & (1U << i)) != 0) return plc::to_id(kWarningCodes[i]);
  }
  return 0;
}

}  // namespace nc::detail
