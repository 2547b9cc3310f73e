// fb::MC_GearInDyn `gear(master, slave)` on the real kernel (SPEC C6, API.md "Slave axes"): every
// call writes GearRatio into the slave's PlcToNc.GearRatio1; Enable rising couples (Busy, Active;
// InGear while the factor in force, NcToPlc.GearRatio, equals GearRatio); a new GearRatio is
// reached within AccBound and InGear comes back then; Enable falling decouples as MC_GearOut does
// (in motion the slave goes on as a master, SPEC C4); bad inputs are refused with their codes
// (the NC's for GearRatio and AccBound, the block's for BufferMode) and nothing changes.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "fb/fb.hpp"
#include "gear_rig.hpp"

namespace {

struct Plc {
  gr::Rig rig{2};
  plc::AXIS_REF& master = rig.at(0);
  plc::AXIS_REF& slave = rig.at(1);
  fb::MC_GearInDyn gear;
  // One PLC call of the gear block and one NC cycle.
  void tick() {
    gear(master, slave);
    rig.kernel.cycle();
  }
  bool exclusive() const {
    return static_cast<int>(gear.Busy) + static_cast<int>(gear.Error) +
               static_cast<int>(gear.CommandAborted) <=
           1;
  }
};

}  // namespace

TEST_CASE("MC_GearInDyn couples, follows GearRatio within AccBound, and decouples in motion",
          "[fb][gear][cyclic]") {
  Plc p;
  p.gear.GearRatio = 0.5;
  p.gear.Acceleration = 8000.0;
  p.gear(p.master, p.slave);
  CHECK(p.slave.PlcToNc.GearRatio1 == 0.5);  // written also while Enable is low
  CHECK_FALSE(p.gear.Busy);
  p.gear.Enable = true;
  p.tick();
  p.gear(p.master, p.slave);
  CHECK(p.gear.Busy);
  CHECK(p.gear.Active);
  CHECK(p.gear.InGear);
  CHECK(p.slave.NcToPlc.CoupleState == 3U);

  fb::MC_MoveVelocity move;
  move.Execute = true;
  move.Velocity = 1000.0;
  move.Direction = fb::MC_Positive_Direction;
  move(p.master);
  for (int i = 0; i < 500; ++i)
    p.tick();
  p.gear.GearRatio = 1.5;
  p.gear(p.master, p.slave);
  CHECK_FALSE(p.gear.InGear);  // the factor in force is still 0.5
  int cycles = 0;
  while (!p.gear.InGear && cycles < 1000) {
    p.rig.kernel.cycle();
    p.gear(p.master, p.slave);
    REQUIRE(std::abs(p.slave.NcToPlc.SetAcc) <= 8000.0);
    REQUIRE(p.exclusive());
    ++cycles;
  }
  CHECK(cycles == 126);  // 1.0 / (8000 / 1000) s, as on the NC alone
  CHECK(p.slave.NcToPlc.GearRatio == 1.5);
  CHECK(p.slave.NcToPlc.SetVelo == 1500.0);

  // Enable falls in motion: the slave becomes a master going on at 1500 mm/s.
  p.gear.Enable = false;
  p.tick();
  CHECK(p.gear.Busy);  // the decoupling is under way
  p.tick();
  p.gear(p.master, p.slave);
  CHECK_FALSE(p.gear.Busy);
  CHECK_FALSE(p.gear.Error);
  CHECK_FALSE(p.gear.InGear);
  CHECK(p.slave.NcToPlc.CoupleState == 0U);
  CHECK(p.slave.NcToPlc.SetVelo == 1500.0);
  CHECK(p.slave.NcToPlc.ErrorCode == 0U);
}

TEST_CASE("MC_GearInDyn refusals: GearRatio 0 / NaN / inf, AccBound <= 0 / NaN, BufferMode",
          "[fb][gear][cyclic]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    double ratio;
    double acc;
    fb::MC_BufferMode buffer;
    uint32_t code;
  };
  const Case cases[] = {
      {0.0, 8000.0, fb::MC_Aborting, 0x421B}, {nan, 8000.0, fb::MC_Aborting, 0x4F02},
      {inf, 8000.0, fb::MC_Aborting, 0x4F02}, {1.0, 0.0, fb::MC_Aborting, 0x422F},
      {1.0, -5.0, fb::MC_Aborting, 0x422F},   {1.0, nan, fb::MC_Aborting, 0x4F02},
      {1.0, 8000.0, fb::MC_Buffered, 0x4F03},
  };
  for (const Case& c : cases) {
    INFO("GearRatio " << c.ratio << " AccBound " << c.acc << " BufferMode " << c.buffer);
    Plc p;
    p.gear.GearRatio = c.ratio;
    p.gear.Acceleration = c.acc;
    p.gear.BufferMode = c.buffer;
    p.gear.Enable = true;
    p.tick();
    p.gear(p.master, p.slave);
    CHECK(p.gear.Error);
    CHECK(p.gear.ErrorID == c.code);
    CHECK_FALSE(p.gear.Busy);
    CHECK(p.exclusive());
    CHECK(p.slave.NcToPlc.CoupleState == 0U);
    CHECK(p.slave.NcToPlc.ErrorCode == 0U);
    CHECK(p.slave.NcToPlc.Warning == 0U);
    // Enable low: the error is gone.
    p.gear.Enable = false;
    p.tick();
    CHECK_FALSE(p.gear.Error);
  }
}
