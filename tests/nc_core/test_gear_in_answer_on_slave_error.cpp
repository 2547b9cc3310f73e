// A slave's MC_GearIn ends in Error when the slave gets an error (SPEC C7; a block whose axis
// goes to ErrorStop shows Error): its own error (INSTANTANEOUS or DELAYED) or its group's. The
// command is no longer InGear (kReached) but kError with the axis's code; the link itself stays
// until MC_GearOut, which is then answered Done.
#include <catch2/catch.hpp>

#include "propagation_rig.hpp"

using plc::CommandState;
using plc::ErrorCode;

namespace {

const uint32_t kFollowing = plc::to_id(ErrorCode::kFollowingErrorPosition);

// A0 master; A1 (factor 1) its slave, A1's drive saturated at 900 mm/s (its own error after
// about 50 ms at 1000 mm/s) unless `faulty_master`, where A0 is the slow one. A1 DELAYED 0.5 s
// when `delayed`.
struct Pair : pr::Group {
  uint16_t gear = 0;
  Pair(bool delayed, bool faulty_master)
      : pr::Group(2, [=](std::size_t i, nc::AxisConfig& c) {
          if ((i == 1) != faulty_master) pr::slow_drive(c);
          if (i == 1 && delayed) pr::delayed(c, 0.5);
        }) {
    gear = post(1, gr::gear_in(0, 1.0));
    cycles(1);
    REQUIRE(answer(1, gear).state == CommandState::kReached);
    post(0, kt::move_absolute(20000.0, 1000.0));
  }
};

}  // namespace

TEST_CASE("A slave's own error ends its MC_GearIn in Error (INSTANTANEOUS)",
          "[propagation][gear]") {
  Pair p(false, false);
  REQUIRE(p.until_error(1) > 0);
  const plc::CommandAnswer a = p.answer(1, p.gear);
  CHECK(a.state == CommandState::kError);
  CHECK(a.error_code == kFollowing);
  CHECK(p.at(1).NcToPlc.CoupleState ==
        static_cast<uint32_t>(plc::CoupleState::kSlave));  // until MC_GearOut
}

TEST_CASE(
    "A slave that leaves on its DELAYED error ends its MC_GearIn in Error; MC_GearOut is "
    "Done",
    "[propagation][gear][delayed]") {
  Pair p(true, false);
  REQUIRE(p.until_error(1) > 0);
  CHECK(p.answer(1, p.gear).state == CommandState::kError);
  CHECK(p.answer(1, p.gear).error_code == kFollowing);
  // The master goes on at 1000 mm/s for the delay; the answer does not change.
  p.cycles(100);
  CHECK(p.at(0).NcToPlc.SetVelo == 1000.0);
  CHECK(p.answer(1, p.gear).state == CommandState::kError);
  const plc::CommandAnswer out = p.decouple(1);
  CHECK(out.state == CommandState::kDone);
  CHECK(p.at(1).NcToPlc.CoupleState == 0U);
  CHECK(p.answer(1, p.gear).state == CommandState::kError);
}

TEST_CASE("The group's error ends a healthy slave's MC_GearIn in Error with the faulty axis's code",
          "[propagation][gear]") {
  Pair p(false, true);
  REQUIRE(p.until_error(0) > 0);
  CHECK(p.error(1) == kFollowing);
  const plc::CommandAnswer a = p.answer(1, p.gear);
  CHECK(a.state == CommandState::kError);
  CHECK(a.error_code == kFollowing);
}
