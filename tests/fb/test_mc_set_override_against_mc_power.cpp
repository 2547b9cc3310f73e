// Who sets PlcToNc.Override when a program has both MC_Power (Override in %) and MC_SetOverride
// (VelFactor): MC_Power writes its Override only on its first call and when the input changes,
// MC_SetOverride on every call while enabled — so an enabled MC_SetOverride wins whatever the
// call order, and MC_Power takes over again with its next change of Override.
#include <catch2/catch.hpp>

#include "fb/mc_power.hpp"
#include "fb/mc_set_override.hpp"
#include "plc_interface/axis_ref.hpp"

namespace {

enum class Order { kPowerFirst, kSetOverrideFirst };

void plc_cycle(Order order, fb::MC_Power& power, fb::MC_SetOverride& set, plc::AXIS_REF& axis) {
  if (order == Order::kPowerFirst) {
    power(axis);
    set(axis);
  } else {
    set(axis);
    power(axis);
  }
}

}  // namespace

TEST_CASE("an enabled MC_SetOverride wins over MC_Power's unchanged Override in either call order",
          "[fb][override]") {
  const Order order = GENERATE(Order::kPowerFirst, Order::kSetOverrideFirst);
  INFO((order == Order::kPowerFirst ? "MC_Power called first" : "MC_SetOverride called first"));
  plc::AXIS_REF axis{};
  fb::MC_Power power;
  fb::MC_SetOverride set;
  power.Enable = true;
  power.Override = 100.0;

  plc_cycle(order, power, set, axis);
  REQUIRE(axis.PlcToNc.Override == 1'000'000);

  set.Enable = true;
  set.VelFactor = 0.75;  // seed 000 §2.2: 100 % → 75 %
  for (int i = 0; i < 10; ++i) {
    plc_cycle(order, power, set, axis);
    REQUIRE(axis.PlcToNc.Override == 750'000);
    REQUIRE(set.Enabled);
    REQUIRE(power.Active);
  }

  // Disabled, MC_SetOverride leaves its value; MC_Power's unchanged 100 % does not overwrite it.
  set.Enable = false;
  plc_cycle(order, power, set, axis);
  REQUIRE(axis.PlcToNc.Override == 750'000);

  // MC_Power's next change of Override is written.
  power.Override = 20.0;
  plc_cycle(order, power, set, axis);
  REQUIRE(axis.PlcToNc.Override == 200'000);
}

TEST_CASE("MC_Power writes its Override on the first call and on every change, not on every call",
          "[fb][override][power]") {
  plc::AXIS_REF axis{};
  axis.PlcToNc.Override = 0;
  fb::MC_Power power;
  power.Override = 40.0;
  power(axis);
  REQUIRE(axis.PlcToNc.Override == 400'000);

  axis.PlcToNc.Override = 123;  // another writer
  power(axis);
  REQUIRE(axis.PlcToNc.Override == 123);

  power.Override = 40.5;
  power(axis);
  REQUIRE(axis.PlcToNc.Override == 405'000);

  // A change to a bad value is not written; back to the value written last, nothing to write.
  axis.PlcToNc.Override = 777;
  power.Override = 140.0;
  power(axis);
  REQUIRE(power.ErrorID == 0x4238);
  REQUIRE(axis.PlcToNc.Override == 777);
  power.Override = 40.5;
  power(axis);
  REQUIRE_FALSE(power.Error);
  REQUIRE(axis.PlcToNc.Override == 777);
  power.Override = 41.0;
  power(axis);
  REQUIRE(axis.PlcToNc.Override == 410'000);
}
