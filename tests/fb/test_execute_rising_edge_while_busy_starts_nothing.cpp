// A rising edge of Execute while the block is Busy gives no feedback and starts no command
// (Tc2_MC2 general rules): the running command goes on as if nothing happened.
#include <catch2/catch.hpp>

#include "block_under_test.hpp"

TEMPLATE_TEST_CASE("a rising edge while the command waits in the mailbox posts nothing",
                   "[fb][rules]", FBTEST_EXECUTE_BLOCKS) {
  fbtest::Bench<TestType> b;

  REQUIRE(b.call(true).busy);
  REQUIRE(b.axis.Mailbox.pending() == 1);
  const uint16_t first = b.block.command_number();
  REQUIRE(b.call(false).busy);
  REQUIRE(b.call(true).busy);  // rising edge while Busy
  REQUIRE(b.call(false).busy);
  REQUIRE(b.call(true).busy);  // and another
  REQUIRE(b.axis.Mailbox.pending() == 1);
  REQUIRE(b.block.command_number() == first);

  b.nc.cycle();
  REQUIRE(b.taken() == 1);
  REQUIRE(b.nc.taken().size() == 1);
}

TEMPLATE_TEST_CASE(
    "a rising edge while the command runs posts nothing and the block keeps "
    "following its first command",
    "[fb][rules]", FBTEST_ABORTABLE_BLOCKS, FBTEST_BESIDE_JOB_BLOCKS) {
  using A = fbtest::Adapter<TestType>;
  fbtest::Bench<TestType> b;

  b.call(true);
  b.nc.cycle();
  const uint16_t first = b.block.command_number();
  for (int i = 0; i < 3; ++i) {
    b.call(false);
    const fbtest::Outputs o = b.call(true);  // rising edge while Busy and Active
    REQUIRE(o.busy);
    REQUIRE(fbtest::shows_running<TestType>(o));
    b.nc.cycle();
  }
  REQUIRE(b.taken() == 1);
  REQUIRE(b.nc.taken().size() == 1);
  REQUIRE(b.block.command_number() == first);
  REQUIRE(fbtest::running_number<TestType>(b.nc) == first);

  // The first command's outcome is the one the block shows.
  if constexpr (A::kHasDone) {
    b.nc.finish();
    REQUIRE(b.call(true).done);
  } else {
    b.nc.reach();
    REQUIRE(b.call(true).in_velocity);
  }
}
