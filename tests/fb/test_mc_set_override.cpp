// MC_SetOverride (seed 000 §2.2): while Enable is TRUE it writes PlcToNc.Override =
// round(VelFactor · 1 000 000) on every call (1.0 = 100 %). A VelFactor outside 0 … 1 or NaN
// is not written and shows Error 0x4238 until the input is valid again; Enable FALSE resets the
// outputs and writes nothing, so the override keeps the value written last.
#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>

#include "fb/mc_set_override.hpp"
#include "plc_interface/axis_ref.hpp"

TEST_CASE("VelFactor becomes round(VelFactor * 1 000 000) in PlcToNc.Override", "[fb][override]") {
  struct Row {
    double factor;
    uint32_t raw;
  };
  // 0.75 and 0.2 are the seed's override levels (100 % → 75 % → 100 %, 20 % → 100 %).
  const Row row = GENERATE(Row{1.0, 1'000'000}, Row{0.75, 750'000}, Row{0.2, 200'000}, Row{0.0, 0},
                           Row{0.000001, 1}, Row{0.0000004, 0}, Row{0.12345678, 123'457},
                           Row{0.9999996, 1'000'000});
  INFO("VelFactor " << row.factor);
  plc::AXIS_REF axis{};
  axis.PlcToNc.Override = 424'242;
  fb::MC_SetOverride set;
  set.Enable = true;
  set.VelFactor = row.factor;
  set(axis);
  REQUIRE(axis.PlcToNc.Override == row.raw);
  REQUIRE(set.Enabled);
  REQUIRE(set.Busy);
  REQUIRE_FALSE(set.Error);
  REQUIRE(set.ErrorID == 0);
}

TEST_CASE("the default VelFactor is 1.0 = 100 %", "[fb][override]") {
  plc::AXIS_REF axis{};
  axis.PlcToNc.Override = 0;
  fb::MC_SetOverride set;
  REQUIRE(set.VelFactor == 1.0);
  set.Enable = true;
  set(axis);
  REQUIRE(axis.PlcToNc.Override == 1'000'000);
}

TEST_CASE("while enabled the override is written on every call, also over another writer",
          "[fb][override]") {
  plc::AXIS_REF axis{};
  fb::MC_SetOverride set;
  set.Enable = true;
  set.VelFactor = 0.75;
  for (int i = 0; i < 5; ++i) {
    axis.PlcToNc.Override = 100'000;  // somebody else wrote 10 %
    set(axis);
    REQUIRE(axis.PlcToNc.Override == 750'000);
  }
  set.VelFactor = 1.0;
  set(axis);
  REQUIRE(axis.PlcToNc.Override == 1'000'000);
}

TEST_CASE(
    "Enable FALSE writes nothing and resets the outputs; the override keeps the value written "
    "last",
    "[fb][override]") {
  plc::AXIS_REF axis{};
  axis.PlcToNc.Override = 333'333;
  fb::MC_SetOverride set;
  set.VelFactor = 0.5;
  set(axis);
  REQUIRE(axis.PlcToNc.Override == 333'333);
  REQUIRE_FALSE(set.Enabled);
  REQUIRE_FALSE(set.Busy);
  REQUIRE_FALSE(set.Error);

  set.Enable = true;
  set(axis);
  REQUIRE(axis.PlcToNc.Override == 500'000);
  REQUIRE(set.Enabled);

  set.Enable = false;
  set.VelFactor = 0.9;
  set(axis);
  REQUIRE(axis.PlcToNc.Override == 500'000);
  REQUIRE_FALSE(set.Enabled);
  REQUIRE_FALSE(set.Busy);
  REQUIRE_FALSE(set.Error);
  REQUIRE(set.ErrorID == 0);
}

TEST_CASE(
    "a VelFactor outside 0 ... 1 or NaN gives Error 0x4238, Enabled FALSE and leaves the "
    "override unchanged",
    "[fb][override]") {
  const double bad =
      GENERATE(-0.000001, -1.0, 1.000001, 2.0, 75.0, std::numeric_limits<double>::infinity(),
               -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN());
  INFO("VelFactor " << bad);
  plc::AXIS_REF axis{};
  fb::MC_SetOverride set;
  set.Enable = true;
  set.VelFactor = 0.4;
  set(axis);
  REQUIRE(axis.PlcToNc.Override == 400'000);

  set.VelFactor = bad;
  for (int i = 0; i < 3; ++i) {
    set(axis);
    REQUIRE(set.Error);
    REQUIRE(set.ErrorID == 0x4238);
    REQUIRE_FALSE(set.Enabled);
    REQUIRE(set.Busy);
    REQUIRE(axis.PlcToNc.Override == 400'000);
  }

  // A bad value with Enable FALSE is not looked at.
  set.Enable = false;
  set(axis);
  REQUIRE_FALSE(set.Error);
  REQUIRE(set.ErrorID == 0);

  set.Enable = true;
  set.VelFactor = 0.6;
  set(axis);
  REQUIRE_FALSE(set.Error);
  REQUIRE(set.ErrorID == 0);
  REQUIRE(set.Enabled);
  REQUIRE(axis.PlcToNc.Override == 600'000);
}
