// Start velocity and override on a two-speed axis in the kernel (SPEC E3; seed 004 "Velocity and
// override"), issue 12's numbers, through MC_MoveAbsolute, MC_Power.Override and MC_SetOverride:
// v 40 → creep only; override 40 % during rapid → creep; override 0 → stationary (travel bits
// off, still 21) and resumes; an override change in a braking phase changes nothing.
#include <catch2/catch.hpp>

#include <cstddef>

#include "two_speed_kernel_rig.hpp"

using tsk::C;
using tsk::Sample;
using tsk::State;

namespace {

bool any_rapid(const std::vector<Sample>& trace, std::size_t from = 0) {
  for (std::size_t i = from; i < trace.size(); ++i) {
    if (trace[i].bit(C::bPlusHigh) || trace[i].bit(C::bMinusHigh)) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("start velocity 40 creeps only; 50.0 too, 50.001 is rapid", "[two_speed][kernel]") {
  for (const double v : {40.0, 50.0}) {
    tsk::Rig rig;
    REQUIRE(rig.position_to(200.0, v));
    CHECK_FALSE(any_rapid(rig.trace));
    CHECK(rig.trace[50].bit(C::bPlusLow));  // creep on after the brake release delay
    CHECK(ts::state_sequence(rig.trace) == std::vector<uint32_t>{21, 23, 24, 20});
  }
  tsk::Rig rig;
  REQUIRE(rig.position_to(200.0, 50.001));
  CHECK(rig.trace[50].bit(C::bPlusHigh));
}

TEST_CASE("override 40 % during rapid: rapid off, the delay, creep", "[two_speed][kernel]") {
  tsk::Rig rig;
  rig.move.Position = 1000.0;
  rig.move.Velocity = 2000.0;
  rig.move.Execute = true;
  rig.cycles(100);
  REQUIRE(rig.last.bit(C::bPlusHigh));
  const std::size_t changed = rig.trace.size();
  rig.power.Override = 40.0;
  rig.cycle();
  CHECK_FALSE(rig.last.bit(C::bPlusHigh));
  CHECK_FALSE(rig.last.travel());
  CHECK(rig.last.state == State::kMainTravel);  // still main travel, through the delay
  rig.cycles(19);
  CHECK_FALSE(rig.last.travel());
  rig.cycle();
  CHECK(rig.last.bit(C::bPlusLow));  // 0.02 s after
  CHECK(rig.trace.size() == changed + 21);
  REQUIRE(rig.cycles_until([&] { return rig.move.Done; }, 40000) > 0);
  CHECK_FALSE(any_rapid(rig.trace, changed));
  // Back to 100 % in main travel: rapid at once (here the positioning has ended: nothing).
  rig.power.Override = 100.0;
  rig.cycles(2);
  CHECK(rig.image().nControlByte == plc::bit_mask(C::bBreak));
}

TEST_CASE("override 0 in main travel: stationary, brake released, 21; resumes at 100 %",
          "[two_speed][kernel]") {
  tsk::Rig rig;
  rig.override_block.Enable = true;
  rig.override_block.VelFactor = 1.0;
  rig.move.Position = 1000.0;
  rig.move.Velocity = 2000.0;
  rig.move.Execute = true;
  rig.cycles(200);
  REQUIRE(rig.last.bit(C::bPlusHigh));
  rig.override_block.VelFactor = 0.0;
  rig.cycles(300);  // the drive runs down
  CHECK_FALSE(rig.last.travel());
  CHECK_FALSE(rig.last.brake());
  CHECK(rig.last.state == State::kMainTravel);
  CHECK(rig.axis.NcToPlc.ActVelo == 0.0);
  const double held = rig.actual();
  CHECK(held < 900.0);
  rig.cycles(100);
  CHECK(rig.actual() == held);
  rig.override_block.VelFactor = 1.0;
  rig.cycle();
  CHECK(rig.last.bit(C::bPlusHigh));  // creep → rapid is at once
  REQUIRE(rig.cycles_until([&] { return rig.move.Done; }) > 0);
  rig.cycles(300);
  CHECK(std::abs(rig.actual() - 1000.0) <= 5.0);
}

TEST_CASE("an override change in a braking phase changes nothing", "[two_speed][kernel]") {
  tsk::Rig reference;
  REQUIRE(reference.position_to(1000.0));
  // The same positioning, the override falling to 0 in 22 and rising to 40 % in 23.
  tsk::Rig rig;
  rig.each = [](tsk::Rig& r) {
    if (r.last.state == State::kHighToLowDelay) r.power.Override = 0.0;
    if (r.last.state == State::kLowSpeedTravel) r.power.Override = 40.0;
  };
  REQUIRE(rig.position_to(1000.0));
  CHECK(rig.power.Override == 40.0);  // both changes were made
  REQUIRE(rig.trace.size() == reference.trace.size());
  for (std::size_t i = 0; i < rig.trace.size(); ++i) {
    INFO("cycle " << i);
    REQUIRE(rig.trace[i].image == reference.trace[i].image);
    REQUIRE(rig.trace[i].read == reference.trace[i].read);
    REQUIRE(rig.trace[i].state == reference.trace[i].state);
  }
}
