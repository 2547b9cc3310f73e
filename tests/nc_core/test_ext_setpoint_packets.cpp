// Which NC cycle takes which external setpoint packet (seed 000 §2.6, seed 001, SPEC B8): a packet
// is taken only while ExtSetDirection is -1 or +1; in the first cycle whose direction is 0 and in
// the cycle of the disable the ExtSetPos then in the interface is still taken; from the next
// cycle on the set position is held. Absolute: the fed values are the set values.
#include <catch2/catch.hpp>

#include <vector>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::CommandType;

TEST_CASE(
    "absolute: packets are taken while the direction is ±1, the first 0 still takes the "
    "position, then it holds",
    "[ext_setpoint][packets]") {
  kt::Harness h;
  const uint16_t enable = h.post(kt::ext_enable(0.0, 1));
  h.cycles(1);
  CHECK(h.state_of(enable) == CommandState::kDone);
  CHECK(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
  CHECK(h.x->NcToPlc.SetPos == 0.0);

  // Cycle i feeds position i, velocity 1000 + i, acceleration 10 + i, with this direction:
  const std::vector<int> direction{0, 1, 1, 0, 0, -1, 0, 1, 0};
  const std::vector<double> position{0.0, 2.0, 3.0, 4.0, 4.0, 6.0, 7.0, 8.0, 9.0};
  const std::vector<double> velocity{0.0, 1002.0, 1003.0, 0.0, 0.0, 1006.0, 0.0, 1008.0, 0.0};
  for (std::size_t i = 0; i < direction.size(); ++i) {
    INFO("packet " << i + 1 << ", direction " << direction[i]);
    const double k = static_cast<double>(i + 1);
    kt::feed(*h.x, k, 1000.0 + k, 10.0 + k, direction[i]);
    h.cycles(1);
    CHECK(h.x->NcToPlc.SetPos == position[i]);
    CHECK(h.x->NcToPlc.SetVelo == velocity[i]);
    CHECK(h.x->NcToPlc.SetAcc == (velocity[i] != 0.0 ? 10.0 + k : 0.0));
  }
  CHECK(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
  CHECK(h.x->NcToPlc.ErrorCode == 0);
}

TEST_CASE("a direction other than -1, 0, +1 counts as no movement", "[ext_setpoint][packets]") {
  kt::Harness h;
  h.post(kt::ext_enable(0.0, 1));
  kt::feed(*h.x, 1.0, 0.0, 0.0, 1);
  h.cycles(1);
  CHECK(h.x->NcToPlc.SetPos == 1.0);
  kt::feed(*h.x, 2.0, 0.0, 0.0, 2);  // first non-±1 cycle: the position is still taken
  h.cycles(1);
  CHECK(h.x->NcToPlc.SetPos == 2.0);
  kt::feed(*h.x, 3.0, 0.0, 0.0, -7);
  h.cycles(1);
  CHECK(h.x->NcToPlc.SetPos == 2.0);
}

TEST_CASE("after the disable the external set position is taken for exactly one more cycle",
          "[ext_setpoint][packets]") {
  kt::Harness h;
  h.post(kt::ext_enable(0.0, 1));
  for (int i = 1; i <= 5; ++i) {
    kt::feed(*h.x, 0.5 * i, 500.0, 0.0, 1);
    h.cycles(1);
  }
  CHECK(h.x->NcToPlc.SetPos == 2.5);
  const uint16_t disable = h.post(kt::simple(CommandType::kExtSetPointGenDisable));
  kt::feed(*h.x, 3.0, 500.0, 0.0, 1);
  h.cycles(1);
  CHECK(h.state_of(disable) == CommandState::kDone);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
  CHECK(h.x->NcToPlc.SetPos == 3.0);  // the one more cycle
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  for (int i = 0; i < 10; ++i) {
    kt::feed(*h.x, 3.5 + i, 500.0, 0.0, 1);
    h.cycles(1);
    REQUIRE(h.x->NcToPlc.SetPos == 3.0);  // held, whatever is fed
  }
  // Disabling what is not enabled does nothing and is not an error.
  const uint16_t again = h.post(kt::simple(CommandType::kExtSetPointGenDisable));
  h.cycles(1);
  CHECK(h.state_of(again) == CommandState::kDone);
  CHECK(h.x->NcToPlc.SetPos == 3.0);
  // After the generation the axis is a normal PTP axis again.
  const uint16_t move = h.post(kt::move_absolute(10.0, 100.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == 10.0);
}

TEST_CASE("relative without internal motion: set position = position at the enable + ExtSetPos",
          "[ext_setpoint][packets]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(50.0, 500.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  h.post(kt::ext_enable(0.0, 2));
  kt::feed(*h.x, 0.0, 0.0, 0.0, 0);
  h.cycles(1);
  CHECK(h.x->NcToPlc.SetPos == 50.0);
  for (int i = 1; i <= 100; ++i) {
    kt::feed(*h.x, 0.2 * i, 200.0, 0.0, 1);
    h.cycles(1);
  }
  CHECK(h.x->NcToPlc.SetPos == Approx(70.0).epsilon(1e-15));
  CHECK(h.x->NcToPlc.SetVelo == 200.0);
  kt::feed(*h.x, 20.0, 0.0, 0.0, 0);
  h.cycles(1);
  CHECK(h.x->NcToPlc.SetPos == 70.0);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  h.post(kt::simple(CommandType::kExtSetPointGenDisable));
  kt::feed(*h.x, -5.0, 0.0, 0.0, 0);
  h.cycles(1);
  CHECK(h.x->NcToPlc.SetPos == 45.0);  // the disable's cycle takes ExtSetPos once more
  h.cycles(20);
  CHECK(h.x->NcToPlc.SetPos == 45.0);
  // A relative start now refers to the held position.
  const uint16_t rel = h.post(kt::move_relative(5.0, 100.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(rel) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == 50.0);
}

TEST_CASE(
    "a relative external offset superimposed on a running MoveAbsolute moves its end by "
    "the offset",
    "[ext_setpoint][packets]") {
  kt::Harness h;
  kt::Harness twin;  // the basic motion alone
  for (kt::Harness* k : {&h, &twin})
    k->post(kt::move_absolute(1000.0, 500.0));
  h.cycles(100);
  twin.cycles(100);
  // Relative, Position 20: the target for the window is the basic target 1000 + 20.
  const uint16_t enable = h.post(kt::ext_enable(20.0, 2));
  for (int i = 1; i <= 400; ++i) {
    const double offset = i <= 200 ? 0.1 * i : 20.0;
    kt::feed(*h.x, offset, i <= 200 ? 100.0 : 0.0, 0.0, i <= 200 ? 1 : 0);
    h.cycles(1);
    twin.cycles(1);
    REQUIRE(h.x->NcToPlc.SetPos == Approx(twin.x->NcToPlc.SetPos + offset).epsilon(1e-15));
    if (i <= 200) REQUIRE(h.x->NcToPlc.SetVelo == twin.x->NcToPlc.SetVelo + 100.0);
  }
  CHECK(h.state_of(enable) == CommandState::kDone);
  CHECK(h.x->NcToPlc.TargetPos == 1020.0);
  const uint16_t move = h.x->NcToPlc.CmdNo;
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == 1020.0);
  CHECK(kt::bit(*h.x, plc::kStateInTargetPosition));
  CHECK(kt::bit(*h.x, plc::kStateExtSetPointGenEnabled));
}
