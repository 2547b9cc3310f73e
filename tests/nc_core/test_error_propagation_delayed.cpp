// SPEC C7 DELAYED (seed 000 §3.1; issue 10): only the faulty axis reacts at once — a faulty
// slave leaves its master's coupling and stops on its emergency ramp, its own slaves follow it —
// with StateDWord bits 31 (Error) and 6 (ErrorPropagationDelayed) set together; the rest of the
// group moves on. round(delay / T) cycles after the cycle in which bit 31 first shows, the group
// reaction acts on the group as it is then (a slave decoupled meanwhile by MC_GearOut goes on)
// and bit 6 is reset. MC_Reset of the faulty axis before that cancels the group reaction.
#include <catch2/catch.hpp>

#include <cmath>

#include "propagation_rig.hpp"

using plc::AxisState;
using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

namespace {

const uint32_t kFollowing = kt::id(ErrorCode::kFollowingErrorPosition);

// A0 head master; A1 (factor 1, drive saturated at 900 mm/s, DELAYED 0.5 s) the faulty slave;
// A2 (factor 0.5) and A4 (factor 2) healthy slaves of A0; A3 (factor 2) a slave of A1. A0 starts
// to 20000 at 1000 mm/s; the run stops in the cycle A1's error first shows.
struct Star : pr::Group {
  int error_cycle = 0;
  Star()
      : pr::Group(5, [](std::size_t i, nc::AxisConfig& c) {
          if (i == 1) {
            pr::slow_drive(c);
            pr::delayed(c, 0.5);
          }
        }) {
    REQUIRE(couple(1, 0, 1.0));
    REQUIRE(couple(2, 0, 0.5));
    REQUIRE(couple(3, 1, 2.0));
    REQUIRE(couple(4, 0, 2.0));
    post(0, kt::move_absolute(20000.0, 1000.0));
    error_cycle = until_error(1);
    REQUIRE(error_cycle > 0);
  }
};

}  // namespace

TEST_CASE("DELAYED: only the faulty slave reacts, with bits 31 and 6; its own slave follows it",
          "[propagation][delayed]") {
  Star s;
  CHECK(s.error(1) == kFollowing);
  CHECK(s.error_bit(1));
  CHECK(s.delayed_bit(1));
  CHECK(kt::axis_state(s.at(1)) == AxisState::kErrorStop);
  for (const std::size_t i : {0U, 2U, 3U, 4U}) {
    INFO("axis " << i);
    CHECK(s.error(i) == 0U);
    CHECK_FALSE(s.delayed_bit(i));
  }
  // The link stays until MC_GearOut: A1 still shows itself a slave (and A3's master).
  CHECK(s.at(1).NcToPlc.CoupleState == 2U);
  const double offset3 = s.at(3).NcToPlc.SetPos - 2.0 * s.at(1).NcToPlc.SetPos;
  for (int k = 0; k < 300; ++k) {
    s.cycles(1);
    // The master and its healthy slaves move on.
    REQUIRE(s.at(0).NcToPlc.SetVelo == 1000.0);
    REQUIRE(s.at(2).NcToPlc.SetVelo == 500.0);
    REQUIRE(s.at(4).NcToPlc.SetVelo == 2000.0);
    // A1 on its own emergency ramp (D 10000 mm/s²), A3 following it (factor 2).
    REQUIRE(s.at(1).NcToPlc.SetAcc >= -10000.0 * (1 + 1e-9));
    REQUIRE(s.at(3).NcToPlc.SetPos == Approx(2.0 * s.at(1).NcToPlc.SetPos + offset3).margin(1e-9));
    REQUIRE(s.delayed_bit(1));
    REQUIRE(s.error(3) == 0U);
  }
  CHECK(s.at(1).NcToPlc.SetVelo == 0.0);  // 1000 mm/s down in about 0.11 s
  CHECK(s.at(3).NcToPlc.SetVelo == 0.0);
}

