// The same MC_GearIn instance re-triggered while InGear (issue 9 decision; SPEC C2, seed 000
// §3.2.2 "Coupling with variable coupling factor"): master 0 → 2000 mm at V 2000, factor -0.7,
// then the same instance's Execute falls and rises with -0.8: a new command, InGear again in the
// next NC cycle, the slave's position continuous and its velocity -0.8 × the master's from then
// on; the instance never shows CommandAborted for its own take-over. A re-trigger the block
// refuses itself (RatioDenominator 0) shows Error and leaves the coupling as it was; a rising
// edge while Busy but not yet InGear still starts nothing.
#include <catch2/catch.hpp>

#include <cmath>

#include "fb/fb.hpp"
#include "gear_rig.hpp"

namespace {

// Master 0 and slave 1 of a rig, the slave's MC_GearIn and the master's MC_MoveAbsolute, both
// called once per PLC cycle before the NC cycle.
class GearPlc {
 public:
  gr::Rig rig{2};
  fb::MC_GearIn gear;
  fb::MC_MoveAbsolute move;

  plc::AXIS_REF& master() { return rig.at(0); }
  plc::AXIS_REF& slave() { return rig.at(1); }
  void call_gear() { gear(master(), slave()); }
  void tick() {
    call_gear();
    move(master());
    rig.kernel.cycle();
  }
};

}  // namespace

TEST_CASE("MC_GearIn re-triggered while InGear changes the factor -0.7 -> -0.8 at once",
          "[fb][gear]") {
  GearPlc p;
  p.gear.Execute = true;
  p.gear.RatioNumerator = -0.7;
  p.tick();
  p.tick();
  REQUIRE(p.gear.InGear);
  const uint16_t first = p.gear.command_number();
  p.move.Execute = true;
  p.move.Position = 2000.0;
  p.move.Velocity = 2000.0;
  for (int i = 0; i < 600; ++i)
    p.tick();
  REQUIRE(p.master().NcToPlc.SetVelo == 2000.0);
  CHECK(p.slave().NcToPlc.SetVelo == -0.7 * 2000.0);

  p.gear.Execute = false;
  p.tick();
  CHECK(p.gear.InGear);  // a falling Execute never ends the coupling
  CHECK(p.gear.Busy);

  p.gear.Execute = true;
  p.gear.RatioNumerator = -0.8;
  const double before = p.slave().NcToPlc.SetPos;
  p.call_gear();  // the rising edge posts the new command
  CHECK(p.gear.command_number() != first);
  CHECK(p.gear.Busy);
  CHECK_FALSE(p.gear.InGear);
  CHECK_FALSE(p.gear.CommandAborted);
  p.move(p.master());
  p.rig.kernel.cycle();
  p.call_gear();
  CHECK(p.gear.InGear);
  CHECK(p.gear.Active);
  CHECK_FALSE(p.gear.CommandAborted);
  CHECK_FALSE(p.gear.Error);
  CHECK(p.slave().NcToPlc.GearRatio == -0.8);
  CHECK(p.slave().NcToPlc.SetVelo == -0.8 * p.master().NcToPlc.SetVelo);
  // Position continuous: one cycle's travel at the new velocity, no jump.
  CHECK(std::abs(p.slave().NcToPlc.SetPos - before) <= 0.8 * 2000.0 * 0.001 * (1.0 + 1e-12));
  const double offset = p.slave().NcToPlc.SetPos + 0.8 * p.master().NcToPlc.SetPos;
  while (!p.move.Done)
    p.tick();
  CHECK(p.master().NcToPlc.SetPos == 2000.0);
  CHECK(p.slave().NcToPlc.SetPos == Approx(-0.8 * 2000.0 + offset).epsilon(1e-14));
  CHECK(p.gear.InGear);
}

TEST_CASE("a re-trigger refused by the block leaves the coupling; no re-trigger before InGear",
          "[fb][gear]") {
  GearPlc p;
  p.gear.Execute = true;
  p.gear.RatioNumerator = 0.5;
  p.call_gear();  // posted, not yet taken
  p.gear.Execute = false;
  p.call_gear();
  p.gear.Execute = true;
  p.gear.RatioNumerator = 2.0;
  const uint16_t first = p.gear.command_number();
  p.call_gear();  // Busy, not InGear: the rising edge starts nothing
  CHECK(p.gear.command_number() == first);
  p.rig.kernel.cycle();
  p.call_gear();
  REQUIRE(p.gear.InGear);
  CHECK(p.slave().NcToPlc.GearRatio == 0.5);

  p.gear.Execute = false;
  p.call_gear();
  p.gear.Execute = true;
  p.gear.RatioDenominator = 0;
  p.call_gear();
  CHECK(p.gear.Error);
  CHECK(p.gear.ErrorID == 0x4B06U);
  CHECK_FALSE(p.gear.InGear);
  p.rig.kernel.cycle();
  CHECK(p.slave().NcToPlc.GearRatio == 0.5);
  CHECK(p.slave().NcToPlc.CoupleState == 3U);
}
