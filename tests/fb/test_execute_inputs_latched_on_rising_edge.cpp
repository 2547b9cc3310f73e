// Inputs of an Execute-type block are read on the rising edge of Execute only (Tc2_MC2 general
// rules, "input parameters"): changing them while the block is busy or shows its result changes
// nothing; the next rising edge takes the new values.
#include <catch2/catch.hpp>

#include "block_under_test.hpp"

TEMPLATE_TEST_CASE(
    "changing an input while Busy changes nothing: the command keeps the value "
    "of the rising edge",
    "[fb][rules]", FBTEST_ABORTABLE_BLOCKS, FBTEST_BESIDE_JOB_BLOCKS) {
  using A = fbtest::Adapter<TestType>;
  fbtest::Bench<TestType> b;

  A::set_input(b.block, 2000.0);
  REQUIRE(b.call(true).busy);  // posted, not yet taken
  A::set_input(b.block, 250.0);
  REQUIRE(b.call(true).busy);
  b.nc.cycle();  // the NC takes it
  A::set_input(b.block, 400.0);
  const fbtest::Outputs running = b.call(true);
  REQUIRE(running.busy);
  REQUIRE(fbtest::shows_running<TestType>(running));
  b.nc.cycle();

  REQUIRE(b.taken() == 1);
  REQUIRE(A::sent(b.nc.last(A::kType)) == 2000.0);
  REQUIRE(b.axis.Mailbox.pending() == 0);
}

TEMPLATE_TEST_CASE(
    "changing an input while the result shows starts nothing; the next rising "
    "edge sends the new value",
    "[fb][rules]", FBTEST_ABORTABLE_BLOCKS, FBTEST_BESIDE_JOB_BLOCKS) {
  using A = fbtest::Adapter<TestType>;
  fbtest::Bench<TestType> b;

  A::set_input(b.block, 2000.0);
  b.call(true);
  b.nc.refuse_next(plc::ErrorCode::kVelocityNotAllowed);
  b.nc.cycle();
  REQUIRE(b.call(true).error_id == 0x4221);

  A::set_input(b.block, 1500.0);
  for (int i = 0; i < 5; ++i) {
    REQUIRE(b.call(true).error_id == 0x4221);
    b.nc.cycle();
  }
  REQUIRE(b.taken() == 1);

  REQUIRE_FALSE(b.call(false).error);
  REQUIRE(b.call(true).busy);
  b.nc.cycle();
  REQUIRE(b.taken() == 2);
  REQUIRE(A::sent(b.nc.taken().front()) == 2000.0);
  REQUIRE(A::sent(b.nc.last(A::kType)) == 1500.0);
}
