// MC_ExtSetPointGenFeed (seed 000 §2.6 "Specification of setpoints"): a function that copies one
// setpoint packet into PlcToNc at once. Its result reads FALSE (0) like Tc2_MC2's unused result
// whenever the packet is written; a Direction other than -1, 0 or +1 returns 0x4F07 and writes
// nothing (the NC keeps the last packet).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

#include "fb/mc_ext_set_point_gen_feed.hpp"
#include "plc_interface/axis_ref.hpp"

TEST_CASE("the packet lands in PlcToNc.ExtSetPos/ExtSetVelo/ExtSetAcc/ExtSetDirection at once",
          "[fb][extsetpoint]") {
  const int32_t direction = GENERATE(-1, 0, 1);
  plc::AXIS_REF axis{};
  const uint32_t result = fb::MC_ExtSetPointGenFeed(12.25, -300.0, 5000.0, direction, axis);
  REQUIRE(result == 0);
  REQUIRE_FALSE(static_cast<bool>(result));  // Tc2_MC2: the result reads FALSE
  REQUIRE(axis.PlcToNc.ExtSetPos == 12.25);
  REQUIRE(axis.PlcToNc.ExtSetVelo == -300.0);
  REQUIRE(axis.PlcToNc.ExtSetAcc == 5000.0);
  REQUIRE(axis.PlcToNc.ExtSetDirection == direction);
}

TEST_CASE("a Direction other than -1, 0 or +1 returns 0x4F07 and writes nothing",
          "[fb][extsetpoint][local]") {
  const int32_t direction = GENERATE(2, -2, 3, 128, std::numeric_limits<int32_t>::min());
  INFO("direction " << direction);
  plc::AXIS_REF axis{};
  REQUIRE(fb::MC_ExtSetPointGenFeed(10.0, 100.0, 0.0, 1, axis) == 0);
  REQUIRE(fb::MC_ExtSetPointGenFeed(11.0, 200.0, 50.0, direction, axis) == 0x4F07);
  REQUIRE(axis.PlcToNc.ExtSetPos == 10.0);
  REQUIRE(axis.PlcToNc.ExtSetVelo == 100.0);
  REQUIRE(axis.PlcToNc.ExtSetAcc == 0.0);
  REQUIRE(axis.PlcToNc.ExtSetDirection == 1);
}

TEST_CASE("values are passed unchecked: the NC validates them", "[fb][extsetpoint]") {
  plc::AXIS_REF axis{};
  REQUIRE(fb::MC_ExtSetPointGenFeed(std::numeric_limits<double>::quiet_NaN(),
                                    std::numeric_limits<double>::infinity(), -1e300, 1, axis) == 0);
  REQUIRE(std::isnan(axis.PlcToNc.ExtSetPos));
  REQUIRE(std::isinf(axis.PlcToNc.ExtSetVelo));
  REQUIRE(axis.PlcToNc.ExtSetAcc == -1e300);
}

TEST_CASE("the function touches nothing but the four ExtSet fields", "[fb][extsetpoint]") {
  plc::AXIS_REF axis{};
  axis.PlcToNc.ControlDWord = 7;
  axis.PlcToNc.Override = 500'000;
  axis.PlcToNc.GearRatio1 = 2.5;
  fb::MC_ExtSetPointGenFeed(1.0, 2.0, 3.0, -1, axis);
  REQUIRE(axis.PlcToNc.ControlDWord == 7);
  REQUIRE(axis.PlcToNc.Override == 500'000);
  REQUIRE(axis.PlcToNc.GearRatio1 == 2.5);
  REQUIRE(axis.Mailbox.pending() == 0);
}
