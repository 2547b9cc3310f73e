// fb::MC_GearIn `gear(master, slave)` and fb::MC_GearOut `(slave)` on the real kernel (SPEC C1,
// C4 at rest; API.md): InGear, Busy and Active once coupled and while coupled; the slave follows
// 0.75 × the master (0 → 20000 at V 2000: slave 0 → 15000, 450 mm/s at override 30 % and
// 1500 mm/s at 100 %); MC_ReadStatus shows SynchronizedMotion; a second MC_GearIn takes over
// (the first CommandAborted); RatioDenominator 0 is refused by the block (0x4B06) and factor 0 by
// the NC (0x421B); MC_GearOut is Done in the next NC cycle with CoupleState 0.
#include <catch2/catch.hpp>

#include "fb/fb.hpp"
#include "gear_rig.hpp"

namespace {

struct Plc {
  gr::Rig rig{2};
  plc::AXIS_REF& master = rig.at(0);
  plc::AXIS_REF& slave = rig.at(1);
  fb::MC_GearIn gear;
  // One PLC call of the gear block and one NC cycle.
  void tick() {
    gear(master, slave);
    rig.kernel.cycle();
  }
};

}  // namespace

TEST_CASE("MC_GearIn couples, the slave follows 0.75 of the seed figure, MC_GearOut decouples",
          "[fb][gear]") {
  Plc p;
  p.master.PlcToNc.Override = 300'000;  // 30 %
  p.gear.Execute = true;
  p.gear.RatioNumerator = 3.0;
  p.gear.RatioDenominator = 4;
  p.gear(p.master, p.slave);
  CHECK(p.gear.Busy);
  CHECK_FALSE(p.gear.InGear);
  p.tick();
  p.gear(p.master, p.slave);
  REQUIRE(p.gear.InGear);
  CHECK(p.gear.Busy);
  CHECK(p.gear.Active);
  CHECK_FALSE(p.gear.Error);

  fb::MC_ReadStatus status;
  status.Enable = true;
  status(p.slave);
  CHECK(status.SynchronizedMotion);

  fb::MC_MoveAbsolute move;
  move.Execute = true;
  move.Position = 20000.0;
  move.Velocity = 2000.0;
  move(p.master);
  double v30 = 0.0;
  for (int i = 0; i < 4000; ++i) {
    p.tick();
    move(p.master);
  }
  v30 = p.slave.NcToPlc.SetVelo;
  CHECK(v30 == Approx(0.75 * 600.0).epsilon(1e-12));  // 450 mm/s
  p.master.PlcToNc.Override = 1'000'000;
  for (int i = 0; i < 3000; ++i) {
    p.tick();
    move(p.master);
  }
  CHECK(p.slave.NcToPlc.SetVelo == Approx(1500.0).epsilon(1e-12));
  while (!move.Done) {
    p.tick();
    move(p.master);
  }
  CHECK(p.master.NcToPlc.SetPos == 20000.0);
  CHECK(p.slave.NcToPlc.SetPos == Approx(15000.0).epsilon(1e-15));
  CHECK(p.gear.InGear);

  fb::MC_GearOut out;
  out.Execute = true;
  out(p.slave);
  CHECK(out.Busy);
  p.rig.kernel.cycle();
  out(p.slave);
  CHECK(out.Done);
  CHECK_FALSE(out.Busy);
  CHECK(p.slave.NcToPlc.CoupleState == 0U);
  p.gear(p.master, p.slave);
  CHECK_FALSE(p.gear.InGear);
  CHECK_FALSE(p.gear.Busy);
  CHECK_FALSE(p.gear.Error);
}

TEST_CASE("a second MC_GearIn takes over; bad ratios give 0x4B06 and 0x421B", "[fb][gear]") {
  Plc p;
  p.gear.Execute = true;
  p.tick();
  p.gear(p.master, p.slave);
  REQUIRE(p.gear.InGear);

  fb::MC_GearIn second;
  second.Execute = true;
  second.RatioNumerator = -1.0;
  second.RatioDenominator = 2;
  second(p.master, p.slave);
  p.rig.kernel.cycle();
  second(p.master, p.slave);
  p.gear(p.master, p.slave);
  CHECK(second.InGear);
  CHECK(p.gear.CommandAborted);
  CHECK_FALSE(p.gear.InGear);
  CHECK(p.slave.NcToPlc.GearRatio == -0.5);

  fb::MC_GearIn zero_den;
  zero_den.Execute = true;
  zero_den.RatioDenominator = 0;
  const uint16_t posted_before = zero_den.command_number();
  zero_den(p.master, p.rig.at(1));
  CHECK(zero_den.Error);
  CHECK(zero_den.ErrorID == 0x4B06U);
  CHECK(zero_den.command_number() == posted_before);  // nothing posted

  gr::Rig other(2);
  fb::MC_GearIn zero;
  zero.Execute = true;
  zero.RatioNumerator = 0.0;
  zero(other.at(0), other.at(1));
  other.kernel.cycle();
  zero(other.at(0), other.at(1));
  CHECK(zero.Error);
  CHECK(zero.ErrorID == 0x421BU);
  CHECK(other.at(1).NcToPlc.CoupleState == 0U);
}
