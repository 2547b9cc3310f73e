// Checks a block makes itself, because the NC cannot know them: a BufferMode that is not an
// MC_BufferMode value (0x4F03), an MC_MoveVelocity direction other than positive, negative or
// current, an MC_MoveModulo direction other than the four MC_Direction values (0x4F07), and a full
// mailbox (0x4F04). Each shows Error at once and posts nothing.
#include <catch2/catch.hpp>

#include "block_under_test.hpp"

TEMPLATE_TEST_CASE("a buffer mode outside MC_BufferMode gives Error 0x4F03 and posts nothing",
                   "[fb][local]", fb::MC_MoveAbsolute, fb::MC_MoveRelative, fb::MC_MoveModulo,
                   fb::MC_MoveVelocity, fb::MC_Halt) {
  const fb::MC_BufferMode mode =
      GENERATE(static_cast<fb::MC_BufferMode>(-1), static_cast<fb::MC_BufferMode>(6),
               static_cast<fb::MC_BufferMode>(42));
  INFO("buffer mode " << static_cast<int>(mode));
  fbtest::Bench<TestType> b;
  b.block.BufferMode = mode;

  const fbtest::Outputs o = b.call(true);
  REQUIRE(o.error);
  REQUIRE(o.error_id == 0x4F03);
  REQUIRE(b.axis.Mailbox.pending() == 0);
  REQUIRE(b.block.command_number() == 0);
  REQUIRE(b.call(true).error_id == 0x4F03);
  REQUIRE_FALSE(b.call(false).error);
}

TEMPLATE_TEST_CASE("every MC_BufferMode value is posted with its number", "[fb][local]",
                   fb::MC_MoveAbsolute, fb::MC_MoveRelative, fb::MC_MoveModulo, fb::MC_MoveVelocity,
                   fb::MC_Halt) {
  const fb::MC_BufferMode mode =
      GENERATE(fb::MC_Buffered, fb::MC_BlendingLow, fb::MC_BlendingPrevious, fb::MC_BlendingNext,
               fb::MC_BlendingHigh);
  INFO("buffer mode " << static_cast<int>(mode));
  fbtest::Bench<TestType> b;
  b.block.BufferMode = mode;
  REQUIRE(b.call(true).busy);
  REQUIRE(b.axis.Mailbox.pending() == 1);
  plc::Command posted;
  REQUIRE(b.axis.Mailbox.take(posted));
  REQUIRE(posted.buffer_mode == static_cast<int32_t>(mode));
}

TEST_CASE("MC_Aborting is posted with buffer mode 0", "[fb][local]") {
  fbtest::Bench<fb::MC_MoveAbsolute> b;
  b.block.BufferMode = fb::MC_Aborting;
  REQUIRE(b.call(true).busy);
  b.nc.cycle();
  REQUIRE(b.nc.last(plc::CommandType::kMoveAbsolute).buffer_mode == 0);
}

TEST_CASE("MC_MoveVelocity accepts the positive, the negative and the current direction",
          "[fb][local]") {
  SECTION("other directions give Error 0x4F07 and post nothing") {
    const fb::MC_Direction direction =
        GENERATE(fb::MC_Shortest_Way, fb::MC_Undefined_Direction, static_cast<fb::MC_Direction>(0),
                 static_cast<fb::MC_Direction>(5), static_cast<fb::MC_Direction>(-1));
    INFO("direction " << static_cast<int>(direction));
    fbtest::Bench<fb::MC_MoveVelocity> b;
    b.block.Direction = direction;
    const fbtest::Outputs o = b.call(true);
    REQUIRE(o.error);
    REQUIRE(o.error_id == 0x4F07);
    REQUIRE(b.axis.Mailbox.pending() == 0);
  }
  SECTION("positive, negative and current are posted as their MC_Direction values 1, 3, 4") {
    const fb::MC_Direction direction =
        GENERATE(fb::MC_Positive_Direction, fb::MC_Negative_Direction, fb::MC_Current_Direction);
    fbtest::Bench<fb::MC_MoveVelocity> b;
    b.block.Direction = direction;
    REQUIRE(b.call(true).busy);
    b.nc.cycle();
    REQUIRE(b.nc.last(plc::CommandType::kMoveVelocity).direction ==
            (direction == fb::MC_Positive_Direction   ? 1
             : direction == fb::MC_Negative_Direction ? 3
                                                      : 4));
  }
}

TEST_CASE("MC_MoveModulo accepts the four directions of MC_Direction and no other value",
          "[fb][local]") {
  SECTION("MC_Undefined_Direction and values outside the enumeration give Error 0x4F07") {
    const fb::MC_Direction direction =
        GENERATE(fb::MC_Undefined_Direction, static_cast<fb::MC_Direction>(0),
                 static_cast<fb::MC_Direction>(5), static_cast<fb::MC_Direction>(-1));
    INFO("direction " << static_cast<int>(direction));
    fbtest::Bench<fb::MC_MoveModulo> b;
    b.block.Direction = direction;
    const fbtest::Outputs o = b.call(true);
    REQUIRE(o.error);
    REQUIRE(o.error_id == 0x4F07);
    REQUIRE(b.axis.Mailbox.pending() == 0);
    REQUIRE(b.block.command_number() == 0);
  }
  SECTION("positive, shortest way, negative and current are posted as 1, 2, 3 and 4") {
    const int value = GENERATE(1, 2, 3, 4);
    fbtest::Bench<fb::MC_MoveModulo> b;
    b.block.Direction = static_cast<fb::MC_Direction>(value);
    REQUIRE(b.call(true).busy);
    b.nc.cycle();
    REQUIRE(b.nc.last(plc::CommandType::kMoveModulo).direction == value);
  }
  SECTION("the direction is checked before the buffer mode") {
    fbtest::Bench<fb::MC_MoveModulo> b;
    b.block.Direction = fb::MC_Undefined_Direction;
    b.block.BufferMode = static_cast<fb::MC_BufferMode>(42);
    REQUIRE(b.call(true).error_id == 0x4F07);
  }
}

TEMPLATE_TEST_CASE("a full mailbox gives Error 0x4F04 and posts nothing", "[fb][local]",
                   FBTEST_EXECUTE_BLOCKS) {
  fbtest::Bench<TestType> b;
  for (std::size_t i = 0; i < plc::CommandMailbox::kQueueCapacity; ++i) {
    plc::Command filler;
    filler.type = plc::CommandType::kMoveRelative;
    REQUIRE(b.axis.Mailbox.post(filler) != 0);
  }
  const fbtest::Outputs o = b.call(true);
  REQUIRE(o.error);
  REQUIRE(o.error_id == 0x4F04);
  REQUIRE(b.axis.Mailbox.pending() == plc::CommandMailbox::kQueueCapacity);
  // With room again, the next rising edge posts.
  b.nc.cycle();
  REQUIRE(b.call(false).error_id == 0);
  REQUIRE(b.call(true).busy);
  REQUIRE(b.axis.Mailbox.pending() == 1);
}
