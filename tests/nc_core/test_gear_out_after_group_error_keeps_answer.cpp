// A slave's MC_GearIn that failed with its group's error keeps that answer when the slave is
// then reset and decoupled in motion (fuzz finding K12, docs/reliability.md): the decoupled
// slave goes on with its master's plan (SPEC C4), here the master's emergency ramp taken as a
// halt; that job has no command number of its own, so when it ends it answers nothing. Before
// the fix it answered Done on CmdNo, the MC_GearIn already answered Error 0x4358.
#include <catch2/catch.hpp>

#include "gear_rig.hpp"

using plc::CommandState;

namespace {

const uint32_t kFeedPlusMissing = plc::to_id(plc::ErrorCode::kFeedEnablePlusMissing);

}  // namespace

TEST_CASE(
    "MC_GearIn failed with the group's error stays Error after MC_Reset and MC_GearOut in "
    "motion",
    "[gear][propagation]") {
  gr::Rig rig(2);
  const uint16_t gear = rig.post(1, gr::gear_in(0, -0.5));
  rig.cycles(1);
  REQUIRE(rig.answer(1, gear).state == CommandState::kReached);
  const uint16_t move = rig.post(0, kt::move_absolute(500.0, 1000.0));
  rig.cycles(50);
  REQUIRE(rig.at(1).NcToPlc.SetVelo < -1.0);  // the slave moves at -0.5 x its master

  // The master loses its feed enable plus: its error, and the group's on the slave.
  kt::set_enables(rig.at(0), true, false, true);
  rig.cycles(1);
  REQUIRE(rig.at(0).NcToPlc.ErrorCode == kFeedPlusMissing);
  REQUIRE(rig.at(1).NcToPlc.ErrorCode == kFeedPlusMissing);
  CHECK(rig.answer(0, move).state == CommandState::kError);
  REQUIRE(rig.answer(1, gear).state == CommandState::kError);
  REQUIRE(rig.answer(1, gear).error_code == kFeedPlusMissing);
  REQUIRE(rig.at(1).NcToPlc.SetVelo != 0.0);

  // The PLC resets the slave and decouples it while it still moves (online, C4).
  plc::Command reset;
  reset.type = plc::CommandType::kReset;
  const uint16_t reset_number = rig.post(1, reset);
  const uint16_t out = rig.post(1, gr::gear_out());
  rig.cycles(1);
  CHECK(rig.answer(1, reset_number).state == CommandState::kDone);
  CHECK(rig.answer(1, out).state == CommandState::kDone);
  CHECK(rig.at(1).NcToPlc.ErrorCode == 0U);

  // It follows the master's ramp to rest; the MC_GearIn's answer never changes.
  int cycles = 0;
  while ((rig.at(1).NcToPlc.SetVelo != 0.0 || rig.at(1).NcToPlc.SetAcc != 0.0) && cycles < 5000) {
    rig.cycles(1);
    ++cycles;
    REQUIRE(rig.answer(1, gear).state == CommandState::kError);
    REQUIRE(rig.answer(1, gear).error_code == kFeedPlusMissing);
  }
  REQUIRE(cycles < 5000);
  rig.cycles(10);
  CHECK(rig.answer(1, gear).state == CommandState::kError);
  CHECK(rig.answer(1, gear).error_code == kFeedPlusMissing);
  CHECK(rig.at(1).NcToPlc.CmdNo == gear);
  CHECK(rig.at(1).NcToPlc.CmdState == static_cast<uint16_t>(CommandState::kError));
}
