// MC_Power writes the enables into PlcToNc.ControlDWord (bit 0 Enable, 1 FeedEnablePlus,
// 2 FeedEnableMinus; the feed enables only with Enable) and the override in percent as
// round(Override · 10 000) into PlcToNc.Override (1 000 000 = 100 %) on its first call and
// whenever the input changes (test_mc_set_override_against_mc_power.cpp). An override outside
// 0 … 100 % or NaN is not written and shows Error 0x4238. Status = Operational bit.
#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>

#include "plc_interface/axis_ref.hpp"
#include "scripted_nc.hpp"

#include "fb/mc_power.hpp"

TEST_CASE("Enable, Enable_Positive and Enable_Negative set ControlDWord bits 0, 1 and 2",
          "[fb][power]") {
  struct Row {
    bool enable, positive, negative;
    uint32_t bits;
  };
  const Row row = GENERATE(Row{false, false, false, 0b000}, Row{true, false, false, 0b001},
                           Row{true, true, false, 0b011}, Row{true, false, true, 0b101},
                           Row{true, true, true, 0b111},
                           // feed enables take effect only with Enable
                           Row{false, true, true, 0b000}, Row{false, true, false, 0b000});
  INFO("Enable " << row.enable << " Positive " << row.positive << " Negative " << row.negative);
  plc::AXIS_REF axis{};
  fb::MC_Power power;
  power.Enable = row.enable;
  power.Enable_Positive = row.positive;
  power.Enable_Negative = row.negative;
  power(axis);
  REQUIRE(axis.PlcToNc.ControlDWord == row.bits);
  REQUIRE(power.Busy == row.enable);
  REQUIRE(power.Active == row.enable);
  REQUIRE_FALSE(power.Error);
}

TEST_CASE(
    "MC_Power leaves the other ControlDWord bits alone and clears its own when Enable "
    "falls",
    "[fb][power]") {
  plc::AXIS_REF axis{};
  axis.PlcToNc.ControlDWord = 0xF0U;
  fb::MC_Power power;
  power.Enable = true;
  power.Enable_Positive = true;
  power.Enable_Negative = true;
  power(axis);
  REQUIRE(axis.PlcToNc.ControlDWord == 0xF7U);
  power.Enable = false;
  power(axis);
  REQUIRE(axis.PlcToNc.ControlDWord == 0xF0U);
  REQUIRE_FALSE(power.Busy);
  REQUIRE_FALSE(power.Active);
}

TEST_CASE("Override in percent becomes round(Override * 10000) in PlcToNc.Override",
          "[fb][power]") {
  struct Row {
    double percent;
    uint32_t raw;
  };
  const Row row =
      GENERATE(Row{100.0, 1'000'000}, Row{0.0, 0}, Row{50.0, 500'000}, Row{68.123, 681'230},
               Row{12.34567, 123'457}, Row{0.00004, 0}, Row{0.00005, 1}, Row{99.99999, 1'000'000});
  INFO("Override " << row.percent);
  plc::AXIS_REF axis{};
  fb::MC_Power power;
  power.Enable = true;
  power.Override = row.percent;
  power(axis);
  REQUIRE(axis.PlcToNc.Override == row.raw);
  REQUIRE_FALSE(power.Error);
  REQUIRE(power.ErrorID == 0);
}

TEST_CASE("the default Override is 100 % = 1 000 000", "[fb][power]") {
  plc::AXIS_REF axis{};
  axis.PlcToNc.Override = 0;
  fb::MC_Power power;
  power(axis);
  REQUIRE(power.Override == 100.0);
  REQUIRE(axis.PlcToNc.Override == 1'000'000);
}

TEST_CASE(
    "an Override outside 0 ... 100 % or NaN gives Error 0x4238 and leaves the written "
    "override unchanged",
    "[fb][power]") {
  const double bad =
      GENERATE(-0.001, 100.001, 150.0, -100.0, std::numeric_limits<double>::quiet_NaN(),
               std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity());
  INFO("Override " << bad);
  plc::AXIS_REF axis{};
  fb::MC_Power power;
  power.Enable = true;
  power.Enable_Positive = true;
  power.Override = 40.0;
  power(axis);
  REQUIRE(axis.PlcToNc.Override == 400'000);

  power.Override = bad;
  power(axis);
  REQUIRE(power.Error);
  REQUIRE(power.ErrorID == 0x4238);
  REQUIRE_FALSE(power.Active);
  REQUIRE(power.Busy);
  REQUIRE(axis.PlcToNc.Override == 400'000);
  // The enables are still written.
  REQUIRE(axis.PlcToNc.ControlDWord == 0b011);

  power.Override = 75.0;
  power(axis);
  REQUIRE_FALSE(power.Error);
  REQUIRE(power.ErrorID == 0);
  REQUIRE(axis.PlcToNc.Override == 750'000);
}

TEST_CASE("Status follows the Operational bit of StateDWord", "[fb][power]") {
  plc::AXIS_REF axis{};
  fbtest::ScriptedNc nc(axis);
  fb::MC_Power power;
  power.Enable = true;
  nc.set_operational(false);
  power(axis);
  REQUIRE_FALSE(power.Status);
  nc.set_operational(true);
  power(axis);
  REQUIRE(power.Status);
  axis.NcToPlc.StateDWord = 0xFFFFFFFEU;  // every bit but Operational
  power(axis);
  REQUIRE_FALSE(power.Status);
}
