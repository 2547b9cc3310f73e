// Enables, errors and MC_Reset on a two-speed axis in the kernel (SPEC E5; issue 12's decision:
// nAxisState 0 before the first start and while disabled): losing the controller enable during
// a positioning fails it with 0x4356, the brake comes on at once and nAxisState is 0; a feed
// enable lost in the direction of travel fails it with 0x4358 / 0x4357; MC_Reset clears the
// error and the next positioning runs. MC_ReadStatus shows the PLCopen state that nAxisState and
// the StateDWord give (Disabled, StandStill, DiscreteMotion, Stopping, ErrorStop).
#include <catch2/catch.hpp>

#include "two_speed_kernel_rig.hpp"

using tsk::C;
using tsk::State;

namespace {

void start_and_run(tsk::Rig& rig, double target, int cycles) {
  rig.move.Execute = false;
  rig.cycle();
  rig.move.Position = target;
  rig.move.Velocity = 2000.0;
  rig.move.Execute = true;
  rig.cycles(cycles);
  REQUIRE(rig.state() == State::kMainTravel);
  REQUIRE(rig.last.travel());
}

void reset(tsk::Rig& rig) {
  rig.reset.Execute = true;
  REQUIRE(rig.cycles_until([&] { return rig.reset.Done || rig.reset.Error; }) > 0);
  CHECK(rig.reset.Done);
  rig.reset.Execute = false;
  rig.cycle();
}

}  // namespace

TEST_CASE("disable during a positioning: 0x4356, brake on at once, nAxisState 0; reset, restart",
          "[two_speed][kernel]") {
  tsk::Rig rig;
  rig.cycle();
  CHECK(rig.power.Status);
  CHECK(rig.state() == State::kInactive);
  start_and_run(rig, 1000.0, 200);
  rig.power.Enable = false;
  rig.cycle();
  CHECK(rig.image().nControlByte == plc::bit_mask(C::bBreak));
  CHECK(rig.state() == State::kInactive);
  CHECK(rig.axis.NcToPlc.ErrorCode == 0x4356U);
  rig.cycle();
  CHECK(rig.move.Error);
  CHECK(rig.move.ErrorID == 0x4356U);
  CHECK_FALSE(rig.power.Status);
  CHECK(plc::test_bit(rig.axis.NcToPlc.StateDWord, plc::kStateError));

  rig.power.Enable = true;
  rig.cycle();
  CHECK(rig.state() == State::kInactive);  // enabled again, no start yet
  // In error: a start is refused until MC_Reset.
  rig.move.Execute = false;
  rig.cycle();
  rig.move.Execute = true;
  rig.cycles(2);
  CHECK(rig.move.ErrorID == plc::to_id(plc::ErrorCode::kAxisInErrorState));
  reset(rig);
  CHECK(rig.axis.NcToPlc.ErrorCode == 0U);
  CHECK(rig.power.Status);
  const double from = rig.actual();
  REQUIRE(rig.position_to(from - 500.0));
  CHECK(rig.state() == State::kStopped);
}

TEST_CASE("a feed enable lost in the direction of travel fails the positioning",
          "[two_speed][kernel]") {
  tsk::Rig rig;
  start_and_run(rig, 1000.0, 200);
  rig.power.Enable_Negative = false;  // the other direction: nothing happens
  rig.cycles(10);
  CHECK(rig.last.bit(C::bPlusHigh));
  rig.power.Enable_Positive = false;
  rig.cycle();
  CHECK(rig.image().nControlByte == plc::bit_mask(C::bBreak));
  CHECK(rig.state() == State::kStopped);
  CHECK(rig.axis.NcToPlc.ErrorCode == 0x4358U);
  rig.cycle();
  CHECK(rig.move.ErrorID == 0x4358U);

  // Without the feed enable of its direction a start is refused (0x4223).
  rig.power.Enable_Positive = true;
  reset(rig);
  rig.power.Enable_Negative = false;
  rig.move.Execute = false;
  rig.cycle();
  rig.move.Position = 0.0;
  rig.move.Execute = true;
  rig.cycles(2);
  CHECK(rig.move.ErrorID == plc::to_id(plc::ErrorCode::kNoControllerOrFeedEnable));
  CHECK(rig.image().nControlByte == plc::bit_mask(C::bBreak));
}

TEST_CASE("MC_ReadStatus on a two-speed axis: StandStill, DiscreteMotion, Stopping, ErrorStop",
          "[two_speed][kernel]") {
  tsk::Rig rig;
  fb::MC_ReadStatus status;
  status.Enable = true;
  const auto read = [&] {
    status(rig.axis);
    REQUIRE(status.Valid);
    REQUIRE_FALSE(status.Error);
  };
  rig.cycle();
  read();
  CHECK(status.StandStill);  // enabled, nAxisState 0 before the first start
  start_and_run(rig, 1000.0, 200);
  read();
  CHECK(status.DiscreteMotion);
  rig.stop.Execute = true;
  rig.cycle();
  rig.cycle();
  REQUIRE(rig.state() != State::kStopped);
  read();
  CHECK(status.Stopping);
  REQUIRE(rig.cycles_until([&] { return rig.stop.Done || rig.stop.Error; }) > 0);
  CHECK(rig.state() == State::kStopped);
  read();
  CHECK(status.StandStill);
  rig.stop.Execute = false;
  rig.cycle();
  // Disabled while travelling: 0x4356, ErrorStop (the error bit wins over Disabled).
  start_and_run(rig, 2000.0, 200);
  rig.power.Enable = false;
  rig.cycle();
  read();
  CHECK(status.ErrorStop);
  reset(rig);
  read();
  CHECK(status.Disabled);
}
