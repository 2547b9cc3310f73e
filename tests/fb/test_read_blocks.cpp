// The Enable-type read blocks: while Enable is TRUE they show Valid and Busy and read NcToPlc on
// every call; with Enable FALSE every output is FALSE / 0.
//  - MC_ReadStatus: one PLCopen state boolean from NcToPlc.AxisState (Tc2_MC2 MC_AxisStates
//    values), ConstantVelocity from StateDWord bit 12, Accelerating / Decelerating from the sign
//    of SetAcc relative to SetVelo; a two-speed nAxisState mapped to its PLCopen state; any
//    other AxisState without a PLCopen state: Error 0x4040.
//  - MC_ReadActualPosition: Position = ActPos.
//  - MC_ReadAxisError: AxisErrorID = NcToPlc.ErrorCode.
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <limits>

#include "fb/mc_read_actual_position.hpp"
#include "fb/mc_read_axis_error.hpp"
#include "fb/mc_read_status.hpp"
#include "plc_interface/axis_ref.hpp"
#include "plc_interface/two_speed.hpp"

namespace {

int states_shown(const fb::MC_ReadStatus& s) {
  return int{s.ErrorStop} + int{s.Disabled} + int{s.Stopping} + int{s.StandStill} +
         int{s.DiscreteMotion} + int{s.ContinuousMotion} + int{s.SynchronizedMotion} +
         int{s.Homing};
}

}  // namespace

TEST_CASE("MC_ReadStatus shows exactly the PLCopen state the NC publishes", "[fb][read]") {
  struct Row {
    uint32_t axis_state;
    bool fb::MC_ReadStatus::*flag;
  };
  const Row row = GENERATE(
      Row{1, &fb::MC_ReadStatus::Disabled}, Row{2, &fb::MC_ReadStatus::StandStill},
      Row{3, &fb::MC_ReadStatus::ErrorStop}, Row{4, &fb::MC_ReadStatus::Stopping},
      Row{5, &fb::MC_ReadStatus::Homing}, Row{6, &fb::MC_ReadStatus::DiscreteMotion},
      Row{7, &fb::MC_ReadStatus::ContinuousMotion}, Row{8, &fb::MC_ReadStatus::SynchronizedMotion});
  INFO("AxisState " << row.axis_state);
  plc::AXIS_REF axis{};
  axis.NcToPlc.AxisState = row.axis_state;
  fb::MC_ReadStatus status;
  status.Enable = true;
  status(axis);
  REQUIRE(status.Valid);
  REQUIRE(status.Busy);
  REQUIRE_FALSE(status.Error);
  REQUIRE(status.*row.flag);
  REQUIRE(states_shown(status) == 1);
}

TEST_CASE("MC_ReadStatus: an AxisState without a PLCopen state gives Error 0x4040, not Valid",
          "[fb][read]") {
  const uint32_t state = GENERATE(9U, 19U, 25U, 1000U);  // neither PLCopen nor two-speed values
  INFO("AxisState " << state);
  plc::AXIS_REF axis{};
  axis.NcToPlc.AxisState = state;
  fb::MC_ReadStatus status;
  status.Enable = true;
  status(axis);
  REQUIRE_FALSE(status.Valid);
  REQUIRE(status.Error);
  REQUIRE(status.ErrorID == 0x4040);
  REQUIRE(states_shown(status) == 0);
}

TEST_CASE("MC_ReadStatus: a two-speed nAxisState (SPEC E5) maps to one PLCopen state",
          "[fb][read][two_speed]") {
  using S = plc::TwoSpeedAxisState;
  using A = plc::AxisState;
  const uint32_t operational = 1U << plc::kStateOperational;
  const uint32_t stopped = operational | 1U << plc::kStateHasBeenStopped;
  const uint32_t error = 1U << plc::kStateError;
  struct Row {
    S state;
    uint32_t word;
    A expected;
  };
  const std::array<Row, 9> rows{{
      {S::kInactive, 0U, A::kDisabled},
      {S::kInactive, operational, A::kStandstill},
      {S::kStopped, operational, A::kStandstill},
      {S::kMainTravel, operational, A::kDiscreteMotion},
      {S::kLowSpeedTravel, operational, A::kDiscreteMotion},
      {S::kLowSpeedTravel, stopped, A::kStopping},
      {S::kBrakeIncidenceDelay, stopped, A::kStopping},
      {S::kInactive, error, A::kErrorStop},
      {S::kMainTravel, operational | error, A::kErrorStop},
  }};
  for (const Row& row : rows) {
    INFO("nAxisState " << static_cast<uint32_t>(row.state) << " StateDWord " << row.word);
    plc::AXIS_REF axis{};
    axis.NcToPlc.AxisState = static_cast<uint32_t>(row.state);
    axis.NcToPlc.StateDWord = row.word;
    fb::MC_ReadStatus status;
    status.Enable = true;
    status(axis);
    CHECK(status.Valid);
    CHECK_FALSE(status.Error);
    CHECK(states_shown(status) == 1);
    CHECK(status.Disabled == (row.expected == A::kDisabled));
    CHECK(status.StandStill == (row.expected == A::kStandstill));
    CHECK(status.DiscreteMotion == (row.expected == A::kDiscreteMotion));
    CHECK(status.Stopping == (row.expected == A::kStopping));
    CHECK(status.ErrorStop == (row.expected == A::kErrorStop));
  }
}