TEST_CASE(
    "DELAYED 0.5 s: the group reacts 500 cycles after the error, without a slave "
    "decoupled at 0.2 s",
    "[propagation][delayed]") {
  Star s;
  // 0.2 s after the error, MC_GearOut of A2 in motion: it goes on as a master at 500 mm/s.
  s.cycles(199);
  const uint16_t out = s.post(2, gr::gear_out());
  s.cycles(1);
  REQUIRE(s.answer(2, out).state == CommandState::kDone);
  REQUIRE(s.at(2).NcToPlc.CoupleState == 0U);
  // Cycles 201 … 499 after the error: nothing more.
  for (int k = 201; k < 500; ++k) {
    s.cycles(1);
    INFO("cycle " << k << " after the error");
    REQUIRE(s.delayed_bit(1));
    REQUIRE(s.error(0) == 0U);
    REQUIRE(s.error(4) == 0U);
    REQUIRE(s.error(3) == 0U);
  }
  // Cycle 500 = 0.5 s / 1 ms: the group reaction, on A0, A3 and A4 with A1's code; bit 6 reset.
  s.cycles(1);
  CHECK_FALSE(s.delayed_bit(1));
  CHECK(s.error_bit(1));
  for (const std::size_t i : {0U, 3U, 4U}) {
    INFO("axis " << i);
    CHECK(s.error(i) == kFollowing);
    CHECK(kt::axis_state(s.at(i)) == AxisState::kErrorStop);
    CHECK_FALSE(s.delayed_bit(i));
  }
  // A2 was no longer in the group: it goes on at 500 mm/s without an error.
  CHECK(s.error(2) == 0U);
  // The head master runs down its emergency ramp, A4 follows it down.
  const double offset4 = s.at(4).NcToPlc.SetPos - 2.0 * s.at(0).NcToPlc.SetPos;
  for (int k = 0; k < 300; ++k) {
    s.cycles(1);
    REQUIRE(s.at(4).NcToPlc.SetPos == Approx(2.0 * s.at(0).NcToPlc.SetPos + offset4).margin(1e-9));
    REQUIRE(s.at(2).NcToPlc.SetVelo == 500.0);
  }
  CHECK(s.at(0).NcToPlc.SetVelo == 0.0);
  CHECK(s.at(4).NcToPlc.SetVelo == 0.0);
  CHECK(s.error(2) == 0U);
}

TEST_CASE("MC_Reset of the faulty axis before the delay runs out cancels the group reaction",
          "[propagation][delayed]") {
  Star s;
  s.cycles(300);
  const uint16_t reset = s.post(1, kt::simple(CommandType::kReset));
  s.cycles(1);
  CHECK(s.answer(1, reset).state == CommandState::kDone);
  CHECK(s.error(1) == 0U);
  CHECK_FALSE(s.delayed_bit(1));
  s.cycles(400);  // past 0.5 s
  for (const std::size_t i : {0U, 1U, 2U, 3U, 4U}) {
    INFO("axis " << i);
    CHECK(s.error(i) == 0U);
  }
  CHECK(s.at(0).NcToPlc.SetVelo == 1000.0);
  // The slave that left stays out of the coupling (it stands) until MC_GearOut, which refuses
  // nothing and leaves it a single axis; a start before it is refused like a coupled slave's.
  CHECK(s.at(1).NcToPlc.SetVelo == 0.0);
  CHECK(s.at(1).NcToPlc.CoupleState == 2U);
  const uint16_t move = s.post(1, kt::move_relative(10.0, 100.0));
  s.cycles(1);
  CHECK(s.answer(1, move).state == CommandState::kError);
  CHECK(s.answer(1, move).error_code == kt::id(ErrorCode::kFunctionNotAllowed));
  const uint16_t again = s.post(1, gr::gear_in(0, 1.0));
  s.cycles(1);
  CHECK(s.answer(1, again).error_code == kt::id(ErrorCode::kFunctionNotAllowed));
  const uint16_t out = s.post(1, gr::gear_out());
  s.cycles(1);
  CHECK(s.answer(1, out).state == CommandState::kDone);
  CHECK(s.at(1).NcToPlc.CoupleState == 1U);  // A3 still follows A1
  CHECK(s.at(3).NcToPlc.CoupleState == 3U);
  CHECK(s.at(0).NcToPlc.CoupleState == 1U);  // A0 still masters A2 and A4
}

