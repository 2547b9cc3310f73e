// MC_MoveVelocity shows InVelocity (in place of Done) while the NC reports the velocity reached;
// it stays Busy and Active until another command takes the axis, whatever Execute does.
#include <catch2/catch.hpp>

#include "block_under_test.hpp"

TEST_CASE("InVelocity comes with the kReached answer, together with Busy and Active",
          "[fb][velocity]") {
  fbtest::Bench<fb::MC_MoveVelocity> b;
  b.call(true);
  b.nc.cycle();
  fbtest::Outputs o = b.call(true);
  REQUIRE(o.active);
  REQUIRE_FALSE(o.in_velocity);

  b.nc.reach();
  o = b.call(true);
  REQUIRE(o.in_velocity);
  REQUIRE(o.busy);
  REQUIRE(o.active);
}

TEST_CASE("InVelocity, Busy and Active stay after Execute falls; the job never ends by itself",
          "[fb][velocity]") {
  fbtest::Bench<fb::MC_MoveVelocity> b;
  b.call(true);
  b.nc.cycle();
  b.nc.reach();
  for (int i = 0; i < 100; ++i) {
    const fbtest::Outputs o = b.call(false);
    REQUIRE(o.in_velocity);
    REQUIRE(o.busy);
    REQUIRE(o.active);
    b.nc.cycle();
  }
  REQUIRE(b.nc.taken().size() == 1);
}

TEST_CASE("a halt ends the velocity job: CommandAborted for one call, InVelocity gone",
          "[fb][velocity]") {
  fbtest::Bench<fb::MC_MoveVelocity> b;
  fb::MC_Halt halt;
  b.call(true);
  b.nc.cycle();
  b.nc.reach();
  REQUIRE(b.call(false).in_velocity);

  halt.Execute = true;
  halt(b.axis);
  b.nc.cycle();
  const fbtest::Outputs aborted = b.call(false);
  REQUIRE(aborted.aborted);
  REQUIRE_FALSE(aborted.in_velocity);
  REQUIRE_FALSE(aborted.busy);
  const fbtest::Outputs after = b.call(false);
  REQUIRE_FALSE(after.aborted);
  REQUIRE_FALSE(after.in_velocity);
}

TEST_CASE("an axis error during the velocity job: Error with the axis's code, InVelocity gone",
          "[fb][velocity]") {
  fbtest::Bench<fb::MC_MoveVelocity> b;
  b.call(true);
  b.nc.cycle();
  b.nc.reach();
  REQUIRE(b.call(true).in_velocity);
  b.nc.fail(plc::ErrorCode::kSoftLimitMaxDuringMotion);
  const fbtest::Outputs o = b.call(true);
  REQUIRE(o.error);
  REQUIRE(o.error_id == 0x4463);
  REQUIRE_FALSE(o.in_velocity);
}
