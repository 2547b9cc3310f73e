// A falling edge of Execute never aborts the block's command (Tc2_MC2 general rules): the block
// stays Busy (and Active) and posts nothing, the NC keeps executing the command.
#include <catch2/catch.hpp>

#include "block_under_test.hpp"

TEMPLATE_TEST_CASE("Execute falling right after the rising edge still lets the command run",
                   "[fb][rules]", FBTEST_EXECUTE_BLOCKS) {
  using A = fbtest::Adapter<TestType>;
  fbtest::Bench<TestType> b;

  REQUIRE(b.call(true).busy);
  REQUIRE(b.call(false).busy);  // fell before the NC even took the command
  b.nc.cycle();
  REQUIRE(b.taken() == 1);
  if constexpr (A::kAbortable) {
    const uint16_t running = fbtest::running_number<TestType>(b.nc);
    REQUIRE(running == b.block.command_number());
    REQUIRE(b.axis.Mailbox.answer(running).state == plc::CommandState::kActive);
  } else {
    // MC_Reset and the other instant commands are answered in the cycle that takes them.
    REQUIRE(b.axis.Mailbox.answer(b.block.command_number()).state == plc::CommandState::kDone);
  }
}

TEMPLATE_TEST_CASE(
    "Execute low for many calls while the command runs: Busy and Active stay, "
    "nothing is posted",
    "[fb][rules]", FBTEST_ABORTABLE_BLOCKS, FBTEST_BESIDE_JOB_BLOCKS) {
  fbtest::Bench<TestType> b;

  b.call(true);
  b.nc.cycle();
  REQUIRE(fbtest::shows_running<TestType>(b.call(true)));
  for (int i = 0; i < 50; ++i) {
    const fbtest::Outputs o = b.call(false);
    REQUIRE(o.busy);
    REQUIRE(fbtest::shows_running<TestType>(o));
    b.nc.cycle();
  }
  REQUIRE(b.nc.taken().size() == 1);
  REQUIRE(b.axis.Mailbox.answer(b.block.command_number()).state == plc::CommandState::kActive);
}
