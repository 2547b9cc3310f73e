// MC_Stop and MC_Halt on a two-speed axis in the kernel (SPEC E2; seed 004 "Stop during an active
// positioning"), issue 12's numbers: a stop at 500 during rapid creeps for the creep distance for
// stop (20 mm, counted from where it is called), then brakes after the brake incidence delay; no
// rapid bit after the stop; the positioning is CommandAborted, the stop Done when the brake is
// on; MC_Stop locks motion commands until its Execute falls, MC_Halt does not.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>

#include "two_speed_kernel_rig.hpp"

using tsk::C;
using tsk::Sample;
using tsk::State;

namespace {

// Starts 0 → 1000 and runs until the encoder passed 500 (in rapid); returns the trace index of
// the cycle the stop block is called before.
std::size_t start_and_reach_500(tsk::Rig& rig) {
  rig.move.Position = 1000.0;
  rig.move.Velocity = 2000.0;
  rig.move.Execute = true;
  REQUIRE(rig.cycles_until([&] { return rig.actual() >= 500.0; }) > 0);
  REQUIRE(rig.last.bit(C::bPlusHigh));
  return rig.trace.size();
}

void check_stop_sequence(const tsk::Rig& rig, std::size_t called, double stop_position) {
  const std::vector<Sample>& t = rig.trace;
  CHECK(ts::images_consistent(t));
  // The stop's own cycle: rapid off, 22.
  CHECK_FALSE(t[called].bit(C::bPlusHigh));
  CHECK(t[called].state == State::kHighToLowDelay);
  for (std::size_t i = called; i < t.size(); ++i) {
    INFO("cycle " << i);
    REQUIRE_FALSE(t[i].bit(C::bPlusHigh));
    REQUIRE_FALSE(t[i].bit(C::bMinusHigh));
  }
  const std::size_t creep_on = ts::first(
      t, [](const Sample& s) { return s.bit(C::bPlusLow); }, called);
  REQUIRE(creep_on == called + 20);  // rapid-to-creep delay
  const std::size_t creep_off = ts::first(
      t, [](const Sample& s) { return !s.bit(C::bPlusLow); }, creep_on);
  REQUIRE(creep_off != ts::kNotFound);
  CHECK(t[creep_off].read >= stop_position + 20.0);
  CHECK(t[creep_off - 1].read < stop_position + 20.0);
  CHECK(t[creep_off].state == State::kBrakeIncidenceDelay);
  const std::size_t brake_on = ts::first(
      t, [](const Sample& s) { return s.brake(); }, creep_off);
  REQUIRE(brake_on == creep_off + 30);  // brake incidence delay +, 0.03 s
  CHECK(t[brake_on].state == State::kStopped);
}

}  // namespace

TEST_CASE("MC_Stop at 500 during rapid: creep 20 mm, brake, no rapid after the stop",
          "[two_speed][kernel][stop]") {
  tsk::Rig rig;
  const std::size_t called = start_and_reach_500(rig);
  const double stop_position = rig.actual();
  rig.stop.Execute = true;
  REQUIRE(rig.cycles_until([&] { return rig.stop.Done || rig.stop.Error; }) > 0);
  CHECK(rig.stop.Done);
  CHECK(rig.move.CommandAborted);
  check_stop_sequence(rig, called, stop_position);
  rig.cycles(300);
  // Short of 520 by the run-down (rapid to creep ramp, then the brake): well before the target.
  CHECK(rig.actual() > stop_position + 20.0);
  CHECK(rig.actual() < stop_position + 40.0);
  CHECK(rig.state() == State::kStopped);
  CHECK(plc::test_bit(rig.axis.NcToPlc.StateDWord, plc::kStateHasBeenStopped));

  // Locked while MC_Stop's Execute stays TRUE: a start is refused (0x42EF), nothing moves.
  CHECK(plc::test_bit(rig.axis.NcToPlc.StateDWord, plc::kStateMotionCommandsLocked));
  rig.move.Execute = false;
  rig.cycle();
  rig.move.Position = 0.0;
  rig.move.Execute = true;
  rig.cycles(2);
  CHECK(rig.move.Error);
  CHECK(rig.move.ErrorID == plc::to_id(plc::ErrorCode::kMotionCommandsLocked));
  CHECK(rig.image().nControlByte == plc::bit_mask(C::bBreak));

  // Execute falls: unlocked; the next start runs.
  rig.stop.Execute = false;
  rig.move.Execute = false;
  rig.cycles(2);
  CHECK_FALSE(plc::test_bit(rig.axis.NcToPlc.StateDWord, plc::kStateMotionCommandsLocked));
  REQUIRE(rig.position_to(0.0));
}

TEST_CASE("MC_Halt at 500 during rapid: the same sequence, no lock", "[two_speed][kernel][stop]") {
  tsk::Rig rig;
  const std::size_t called = start_and_reach_500(rig);
  const double stop_position = rig.actual();
  rig.halt.Execute = true;
  REQUIRE(rig.cycles_until([&] { return rig.halt.Done || rig.halt.Error; }) > 0);
  CHECK(rig.halt.Done);
  CHECK(rig.move.CommandAborted);
  check_stop_sequence(rig, called, stop_position);
  CHECK_FALSE(plc::test_bit(rig.axis.NcToPlc.StateDWord, plc::kStateMotionCommandsLocked));
  rig.cycles(300);
  REQUIRE(rig.position_to(0.0));
}

TEST_CASE("a stop at rest is Done at once and a stop without enable is refused",
          "[two_speed][kernel][stop]") {
  tsk::Rig rig;
  rig.halt.Execute = true;
  rig.cycles(3);
  CHECK(rig.halt.Done);
  CHECK(rig.image().nControlByte == plc::bit_mask(C::bBreak));
  rig.halt.Execute = false;
  rig.power.Enable = false;
  rig.cycles(2);
  rig.halt.Execute = true;
  rig.cycles(2);
  CHECK(rig.halt.Error);
  CHECK(rig.halt.ErrorID == plc::to_id(plc::ErrorCode::kNoControllerOrFeedEnable));
}
