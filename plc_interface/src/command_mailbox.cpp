#include "plc_interface/command.hpp"

namespace plc {

uint16_t CommandMailbox::post(Command command) noexcept {
  if (count_ == kQueueCapacity) return 0;
  last_number_ = static_cast<uint16_t>(last_number_ + 1U);
  if (last_number_ == 0) last_number_ = 1;  // 0 means "no command"
  command.number = last_number_;
  queue_[(head_ + count_) % kQueueCapacity] = command;
  ++count_;
  set_answer(command.number, CommandState::kPosted);
  return command.number;
}

bool CommandMailbox::take(Command& out) noexcept {
  if (count_ == 0) return false;
  out = queue_[head_];
  head_ = (head_ + 1) % kQueueCapacity;
  --count_;
  return true;
}

void CommandMailbox::set_answer(uint16_t number, CommandState state, uint32_t error_code) noexcept {
  if (number == 0) return;
  CommandAnswer& slot = answers_[number % kAnswerSlots];
  // A slot belongs to the newest number that maps to it. Numbers wrap (65535 → 1), so "newer"
  // is a distance below half the range; the skipped 0 shifts it by one only across the wrap.
  const auto ahead = static_cast<uint16_t>(slot.number - number);
  if (slot.number != 0 && ahead != 0 && ahead < 0x8000U) return;  // `number` is older: too late
  slot = CommandAnswer{number, state, error_code};
}

}  // namespace plc
