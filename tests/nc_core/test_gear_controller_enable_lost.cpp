// Issue 10 item 4: losing the controller enable while a command runs is the vendor's 0x4260 ("the
// axis or a coupled slave axis has lost its controller enable signal while executing a command"),
// for a master running a job and for a coupled slave (its coupling is the command it executes);
// the group reaction (SPEC C7) then gives every axis of the group that code. An uncoupled axis
// at rest losing its enable is no error, and neither is a slave whose enable was never there.
#include <catch2/catch.hpp>

#include "gear_rig.hpp"

namespace {

using plc::AxisState;
using plc::CommandState;

}  // namespace

TEST_CASE(
    "a coupled slave losing its controller enable while its master moves: 0x4260 on the "
    "whole group",
    "[gear][enables]") {
  gr::Rig rig(3);
  const uint16_t gear = rig.post(1, gr::gear_in(0, 2.0));
  rig.cycles(1);
  REQUIRE(rig.answer(1, gear).state == CommandState::kReached);
  const uint16_t move = rig.post(0, kt::move_absolute(20000.0, 1000.0));
  rig.post(2, kt::move_absolute(20000.0, 1000.0));  // beside the group
  rig.cycles(500);
  kt::set_enables(rig.at(1), false);
  rig.cycles(1);
  CHECK(rig.at(1).NcToPlc.ErrorCode == 0x4260U);
  CHECK(rig.at(0).NcToPlc.ErrorCode == 0x4260U);  // the group reaction, same cycle
  // The coupling stays, as after any group reaction (docs/behaviour.md "Slave axes").
  CHECK(rig.at(1).NcToPlc.CoupleState == 3U);
  CHECK(rig.answer(0, move).state == CommandState::kError);
  CHECK(kt::axis_state(rig.at(0)) == AxisState::kErrorStop);
  CHECK(rig.at(2).NcToPlc.ErrorCode == 0U);  // not in the group
  CHECK(rig.at(2).NcToPlc.SetVelo == 1000.0);
}

TEST_CASE("a master losing its controller enable while its slave follows: 0x4260 on both",
          "[gear][enables]") {
  gr::Rig rig(2);
  REQUIRE(rig.couple(1, 0, -0.5).state == CommandState::kReached);
  rig.post(0, kt::move_absolute(20000.0, 1000.0));
  rig.cycles(500);
  kt::set_enables(rig.at(0), false);
  rig.cycles(1);
  CHECK(rig.at(0).NcToPlc.ErrorCode == 0x4260U);
  CHECK(rig.at(1).NcToPlc.ErrorCode == 0x4260U);
}

TEST_CASE(
    "a coupled slave losing its enable at rest is 0x4260 as well; an uncoupled axis at "
    "rest is not an error",
    "[gear][enables]") {
  gr::Rig rig(3);
  REQUIRE(rig.couple(1, 0, 1.5).state == CommandState::kReached);
  kt::set_enables(rig.at(1), false);
  kt::set_enables(rig.at(2), false);
  rig.cycles(1);
  CHECK(rig.at(1).NcToPlc.ErrorCode == 0x4260U);
  CHECK(rig.at(0).NcToPlc.ErrorCode == 0x4260U);
  CHECK(rig.at(2).NcToPlc.ErrorCode == 0U);
  CHECK(kt::axis_state(rig.at(2)) == AxisState::kDisabled);
  // Only the edge is an error: after MC_Reset with the enable still off nothing comes back.
  rig.post(1, kt::simple(plc::CommandType::kReset));
  rig.cycles(2);
  CHECK(rig.at(1).NcToPlc.ErrorCode == 0U);
}
