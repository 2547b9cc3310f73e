// The answer table of plc::CommandMailbox (plc_interface/command.hpp): 64 slots indexed by command
// number, a slot belongs to the newest number that maps to it. The NC answering an old command
// after its slot went to a newer one must not overwrite the newer answer (fuzz finding K21: the
// newer command's answer was lost, its block saw kFree).
#include <catch2/catch.hpp>

#include <cstdint>

#include "plc_interface/command.hpp"

using plc::CommandMailbox;
using plc::CommandState;

namespace {

// Posts and takes one command; returns its number.
uint16_t post_and_take(CommandMailbox& mailbox) {
  const uint16_t number = mailbox.post(plc::Command{});
  plc::Command taken;
  REQUIRE(mailbox.take(taken));
  REQUIRE(taken.number == number);
  return number;
}

}  // namespace

TEST_CASE("a late answer for a number whose slot a newer number took keeps the newer answer",
          "[mailbox][answers]") {
  CommandMailbox mailbox;
  const uint16_t old_number = post_and_take(mailbox);
  CHECK(old_number == 1);
  mailbox.set_answer(old_number, CommandState::kActive);
  uint16_t newer = 0;
  for (std::size_t i = 0; i < CommandMailbox::kAnswerSlots; ++i)
    newer = post_and_take(mailbox);
  REQUIRE(newer == 1 + CommandMailbox::kAnswerSlots);  // the same slot as command 1
  mailbox.set_answer(newer, CommandState::kDone);

  // The NC answers command 1 at last (its job failed): the slot stays command 65's.
  mailbox.set_answer(old_number, CommandState::kError, 0x4260);
  const plc::CommandAnswer kept = mailbox.answer(newer);
  CHECK(kept.number == newer);
  CHECK(kept.state == CommandState::kDone);
  CHECK(kept.error_code == 0U);
  CHECK(mailbox.answer(old_number).state == CommandState::kFree);  // too old: unknown
}

TEST_CASE("a newer number takes its slot over from an older one, also across the wrap",
          "[mailbox][answers]") {
  CommandMailbox mailbox;
  // Numbers run 1 … 65535 and wrap to 1 (0 is skipped): walk to just before the wrap.
  uint16_t number = 0;
  for (int i = 0; i < 65535 - 10; ++i)
    number = post_and_take(mailbox);
  REQUIRE(number == 65525);
  mailbox.set_answer(number, CommandState::kDone);
  CHECK(mailbox.answer(number).state == CommandState::kDone);

  // 65525 % 64 = 53: the next number in that slot comes after the wrap (65526 … 65535, 1 …):
  // 53 itself.
  uint16_t after_wrap = 0;
  do {
    after_wrap = post_and_take(mailbox);
  } while (after_wrap != 53);
  CHECK(mailbox.answer(53).state == CommandState::kPosted);  // post() took the slot over
  mailbox.set_answer(53, CommandState::kActive);
  CHECK(mailbox.answer(53).state == CommandState::kActive);
  CHECK(mailbox.answer(65525).state == CommandState::kFree);

  // A late answer for 65525 (before the wrap, so older) leaves 53's answer alone.
  mailbox.set_answer(65525, CommandState::kAborted);
  CHECK(mailbox.answer(53).state == CommandState::kActive);
  CHECK(mailbox.answer(65525).state == CommandState::kFree);
}

TEST_CASE("answers of numbers that keep their slots change as the NC sets them",
          "[mailbox][answers]") {
  CommandMailbox mailbox;
  const uint16_t a = post_and_take(mailbox);
  const uint16_t b = post_and_take(mailbox);
  mailbox.set_answer(a, CommandState::kActive);
  mailbox.set_answer(b, CommandState::kError, 0x4F04);
  mailbox.set_answer(a, CommandState::kAborted);
  CHECK(mailbox.answer(a).state == CommandState::kAborted);
  CHECK(mailbox.answer(b).state == CommandState::kError);
  CHECK(mailbox.answer(b).error_code == 0x4F04U);

  // 0 means "no command": nothing is written, not even into slot 0 (number 64's).
  uint16_t in_slot_0 = b;
  while (in_slot_0 != CommandMailbox::kAnswerSlots)
    in_slot_0 = post_and_take(mailbox);
  mailbox.set_answer(in_slot_0, CommandState::kActive);
  mailbox.set_answer(0, CommandState::kDone);
  CHECK(mailbox.answer(in_slot_0).state == CommandState::kActive);
}
