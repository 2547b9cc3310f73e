// CommandAborted when another command takes the axis (the NC answers kAborted); Active only
// while the axis executes the block's own command.
#include <catch2/catch.hpp>

#include "block_under_test.hpp"

TEMPLATE_TEST_CASE(
    "another command taking the axis ends the block with CommandAborted and "
    "moves Active to the new block",
    "[fb][rules]", FBTEST_ABORTABLE_BLOCKS) {
  fbtest::Bench<TestType> b;
  TestType second{};
  fbtest::Adapter<TestType>::prepare(second);

  const fbtest::Outputs posted = b.call(true);
  REQUIRE(posted.busy);
  REQUIRE_FALSE(posted.active);  // posted, the axis does not execute it yet
  b.nc.cycle();
  REQUIRE(fbtest::shows_running<TestType>(b.call(true)));

  second.Execute = true;
  second(b.axis);
  // Until the NC takes the second command, the first one still runs.
  REQUIRE(fbtest::shows_running<TestType>(b.call(true)));
  b.nc.cycle();

  const fbtest::Outputs aborted = b.call(true);
  REQUIRE(aborted.aborted);
  REQUIRE_FALSE(aborted.active);
  REQUIRE_FALSE(aborted.busy);
  REQUIRE(aborted.error_id == 0);
  second(b.axis);
  const fbtest::Outputs taker = fbtest::Adapter<TestType>::view(second);
  REQUIRE(taker.busy);
  REQUIRE(fbtest::shows_running<TestType>(taker));
  REQUIRE(b.nc.executing() == second.command_number());
}

TEST_CASE(
    "MC_Halt takes the axis from MC_MoveAbsolute: the move shows CommandAborted, the halt "
    "Done at standstill",
    "[fb][rules]") {
  fbtest::Bench<fb::MC_MoveAbsolute> b;
  fb::MC_Halt halt;
  b.call(true);
  b.nc.cycle();
  REQUIRE(b.call(true).active);

  halt.Execute = true;
  halt(b.axis);
  b.nc.cycle();
  const fbtest::Outputs move = b.call(true);
  halt(b.axis);
  REQUIRE(move.aborted);
  REQUIRE(halt.Busy);
  REQUIRE(halt.Active);

  b.nc.finish();
  halt(b.axis);
  REQUIRE(halt.Done);
  REQUIRE_FALSE(halt.Busy);
  REQUIRE_FALSE(halt.Active);
  // The aborted move still shows CommandAborted while its Execute stays high.
  REQUIRE(b.call(true).aborted);
}

TEST_CASE(
    "a refused command does not abort the running one: Active stays with the running "
    "block",
    "[fb][rules]") {
  fbtest::Bench<fb::MC_MoveAbsolute> b;
  fb::MC_MoveRelative refused;
  refused.Distance = 10.0;
  refused.Velocity = 5000.0;
  b.call(true);
  b.nc.cycle();

  refused.Execute = true;
  refused(b.axis);
  b.nc.refuse_next(plc::ErrorCode::kVelocityNotAllowed);
  b.nc.cycle();
  refused(b.axis);
  REQUIRE(refused.Error);
  REQUIRE(refused.ErrorID == 0x4221);
  const fbtest::Outputs running = b.call(true);
  REQUIRE(running.busy);
  REQUIRE(running.active);
  REQUIRE_FALSE(running.aborted);
}
