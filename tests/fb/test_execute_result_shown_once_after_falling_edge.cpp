// Done, Error and CommandAborted: shown while Execute stays high; a result reached after Execute
// fell is shown for exactly one call; once Execute is low and the result was shown, the outputs
// reset (Tc2_MC2 general rules, "initial state").
#include <catch2/catch.hpp>

#include "outcome.hpp"

using fbtest::Outcome;

TEMPLATE_TEST_CASE("a result reached after Execute fell is shown for exactly one call",
                   "[fb][rules]", FBTEST_EXECUTE_BLOCKS) {
  const Outcome o =
      GENERATE(Outcome::kDone, Outcome::kRefused, Outcome::kFailed, Outcome::kAborted);
  if (!fbtest::applies<TestType>(o)) return;
  INFO("outcome " << fbtest::name(o));
  fbtest::Bench<TestType> b;
  TestType other{};

  REQUIRE(b.call(true).busy);
  REQUIRE(b.call(false).busy);
  b.block.Execute = false;
  fbtest::produce(b, other, o);

  fbtest::require_shows(b.call(false), o);
  for (int i = 0; i < 10; ++i) {
    fbtest::require_all_reset(b.call(false));
    b.nc.cycle();
  }
}

TEMPLATE_TEST_CASE(
    "a result reached while Execute is high stays while Execute stays high and "
    "resets on the first call with Execute low",
    "[fb][rules]", FBTEST_EXECUTE_BLOCKS) {
  const Outcome o =
      GENERATE(Outcome::kDone, Outcome::kRefused, Outcome::kFailed, Outcome::kAborted);
  if (!fbtest::applies<TestType>(o)) return;
  INFO("outcome " << fbtest::name(o));
  fbtest::Bench<TestType> b;
  TestType other{};

  REQUIRE(b.call(true).busy);
  fbtest::produce(b, other, o);
  for (int i = 0; i < 25; ++i) {
    fbtest::require_shows(b.call(true), o);
    b.nc.cycle();
  }
  fbtest::require_all_reset(b.call(false));
  fbtest::require_all_reset(b.call(false));
}

TEMPLATE_TEST_CASE(
    "a rising edge right after a result shown with Execute low starts the next "
    "command",
    "[fb][rules]", FBTEST_EXECUTE_BLOCKS) {
  const Outcome o = GENERATE(Outcome::kDone, Outcome::kRefused);
  if (!fbtest::applies<TestType>(o)) return;
  fbtest::Bench<TestType> b;
  TestType other{};

  b.call(true);
  b.call(false);
  b.block.Execute = false;
  fbtest::produce(b, other, o);
  fbtest::require_shows(b.call(false), o);
  const uint16_t first = b.block.command_number();
  const fbtest::Outputs again = b.call(true);
  REQUIRE(again.busy);
  REQUIRE_FALSE(again.done);
  REQUIRE_FALSE(again.error);
  REQUIRE(b.block.command_number() != first);
  b.nc.cycle();
  REQUIRE(b.taken() == 2);
}
