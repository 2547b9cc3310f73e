// MC_ExtSetPointGenEnable / MC_ExtSetPointGenDisable (seed 000 §2.6, seed 001): Enable posts the
// target position for window monitoring and the start type (E_PositionType values 1 and 2) and
// refuses any other PositionType itself (0x4239, nothing posted); both are Done once the NC takes
// them; Enabled shows StateDWord bit 14 at every call, whatever Execute does.
#include <catch2/catch.hpp>

#include "fb/mc_ext_set_point_gen_disable.hpp"
#include "fb/mc_ext_set_point_gen_enable.hpp"
#include "fb/types.hpp"
#include "plc_interface/axis_ref.hpp"
#include "scripted_nc.hpp"

TEST_CASE("E_PositionType has Tc2_MC2's values", "[fb][extsetpoint]") {
  STATIC_REQUIRE(fb::POSITIONTYPE_ABSOLUTE == 1);
  STATIC_REQUIRE(fb::POSITIONTYPE_RELATIVE == 2);
}

TEST_CASE("MC_ExtSetPointGenEnable posts kExtSetPointGenEnable with Position and the start type",
          "[fb][extsetpoint]") {
  const fb::E_PositionType type = GENERATE(fb::POSITIONTYPE_ABSOLUTE, fb::POSITIONTYPE_RELATIVE);
  plc::AXIS_REF axis{};
  fbtest::ScriptedNc nc(axis);
  fb::MC_ExtSetPointGenEnable enable;
  enable.Position = 1234.5;
  enable.PositionType = type;
  enable.Execute = true;
  enable(axis);
  REQUIRE(enable.Busy);
  REQUIRE_FALSE(enable.Enabled);
  nc.cycle();
  REQUIRE(nc.taken().size() == 1);
  const plc::Command c = nc.taken().front();
  REQUIRE(c.type == plc::CommandType::kExtSetPointGenEnable);
  REQUIRE(c.position == 1234.5);
  REQUIRE(c.mode == static_cast<int32_t>(type));

  enable(axis);
  REQUIRE(enable.Done);
  REQUIRE_FALSE(enable.Busy);
  REQUIRE(enable.Enabled);
  // The command does not take the axis's job: CmdNo is untouched.
  REQUIRE(axis.NcToPlc.CmdNo == 0);
}

TEST_CASE("a PositionType outside E_PositionType gives Error 0x4239 and posts nothing",
          "[fb][extsetpoint][local]") {
  const int value = GENERATE(0, 3, -1, 255);
  INFO("PositionType " << value);
  plc::AXIS_REF axis{};
  fbtest::ScriptedNc nc(axis);
  fb::MC_ExtSetPointGenEnable enable;
  enable.PositionType = static_cast<fb::E_PositionType>(value);
  enable.Execute = true;
  enable(axis);
  REQUIRE(enable.Error);
  REQUIRE(enable.ErrorID == 0x4239);
  REQUIRE_FALSE(enable.Busy);
  REQUIRE(axis.Mailbox.pending() == 0);
  REQUIRE(enable.command_number() == 0);
  nc.cycle();
  enable(axis);
  REQUIRE(enable.ErrorID == 0x4239);  // stays while Execute stays high
  enable.Execute = false;
  enable(axis);
  REQUIRE_FALSE(enable.Error);
  REQUIRE(enable.ErrorID == 0);
}

TEST_CASE("MC_ExtSetPointGenEnable on an axis in error shows the NC's Error, Enabled stays FALSE",
          "[fb][extsetpoint]") {
  plc::AXIS_REF axis{};
  fbtest::ScriptedNc nc(axis);
  nc.fail(plc::ErrorCode::kFollowingErrorPosition);
  fb::MC_ExtSetPointGenEnable enable;
  enable.Execute = true;
  enable(axis);
  nc.cycle();
  enable(axis);
  REQUIRE(enable.Error);
  REQUIRE(enable.ErrorID == 0x4F06);
  REQUIRE_FALSE(enable.Enabled);
}

TEST_CASE("MC_ExtSetPointGenDisable posts kExtSetPointGenDisable and is Done; Enabled falls",
          "[fb][extsetpoint]") {
  plc::AXIS_REF axis{};
  fbtest::ScriptedNc nc(axis);
  fb::MC_ExtSetPointGenEnable enable;
  fb::MC_ExtSetPointGenDisable disable;
  enable.Execute = true;
  enable(axis);
  nc.cycle();
  enable(axis);
  disable(axis);
  REQUIRE(enable.Enabled);
  REQUIRE(disable.Enabled);  // shows the state without being triggered

  disable.Execute = true;
  disable(axis);
  REQUIRE(disable.Busy);
  REQUIRE(disable.Enabled);
  nc.cycle();
  REQUIRE(nc.taken().back().type == plc::CommandType::kExtSetPointGenDisable);
  disable(axis);
  enable(axis);
  REQUIRE(disable.Done);
  REQUIRE_FALSE(disable.Enabled);
  REQUIRE_FALSE(enable.Enabled);
  REQUIRE(enable.Done);  // its own result still shows while its Execute is high
}

TEST_CASE("Enabled follows StateDWord bit 14 at every call, with Execute low or high",
          "[fb][extsetpoint]") {
  plc::AXIS_REF axis{};
  fb::MC_ExtSetPointGenEnable enable;
  fb::MC_ExtSetPointGenDisable disable;
  for (int i = 0; i < 8; ++i) {
    const bool bit = (i % 3) != 0;
    enable.Execute = (i % 2) != 0;  // never posted anywhere: the mailbox just fills
    axis.NcToPlc.StateDWord = plc::with_bit(0U, plc::kStateExtSetPointGenEnabled, bit);
    enable(axis);
    disable(axis);
    REQUIRE(enable.Enabled == bit);
    REQUIRE(disable.Enabled == bit);
  }
}
