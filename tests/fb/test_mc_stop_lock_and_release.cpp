// MC_Stop locks the axis (StateDWord bit 29, motion refused with 0x42EF) and keeps it locked
// until its Execute is low AND it is Done; then it posts kStopRelease exactly once (Tc2_MC2
// MC_Stop). MC_Halt stops without a lock.
#include <catch2/catch.hpp>

#include "block_under_test.hpp"

namespace {

std::size_t releases(const fbtest::ScriptedNc& nc) {
  return nc.count(plc::CommandType::kStopRelease);
}

// A move started on the axis: its outputs after the NC took it.
fb::MC_MoveAbsolute try_move(plc::AXIS_REF& axis, fbtest::ScriptedNc& nc) {
  fb::MC_MoveAbsolute move;
  move.Position = 100.0;
  move.Velocity = 500.0;
  move.Execute = true;
  move(axis);
  nc.cycle();
  move(axis);
  return move;
}

}  // namespace

TEST_CASE(
    "Execute held high after Done keeps the axis locked; the falling edge releases it "
    "once",
    "[fb][stop]") {
  fbtest::Bench<fb::MC_Stop> b;
  b.call(true);
  b.nc.cycle();
  REQUIRE(b.nc.locked());
  REQUIRE(b.call(true).active);
  b.nc.finish();  // standstill

  for (int i = 0; i < 20; ++i) {
    REQUIRE(b.call(true).done);
    b.nc.cycle();
  }
  REQUIRE(b.nc.locked());
  REQUIRE(releases(b.nc) == 0);
  const fb::MC_MoveAbsolute refused = try_move(b.axis, b.nc);
  REQUIRE(refused.Error);
  REQUIRE(refused.ErrorID == 0x42EF);

  fbtest::Outputs o = b.call(false);
  REQUIRE_FALSE(o.done);
  REQUIRE_FALSE(o.busy);
  REQUIRE(b.axis.Mailbox.pending() == 1);
  b.nc.cycle();
  REQUIRE_FALSE(b.nc.locked());
  for (int i = 0; i < 20; ++i) {
    b.call(false);
    b.nc.cycle();
  }
  REQUIRE(releases(b.nc) == 1);
  const fb::MC_MoveAbsolute accepted = try_move(b.axis, b.nc);
  REQUIRE(accepted.Busy);
  REQUIRE(accepted.Active);
}

TEST_CASE(
    "Execute low before Done: no release while the axis brakes; Done is shown once and "
    "the release posted in that call",
    "[fb][stop]") {
  fbtest::Bench<fb::MC_Stop> b;
  b.call(true);
  b.nc.cycle();
  for (int i = 0; i < 10; ++i) {
    const fbtest::Outputs o = b.call(false);
    REQUIRE(o.busy);
    REQUIRE(o.active);
    b.nc.cycle();
  }
  REQUIRE(releases(b.nc) == 0);
  REQUIRE(b.nc.locked());

  b.nc.finish();
  const fbtest::Outputs shown = b.call(false);
  REQUIRE(shown.done);
  REQUIRE_FALSE(shown.busy);
  b.nc.cycle();
  REQUIRE(releases(b.nc) == 1);
  REQUIRE_FALSE(b.nc.locked());
  for (int i = 0; i < 10; ++i) {
    fbtest::Outputs o = b.call(false);
    REQUIRE_FALSE(o.done);
    REQUIRE_FALSE(o.busy);
    b.nc.cycle();
  }
  REQUIRE(releases(b.nc) == 1);
}

TEST_CASE("a stop that ends in Error posts no release: the axis stays locked until MC_Reset",
          "[fb][stop]") {
  fbtest::Bench<fb::MC_Stop> b;
  b.call(true);
  b.nc.cycle();
  b.nc.fail(plc::ErrorCode::kFollowingErrorPosition);
  REQUIRE(b.call(true).error_id == 0x4550);
  b.call(false);
  b.nc.cycle();
  REQUIRE(releases(b.nc) == 0);
  REQUIRE(b.nc.locked());

  fb::MC_Reset reset;
  reset.Execute = true;
  reset(b.axis);
  b.nc.cycle();
  reset(b.axis);
  REQUIRE(reset.Done);
  REQUIRE_FALSE(b.nc.locked());
}

TEST_CASE("a stop aborted by a second MC_Stop posts no release: the lock is the second's",
          "[fb][stop]") {
  fbtest::Bench<fb::MC_Stop> b;
  fb::MC_Stop second;
  b.call(true);
  b.nc.cycle();
  second.Execute = true;
  second(b.axis);
  b.nc.cycle();
  REQUIRE(b.call(true).aborted);
  REQUIRE(b.call(false).busy == false);
  b.nc.cycle();
  REQUIRE(releases(b.nc) == 0);
  REQUIRE(b.nc.locked());

  b.nc.finish();
  second(b.axis);
  REQUIRE(second.Done);
  b.nc.cycle();
  REQUIRE(b.nc.locked());  // second's Execute still high
  second.Execute = false;
  second(b.axis);
  b.nc.cycle();
  REQUIRE(releases(b.nc) == 1);
  REQUIRE_FALSE(b.nc.locked());
}

TEST_CASE(
    "a release that finds the mailbox full is posted later, once; the block is Busy "
    "meanwhile",
    "[fb][stop]") {
  fbtest::Bench<fb::MC_Stop> b;
  b.call(true);
  b.nc.cycle();
  b.nc.finish();
  REQUIRE(b.call(true).done);
  for (std::size_t i = 0; i < plc::CommandMailbox::kQueueCapacity; ++i) {
    plc::Command filler;
    filler.type = plc::CommandType::kHalt;
    REQUIRE(b.axis.Mailbox.post(filler) != 0);
  }
  const fbtest::Outputs waiting = b.call(false);
  REQUIRE(waiting.busy);
  REQUIRE_FALSE(waiting.done);
  REQUIRE(b.call(false).busy);
  b.nc.cycle();  // drains the fillers (refused: locked)
  REQUIRE(releases(b.nc) == 0);
  REQUIRE(b.nc.locked());

  REQUIRE_FALSE(b.call(false).busy);  // posted now
  b.nc.cycle();
  REQUIRE(releases(b.nc) == 1);
  REQUIRE_FALSE(b.nc.locked());
  b.call(false);
  b.nc.cycle();
  REQUIRE(releases(b.nc) == 1);
}

TEST_CASE("MC_Halt stops without a lock: a move right after its Done is accepted", "[fb][stop]") {
  fbtest::Bench<fb::MC_Halt> b;
  b.call(true);
  b.nc.cycle();
  REQUIRE_FALSE(b.nc.locked());
  b.nc.finish();
  REQUIRE(b.call(true).done);
  const fb::MC_MoveAbsolute move = try_move(b.axis, b.nc);
  REQUIRE(move.Active);
  REQUIRE(b.nc.count(plc::CommandType::kStopRelease) == 0);
}
