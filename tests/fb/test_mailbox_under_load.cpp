// Mailbox under load (issue 16, item 4; plc_interface/command.hpp): a PLC cycle that posts more
// commands to one axis than its mailbox holds (CommandMailbox::kQueueCapacity = 16). The blocks
// whose command found the mailbox full show Error 0x4F04 (kMailboxFull) and posted nothing; every
// command that was posted is answered in the next NC cycle — none is dropped: each earlier move
// is aborted by the next one (CommandAborted), the last runs to its target (Done), and the
// answer table keeps every number's outcome. Once the mailbox has room, the refused blocks post
// on their next rising edge.
#include <catch2/catch.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

#include "fb/fb.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/kernel.hpp"

namespace {

constexpr std::size_t kCapacity = plc::CommandMailbox::kQueueCapacity;  // 16
constexpr std::size_t kBlocks = kCapacity + 4;                          // 4 too many
constexpr uint32_t kMailboxFull = 0x4F04;

// An enabled axis and kBlocks MC_MoveRelative blocks; block i moves by 10·(i+1) mm.
struct Load {
  nc::Kernel kernel;
  plc::AXIS_REF& axis;
  fb::MC_Power power;
  std::array<fb::MC_MoveRelative, kBlocks> moves;

  Load() : axis(kernel.add_axis(config())) {
    for (std::size_t i = 0; i < kBlocks; ++i) {
      moves[i].Distance = 10.0 * static_cast<double>(i + 1);
      moves[i].Velocity = 1'000.0;
    }
    // Enables in.
    for (int i = 0; i < 3; ++i)
      tick(false);
  }
  static nc::AxisConfig config() {
    nc::AxisConfig c;
    c.name = "X";
    return c;
  }
  // One PLC cycle (power, then every move block with `execute`), then one NC cycle.
  void tick(bool execute) {
    power.Enable = power.Enable_Positive = power.Enable_Negative = true;
    power(axis);
    for (auto& m : moves) {
      m.Execute = execute;
      m(axis);
    }
    kernel.cycle();
  }
};

}  // namespace

TEST_CASE("more commands than the mailbox holds: the extra ones are refused with 0x4F04",
          "[fb][kernel][mailbox]") {
  Load load;
  // One PLC cycle: 20 rising edges. Call the blocks without the NC cycle first.
  load.power(load.axis);
  for (auto& m : load.moves) {
    m.Execute = true;
    m(load.axis);
  }
  REQUIRE(load.axis.Mailbox.pending() == kCapacity);
  for (std::size_t i = 0; i < kBlocks; ++i) {
    INFO("block " << i);
    if (i < kCapacity) {
      REQUIRE(load.moves[i].Busy);
      REQUIRE_FALSE(load.moves[i].Error);
      REQUIRE(load.moves[i].command_number() != 0);
    } else {
      REQUIRE(load.moves[i].Error);
      REQUIRE(load.moves[i].ErrorID == kMailboxFull);
      REQUIRE_FALSE(load.moves[i].Busy);
      REQUIRE(load.moves[i].command_number() == 0);  // nothing was posted
    }
  }
}

TEST_CASE("under load no posted command is dropped: each is answered, the last one runs to Done",
          "[fb][kernel][mailbox]") {
  Load load;
  load.tick(true);  // 16 posted, 4 refused; the NC takes all 16 in this cycle
  REQUIRE(load.axis.Mailbox.pending() == 0);
  for (std::size_t i = 0; i < kCapacity; ++i) {
    INFO("command of block " << i);
    const plc::CommandAnswer answer = load.axis.Mailbox.answer(load.moves[i].command_number());
    // Each one accepted and then aborted by the next one; the last one runs.
    REQUIRE(answer.state ==
            (i + 1 < kCapacity ? plc::CommandState::kAborted : plc::CommandState::kActive));
  }
  load.tick(true);  // the blocks see their answers
  for (std::size_t i = 0; i < kBlocks; ++i) {
    INFO("block " << i);
    if (i + 1 < kCapacity) {
      REQUIRE(load.moves[i].CommandAborted);
      REQUIRE_FALSE(load.moves[i].Error);
    } else if (i + 1 == kCapacity) {
      REQUIRE(load.moves[i].Busy);
      REQUIRE(load.moves[i].Active);
    } else {
      REQUIRE(load.moves[i].Error);
      REQUIRE(load.moves[i].ErrorID == kMailboxFull);  // stays while Execute stays high
    }
  }
  // The 16th command (160 mm from 0) runs to its end.
  int cycles = 0;
  while (!load.moves[kCapacity - 1].Done && cycles < 5'000) {
    load.tick(true);
    ++cycles;
  }
  REQUIRE(load.moves[kCapacity - 1].Done);
  REQUIRE(load.axis.NcToPlc.SetPos == Approx(160.0).margin(1e-9));
  REQUIRE(load.axis.NcToPlc.ErrorCode == 0);
  // The earlier outcomes are still in the answer table: nothing was overwritten or lost.
  for (std::size_t i = 0; i + 1 < kCapacity; ++i) {
    REQUIRE(load.axis.Mailbox.answer(load.moves[i].command_number()).state ==
            plc::CommandState::kAborted);
  }
}

TEST_CASE("the refused blocks post on their next rising edge once the mailbox has room",
          "[fb][kernel][mailbox]") {
  Load load;
  load.tick(true);
  load.tick(false);  // Execute falls: results shown once, outputs reset
  load.tick(false);
  for (std::size_t i = 0; i < kBlocks; ++i) {
    INFO("block " << i);
    REQUIRE_FALSE(load.moves[i].Error);
    // The 16th block's move still runs; a falling Execute never aborts it.
    REQUIRE(load.moves[i].Busy == (i + 1 == kCapacity));
  }
  // Only the four refused blocks rise again: they fit now.
  load.power(load.axis);
  for (std::size_t i = kCapacity; i < kBlocks; ++i) {
    load.moves[i].Execute = true;
    load.moves[i](load.axis);
    REQUIRE(load.moves[i].Busy);
    REQUIRE(load.moves[i].command_number() != 0);
  }
  REQUIRE(load.axis.Mailbox.pending() == kBlocks - kCapacity);
  load.kernel.cycle();
  REQUIRE(load.axis.Mailbox.pending() == 0);
  // The last of them (200 mm) is the axis's command now; the running move and the other three
  // were aborted by it.
  REQUIRE(load.axis.NcToPlc.CmdNo == load.moves[kBlocks - 1].command_number());
  for (std::size_t i = kCapacity - 1; i + 1 < kBlocks; ++i) {
    REQUIRE(load.axis.Mailbox.answer(load.moves[i].command_number()).state ==
            plc::CommandState::kAborted);
  }
}