TEST_CASE("MC_ReadStatus: Accelerating, Decelerating and ConstantVelocity", "[fb][read]") {
  struct Row {
    double velo, acc;
    bool constant_bit;
    bool constant, accelerating, decelerating;
  };
  const Row row = GENERATE(Row{0.0, 0.0, false, false, false, false},    // at rest
                           Row{0.0, 500.0, false, false, true, false},   // starting forward
                           Row{0.0, -500.0, false, false, true, false},  // starting backward
                           Row{1000.0, 5000.0, false, false, true, false},
                           Row{1000.0, -5000.0, false, false, false, true},
                           Row{-1000.0, -5000.0, false, false, true, false},
                           Row{-1000.0, 5000.0, false, false, false, true},
                           Row{2000.0, 0.0, true, true, false, false},
                           Row{2000.0, 0.0, false, false, false, false});
  INFO("SetVelo " << row.velo << " SetAcc " << row.acc << " bit 12 " << row.constant_bit);
  plc::AXIS_REF axis{};
  axis.NcToPlc.AxisState = 6;
  axis.NcToPlc.SetVelo = row.velo;
  axis.NcToPlc.SetAcc = row.acc;
  axis.NcToPlc.StateDWord = plc::with_bit(0, plc::kStateConstantVelocity, row.constant_bit);
  fb::MC_ReadStatus status;
  status.Enable = true;
  status(axis);
  REQUIRE(status.ConstantVelocity == row.constant);
  REQUIRE(status.Accelerating == row.accelerating);
  REQUIRE(status.Decelerating == row.decelerating);
}

TEST_CASE("MC_ReadStatus with Enable FALSE shows nothing", "[fb][read]") {
  plc::AXIS_REF axis{};
  axis.NcToPlc.AxisState = 7;
  axis.NcToPlc.SetVelo = 100.0;
  axis.NcToPlc.SetAcc = 100.0;
  fb::MC_ReadStatus status;
  status.Enable = true;
  status(axis);
  REQUIRE(status.ContinuousMotion);
  REQUIRE(status.Accelerating);
  status.Enable = false;
  status(axis);
  REQUIRE_FALSE(status.Valid);
  REQUIRE_FALSE(status.Busy);
  REQUIRE_FALSE(status.ContinuousMotion);
  REQUIRE_FALSE(status.Accelerating);
  REQUIRE(states_shown(status) == 0);
}

TEST_CASE("MC_ReadActualPosition shows ActPos on every call while enabled", "[fb][read]") {
  plc::AXIS_REF axis{};
  fb::MC_ReadActualPosition read;
  read.Enable = true;
  axis.NcToPlc.ActPos = 1999.9987;
  read(axis);
  REQUIRE(read.Valid);
  REQUIRE(read.Busy);
  REQUIRE(read.Position == 1999.9987);
  axis.NcToPlc.ActPos = -12.5;
  read(axis);
  REQUIRE(read.Position == -12.5);

  axis.NcToPlc.ActPos = std::numeric_limits<double>::quiet_NaN();
  read(axis);
  REQUIRE_FALSE(read.Valid);
  REQUIRE(read.Error);
  REQUIRE(read.ErrorID == 0x4F0B);
  REQUIRE(read.Position == 0.0);

  axis.NcToPlc.ActPos = 7.0;
  read.Enable = false;
  read(axis);
  REQUIRE_FALSE(read.Valid);
  REQUIRE_FALSE(read.Busy);
  REQUIRE_FALSE(read.Error);
  REQUIRE(read.Position == 0.0);
}

TEST_CASE("MC_ReadAxisError shows NcToPlc.ErrorCode while enabled", "[fb][read]") {
  plc::AXIS_REF axis{};
  fb::MC_ReadAxisError read;
  read.Enable = true;
  read(axis);
  REQUIRE(read.Valid);
  REQUIRE(read.AxisErrorID == 0);
  axis.NcToPlc.ErrorCode = 0x4550;
  read(axis);
  REQUIRE(read.AxisErrorID == 0x4550);
  REQUIRE_FALSE(read.Error);  // the axis's error is not the block's
  read.Enable = false;
  read(axis);
  REQUIRE_FALSE(read.Valid);
  REQUIRE(read.AxisErrorID == 0);
}
