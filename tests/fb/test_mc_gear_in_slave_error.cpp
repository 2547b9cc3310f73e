// fb::MC_GearIn and fb::MC_GearInDyn when their slave gets an error (SPEC C7; a block whose
// axis goes to ErrorStop shows Error): Error with the axis's ErrorID (0x4550: the slave's drive
// saturates at 900 mm/s behind a master at 1000 mm/s), no longer InGear, Busy or Active.
#include <catch2/catch.hpp>

#include "fb/fb.hpp"
#include "propagation_rig.hpp"

namespace {

constexpr uint32_t kFollowing = 0x4550;

struct Plc {
  pr::Group rig{2, [](std::size_t i, nc::AxisConfig& c) {
                  if (i == 1) pr::slow_drive(c);
                }};
  plc::AXIS_REF& master = rig.at(0);
  plc::AXIS_REF& slave = rig.at(1);
  fb::MC_MoveAbsolute move;
  // Starts the master to 20000 at 1000 mm/s and runs until the slave shows its error.
  template <class Gear>
  void run_until_slave_error(Gear& gear) {
    move.Execute = true;
    move.Position = 20000.0;
    move.Velocity = 1000.0;
    for (int i = 0; i < 2000 && slave.NcToPlc.ErrorCode == 0U; ++i) {
      move(master);
      gear(master, slave);
      rig.kernel.cycle();
    }
    REQUIRE(slave.NcToPlc.ErrorCode == kFollowing);
    gear(master, slave);
  }
  // The block once coupled (InGear after one NC cycle), then through the slave's error.
  template <class Gear>
  void check_fails_with_slave(Gear& gear) {
    gear(master, slave);
    rig.kernel.cycle();
    gear(master, slave);
    REQUIRE(gear.InGear);
    run_until_slave_error(gear);
    CHECK(gear.Error);
    CHECK(gear.ErrorID == kFollowing);
    CHECK_FALSE(gear.InGear);
    CHECK_FALSE(gear.Busy);
    CHECK_FALSE(gear.Active);
  }
};

}  // namespace

TEST_CASE("MC_GearIn shows Error with the slave's ErrorID when the slave fails", "[fb][gear]") {
  Plc p;
  fb::MC_GearIn gear;
  gear.Execute = true;
  gear.RatioNumerator = 1.0;
  p.check_fails_with_slave(gear);
}

TEST_CASE("MC_GearInDyn shows Error with the slave's ErrorID when the slave fails", "[fb][gear]") {
  Plc p;
  fb::MC_GearInDyn gear;
  gear.Enable = true;
  gear.GearRatio = 1.0;
  gear.Acceleration = 10000.0;
  p.check_fails_with_slave(gear);
}
