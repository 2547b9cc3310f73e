// Each block posts its own command type with its inputs in the command's fields; dynamics of 0
// are passed as 0 (the NC substitutes the axis default), nothing is clamped or checked here.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "block_under_test.hpp"

namespace {

template <class B>
plc::Command post_once(B& block) {
  plc::AXIS_REF axis{};
  fbtest::ScriptedNc nc(axis);
  block.Execute = true;
  block(axis);
  nc.cycle();
  REQUIRE(nc.taken().size() == 1);
  return nc.taken().front();
}

}  // namespace

TEST_CASE("MC_MoveAbsolute posts kMoveAbsolute with Position, Velocity and the dynamics",
          "[fb][command]") {
  fb::MC_MoveAbsolute move;
  move.Position = 2000.0;
  move.Velocity = 1000.0;
  move.Acceleration = 5000.0;
  move.Deceleration = 4000.0;
  move.Jerk = 50000.0;
  const plc::Command c = post_once(move);
  REQUIRE(c.type == plc::CommandType::kMoveAbsolute);
  REQUIRE(c.position == 2000.0);
  REQUIRE(c.velocity == 1000.0);
  REQUIRE(c.acceleration == 5000.0);
  REQUIRE(c.deceleration == 4000.0);
  REQUIRE(c.jerk == 50000.0);
  REQUIRE(c.buffer_mode == 0);
}

TEST_CASE("dynamics of 0 are passed as 0: the NC uses the axis defaults", "[fb][command]") {
  fb::MC_MoveAbsolute move;
  move.Position = -150.0;
  move.Velocity = 600.0;
  const plc::Command c = post_once(move);
  REQUIRE(c.position == -150.0);
  REQUIRE(c.acceleration == 0.0);
  REQUIRE(c.deceleration == 0.0);
  REQUIRE(c.jerk == 0.0);
}

TEST_CASE("bad motion parameters are posted unchanged: the NC validates them", "[fb][command]") {
  fb::MC_MoveRelative move;
  move.Distance = std::numeric_limits<double>::quiet_NaN();
  move.Velocity = -5.0;
  move.Jerk = std::numeric_limits<double>::infinity();
  const plc::Command c = post_once(move);
  REQUIRE(c.type == plc::CommandType::kMoveRelative);
  REQUIRE(std::isnan(c.position));
  REQUIRE(c.velocity == -5.0);
  REQUIRE(std::isinf(c.jerk));
}

TEST_CASE("MC_MoveRelative posts kMoveRelative with Distance in the position field",
          "[fb][command]") {
  fb::MC_MoveRelative move;
  move.Distance = -2000.0;
  move.Velocity = 2200.0;
  move.Acceleration = 1000.0;
  const plc::Command c = post_once(move);
  REQUIRE(c.type == plc::CommandType::kMoveRelative);
  REQUIRE(c.position == -2000.0);
  REQUIRE(c.velocity == 2200.0);
  REQUIRE(c.acceleration == 1000.0);
}

TEST_CASE("MC_MoveVelocity posts kMoveVelocity with Velocity, dynamics and direction",
          "[fb][command]") {
  fb::MC_MoveVelocity move;
  move.Velocity = 300.0;
  move.Deceleration = 2500.0;
  move.Jerk = 20000.0;
  move.Direction = fb::MC_Negative_Direction;
  const plc::Command c = post_once(move);
  REQUIRE(c.type == plc::CommandType::kMoveVelocity);
  REQUIRE(c.velocity == 300.0);
  REQUIRE(c.deceleration == 2500.0);
  REQUIRE(c.jerk == 20000.0);
  REQUIRE(c.direction == 3);
}

TEST_CASE("MC_Halt posts kHalt and MC_Stop kStop with Deceleration and Jerk", "[fb][command]") {
  fb::MC_Halt halt;
  halt.Deceleration = 2500.0;
  halt.Jerk = 30000.0;
  const plc::Command h = post_once(halt);
  REQUIRE(h.type == plc::CommandType::kHalt);
  REQUIRE(h.deceleration == 2500.0);
  REQUIRE(h.jerk == 30000.0);

  fb::MC_Stop stop;
  stop.Deceleration = 10000.0;
  const plc::Command s = post_once(stop);
  REQUIRE(s.type == plc::CommandType::kStop);
  REQUIRE(s.deceleration == 10000.0);
  REQUIRE(s.jerk == 0.0);
}

TEST_CASE("MC_Reset posts kReset", "[fb][command]") {
  fb::MC_Reset reset;
  REQUIRE(post_once(reset).type == plc::CommandType::kReset);
}

TEST_CASE("MC_MoveModulo posts kMoveModulo with Position, Velocity, the dynamics and Direction",
          "[fb][command]") {
  fb::MC_MoveModulo move;
  move.Position = 540.0;  // seed 000 §2.1: one extra turn, ends at modulo 180
  move.Velocity = 720.0;
  move.Acceleration = 3600.0;
  move.Deceleration = 1800.0;
  move.Jerk = 36000.0;
  move.Direction = fb::MC_Shortest_Way;
  const plc::Command c = post_once(move);
  REQUIRE(c.type == plc::CommandType::kMoveModulo);
  REQUIRE(c.position == 540.0);
  REQUIRE(c.velocity == 720.0);
  REQUIRE(c.acceleration == 3600.0);
  REQUIRE(c.deceleration == 1800.0);
  REQUIRE(c.jerk == 36000.0);
  REQUIRE(c.direction == 2);
  REQUIRE(c.buffer_mode == 0);
}

TEST_CASE("MC_NewPos posts kNewPos with NewPos as the position", "[fb][command]") {
  fb::MC_NewPos new_pos;
  new_pos.NewPos = 5000.0;  // seed 000 §2.3: 0 → 3000 mm, then 5000 mm
  const plc::Command c = post_once(new_pos);
  REQUIRE(c.type == plc::CommandType::kNewPos);
  REQUIRE(c.position == 5000.0);
  REQUIRE(c.velocity == 0.0);
}

TEST_CASE(
    "MC_NewPosAndVelo posts kNewPosAndVelo with EPos as the position, VNew as the velocity "
    "and APos as the activation position",
    "[fb][command]") {
  fb::MC_NewPosAndVelo change;
  change.NewPos = 4000.0;
  change.NewVelo = 1000.0;
  change.ActivationPos = 2500.0;
  const plc::Command c = post_once(change);
  REQUIRE(c.type == plc::CommandType::kNewPosAndVelo);
  REQUIRE(c.position == 4000.0);
  REQUIRE(c.velocity == 1000.0);
  REQUIRE(c.activation_position == 2500.0);
}

TEST_CASE("MC_NewPos and MC_NewPosAndVelo post bad values unchanged: the NC validates them",
          "[fb][command]") {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  fb::MC_NewPos new_pos;
  new_pos.NewPos = kNaN;
  REQUIRE(std::isnan(post_once(new_pos).position));

  fb::MC_NewPosAndVelo change;
  change.NewPos = -std::numeric_limits<double>::infinity();
  change.NewVelo = -1.0;
  change.ActivationPos = std::numeric_limits<double>::infinity();
  const plc::Command c = post_once(change);
  REQUIRE(std::isinf(c.position));
  REQUIRE(c.velocity == -1.0);
  REQUIRE(std::isinf(c.activation_position));
}
