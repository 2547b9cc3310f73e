// Fuzz finding K21 through the kernel: a move runs for long (command 1, kActive) while the PLC
// posts 64 resets (each answered kDone at once, seed behaviour "Reset and stop release are
// answered in the same cycle"); the 64th reset is number 65, in command 1's answer slot. Then the
// controller enable is lost: the move ends with 0x4260. Its late answer must not overwrite reset
// 65's kDone — before the fix the slot showed command 1's error and the reset's block read kFree
// (its answer lost), which MC_Reset reports as 0x4F05 (unknown command) although it was done.
#include <catch2/catch.hpp>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::CommandType;

TEST_CASE("a late answer of a long-running move leaves a newer command's answer in its slot",
          "[kernel][answers]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(1000.0, 10.0));  // 100 s at 10 mm/s
  REQUIRE(move == 1);
  h.cycles(1);
  REQUIRE(h.state_of(move) == CommandState::kActive);

  uint16_t reset = 0;
  for (std::size_t i = 0; i < plc::CommandMailbox::kAnswerSlots; ++i) {
    reset = h.post(kt::simple(CommandType::kReset));
    h.cycles(1);
    REQUIRE(h.state_of(reset) == CommandState::kDone);
  }
  REQUIRE(reset == 1 + plc::CommandMailbox::kAnswerSlots);
  CHECK(h.x->NcToPlc.CmdNo == move);  // the move still runs: resets do not take CmdNo
  CHECK(h.x->NcToPlc.SetVelo > 9.0);

  kt::set_enables(*h.x, false);
  h.cycles(1);
  CHECK(h.x->NcToPlc.ErrorCode == 0x4260U);
  CHECK(h.x->NcToPlc.CmdState == static_cast<uint16_t>(CommandState::kError));
  const plc::CommandAnswer kept = h.answer(reset);
  CHECK(kept.number == reset);
  CHECK(kept.state == CommandState::kDone);
  CHECK(kept.error_code == 0U);
  CHECK(h.state_of(move) == CommandState::kFree);  // its slot is reset 65's: unknown to the PLC
}