TEST_CASE("DELAYED on the head master: it stops alone, its slaves follow it by set values",
          "[propagation][delayed]") {
  pr::Group g(3, [](std::size_t i, nc::AxisConfig& c) {
    if (i == 0) pr::delayed(c, 0.25);
  });
  REQUIRE(g.couple(1, 0, 1.5));
  REQUIRE(g.couple(2, 1, -1.0));
  g.post(0, kt::move_absolute(20000.0, 1000.0));
  g.cycles(500);
  kt::set_enables(g.at(0), true, false, true);  // feed enable + gone while it moves +
  g.cycles(1);
  REQUIRE(g.error(0) == kt::id(ErrorCode::kFeedEnablePlusMissing));
  CHECK(g.delayed_bit(0));
  const double offset1 = g.at(1).NcToPlc.SetPos - 1.5 * g.at(0).NcToPlc.SetPos;
  for (int k = 1; k < 250; ++k) {
    g.cycles(1);
    REQUIRE(g.error(1) == 0U);
    REQUIRE(g.error(2) == 0U);
    REQUIRE(g.at(1).NcToPlc.SetPos == Approx(1.5 * g.at(0).NcToPlc.SetPos + offset1).margin(1e-9));
  }
  g.cycles(1);  // 250 cycles = 0.25 s
  CHECK(g.error(1) == kt::id(ErrorCode::kFeedEnablePlusMissing));
  CHECK(g.error(2) == kt::id(ErrorCode::kFeedEnablePlusMissing));
  CHECK_FALSE(g.delayed_bit(0));
}

TEST_CASE("DELAYED with delay 0 acts as INSTANTANEOUS; an uncoupled DELAYED axis never shows bit 6",
          "[propagation][delayed]") {
  pr::Group g(3, [](std::size_t i, nc::AxisConfig& c) {
    if (i == 1) pr::slow_drive(c);
    if (i == 1) pr::delayed(c, 0.0);
    if (i == 2) {
      pr::slow_drive(c);
      pr::delayed(c, 0.5);
    }
  });
  REQUIRE(g.couple(1, 0, 1.0));
  g.post(0, kt::move_absolute(20000.0, 1000.0));
  g.post(2, kt::move_absolute(20000.0, 1000.0));
  REQUIRE(g.until_error(1) > 0);
  CHECK(g.error(0) == kt::id(ErrorCode::kFollowingErrorPosition));
  CHECK_FALSE(g.delayed_bit(1));
  if (g.error(2) == 0U) REQUIRE(g.until_error(2) > 0);
  CHECK_FALSE(g.delayed_bit(2));
}

TEST_CASE(
    "a faulty slave released by MC_GearOut during the delay takes the group reaction "
    "only to its own slaves",
    "[propagation][delayed]") {
  Star s;
  s.cycles(100);
  const uint16_t out = s.post(1, gr::gear_out());  // while A1 is in error
  s.cycles(1);
  CHECK(s.answer(1, out).state == CommandState::kDone);
  CHECK(s.at(1).NcToPlc.CoupleState == 1U);  // A3's master only
  CHECK(s.at(0).NcToPlc.CoupleState == 1U);  // still A2's and A4's
  CHECK(s.error(1) == kFollowing);
  CHECK(s.delayed_bit(1));
  s.cycles(398);  // cycle 499 after the error
  CHECK(s.error(3) == 0U);
  s.cycles(1);  // cycle 500: A1's group is A1 and A3 now
  CHECK(s.error(3) == kFollowing);
  CHECK_FALSE(s.delayed_bit(1));
  for (const std::size_t i : {0U, 2U, 4U}) {
    INFO("axis " << i);
    CHECK(s.error(i) == 0U);
  }
  CHECK(s.at(0).NcToPlc.SetVelo == 1000.0);
}
