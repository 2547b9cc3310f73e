// A two-speed positioning in the kernel through MC_Power and MC_MoveAbsolute / MC_MoveRelative
// (SPEC E1, E4, E5; seed 004 "Positioning A → B, without loop movement"), with issue 12's
// numbers: brake released at T0 (the start's cycle), rapid on at T0 + 0.05 s, rapid off in the
// first cycle whose encoder value passed the creep point, creep on 0.02 s later, creep off past the
// braking point, brake on after the brake incidence delay; nAxisState 21 → 22 → 23 → 24 → 20 in
// those cycles; Done when the brake is on; both control bytes consistent in every cycle; the end
// within the braking distance of the target, the same bit for bit in a second run and cycle for
// cycle what the standalone sequencer and plant do.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "two_speed_kernel_rig.hpp"

using tsk::C;
using tsk::Sample;
using tsk::State;

namespace {

struct Direction {
  double target;
  double creep_point;    // rapid off once the encoder value passed it
  double braking_point;  // creep off once the encoder value passed it
  std::size_t brake_incidence_cycles;
  double braking_distance;
  C rapid;
  C creep;
};

const Direction kPositive{1000.0, 900.0, 995.0, 30, 5.0, C::bPlusHigh, C::bPlusLow};
const Direction kNegative{-1000.0, -880.0, -994.0, 40, 6.0, C::bMinusHigh, C::bMinusLow};

bool passed(double p, double point, double target) {
  return target > 0.0 ? p >= point : p <= point;
}

void check_positioning(const Direction& d) {
  tsk::Rig rig;
  CHECK(rig.state() == State::kInactive);  // enabled, never started: 0
  REQUIRE(rig.position_to(d.target));
  const std::vector<Sample>& trace = rig.trace;
  CHECK(ts::images_consistent(trace));

  // T0: the start's cycle releases the brake; nothing travels yet; nAxisState 21.
  CHECK_FALSE(trace[0].brake());
  CHECK(trace[0].bit(C::bBreakInv));
  CHECK_FALSE(trace[0].travel());
  CHECK(trace[0].state == State::kMainTravel);

  const std::size_t rapid_on = ts::first(trace, [&](const Sample& s) { return s.bit(d.rapid); });
  REQUIRE(rapid_on != ts::kNotFound);
  CHECK(rapid_on == 50);  // T0 + 0.05 s at 1 ms

  const std::size_t rapid_off = ts::first(
      trace, [&](const Sample& s) { return !s.bit(d.rapid); }, rapid_on);
  REQUIRE(rapid_off != ts::kNotFound);
  CHECK(passed(trace[rapid_off].read, d.creep_point, d.target));
  CHECK_FALSE(passed(trace[rapid_off - 1].read, d.creep_point, d.target));
  CHECK(trace[rapid_off].state == State::kHighToLowDelay);
  CHECK(trace[rapid_off - 1].state == State::kMainTravel);

  const std::size_t creep_on = ts::first(trace, [&](const Sample& s) { return s.bit(d.creep); });
  REQUIRE(creep_on != ts::kNotFound);
  CHECK(creep_on == rapid_off + 20);  // rapid-to-creep delay 0.02 s
  CHECK(trace[creep_on].state == State::kLowSpeedTravel);
  CHECK(trace[creep_on - 1].state == State::kHighToLowDelay);

  const std::size_t creep_off = ts::first(
      trace, [&](const Sample& s) { return !s.bit(d.creep); }, creep_on);
  REQUIRE(creep_off != ts::kNotFound);
  CHECK(passed(trace[creep_off].read, d.braking_point, d.target));
  CHECK_FALSE(passed(trace[creep_off - 1].read, d.braking_point, d.target));
  CHECK(trace[creep_off].state == State::kBrakeIncidenceDelay);
  CHECK_FALSE(trace[creep_off].brake());

  const std::size_t brake_on = ts::first(
      trace, [](const Sample& s) { return s.brake(); }, creep_off);
  REQUIRE(brake_on != ts::kNotFound);
  CHECK(brake_on == creep_off + d.brake_incidence_cycles);
  CHECK(trace[brake_on].state == State::kStopped);
  CHECK(ts::state_sequence(trace) == std::vector<uint32_t>{21, 22, 23, 24, 20});
  // Done is reported in the brake-on cycle; the block shows it at its next call.
  CHECK(rig.move.Done);
  CHECK(trace.size() == brake_on + 2);

  rig.cycles(300);  // the plant runs down under the brake
  const double final_position = rig.actual();
  CHECK(std::abs(final_position - d.target) <= d.braking_distance);
  CHECK(rig.axis.NcToPlc.TargetPos == d.target);
  CHECK(rig.state() == State::kStopped);
  CHECK(rig.axis.NcToPlc.ErrorCode == 0U);

  // A second run: the same, bit for bit.
  tsk::Rig again;
  REQUIRE(again.position_to(d.target));
  again.cycles(300);
  CHECK(again.actual() == final_position);
  CHECK(again.trace == rig.trace);

  // The kernel runs exactly the standalone sequencer and plant, cycle for cycle.
  ts::Loop loop(ts::issue_axis());
  REQUIRE(loop.start(d.target, 2000.0) == plc::ErrorCode::kNone);
  for (std::size_t i = 0; i < trace.size(); ++i) {
    const ts::Sample& s = loop.cycle();
    INFO("cycle " << i);
    REQUIRE(s.image == trace[i].image);
    REQUIRE(s.actual == trace[i].read);
    REQUIRE(s.state == trace[i].state);
  }
}

}  // namespace

TEST_CASE("0 → 1000 at v 2000 through the blocks: the issue's timing in the kernel",
          "[two_speed][kernel]") {
  check_positioning(kPositive);
}

TEST_CASE("0 → -1000: the same with the negative-direction parameters", "[two_speed][kernel]") {
  check_positioning(kNegative);
}

TEST_CASE("MC_MoveRelative counts its distance from the actual position", "[two_speed][kernel]") {
  tsk::Rig rig;
  REQUIRE(rig.position_to(300.0));
  rig.cycles(300);
  const double from = rig.actual();
  rig.relative.Distance = 200.0;
  rig.relative.Velocity = 2000.0;
  rig.relative.Execute = true;
  REQUIRE(rig.cycles_until([&] { return rig.relative.Done || rig.relative.Error; }) > 0);
  CHECK(rig.relative.Done);
  CHECK(rig.axis.NcToPlc.TargetPos == from + 200.0);
  rig.cycles(300);
  CHECK(std::abs(rig.actual() - (from + 200.0)) <= 5.0);
}

TEST_CASE("the NC→PLC image of a two-speed axis while it travels and at rest",
          "[two_speed][kernel]") {
  tsk::Rig rig;
  rig.move.Position = 1000.0;
  rig.move.Velocity = 2000.0;
  rig.move.Execute = true;
  rig.cycles(200);  // rapid, ramped up (0.1 s) after the brake release delay
  const plc::NCTOPLC_AXIS_REF& nc = rig.axis.NcToPlc;
  CHECK(nc.AxisState == 21U);
  CHECK(nc.SetVelo == 500.0);  // the commanded speed: rapid, positive
  CHECK(nc.ActVelo == 500.0);
  CHECK(nc.SetPos == nc.ActPos);  // no set position: the actual one
  CHECK(plc::test_bit(nc.StateDWord, plc::kStateHasJob));
  CHECK(plc::test_bit(nc.StateDWord, plc::kStatePositiveDirection));
  CHECK(plc::test_bit(nc.StateDWord, plc::kStateConstantVelocity));
  CHECK_FALSE(plc::test_bit(nc.StateDWord, plc::kStateNotMoving));
  CHECK(plc::test_bit(nc.StateDWord, plc::kStateOperational));
  CHECK(rig.power.Status);
  CHECK(rig.move.Busy);
  CHECK(rig.move.Active);
  CHECK(nc.CoupleState == 0U);

  REQUIRE(rig.cycles_until([&] { return rig.move.Done; }) > 0);
  rig.cycles(300);
  CHECK(nc.AxisState == 20U);
  CHECK(nc.SetVelo == 0.0);
  CHECK(nc.ActVelo == 0.0);
  CHECK_FALSE(plc::test_bit(nc.StateDWord, plc::kStateHasJob));
  CHECK(plc::test_bit(nc.StateDWord, plc::kStateNotMoving));
  // The target window (2 mm by default) is reported, not waited for: the end is ~4.75 mm short.
  CHECK_FALSE(plc::test_bit(nc.StateDWord, plc::kStateInTargetPosition));
  fb::MC_ReadActualPosition read;
  read.Enable = true;
  read(rig.axis);
  CHECK(read.Valid);
  CHECK(read.Position == rig.actual());
}

// Fuzz finding K11's other half: at the largest rapid speed the configuration takes (1e12 mm/s)
// with a step ramp (ramp time 0), the step's acceleration is 1e12 / 0.001 s = 1e15 mm/s², and
// every value the NC publishes stays finite.
TEST_CASE("at a rapid speed of 1e12 mm/s with a step ramp every published value stays finite",
          "[two_speed][kernel]") {
  nc::AxisConfig config = ts::issue_axis();
  config.rapid_velocity = 1e12;
  config.two_speed_ramp_time = 0.0;
  tsk::Rig rig(config);
  rig.move.Position = 1000.0;
  rig.move.Velocity = 1e12;
  rig.move.Execute = true;
  double largest_acceleration = 0.0;
  for (int i = 0; i < 300; ++i) {
    rig.cycle();
    const plc::NCTOPLC_AXIS_REF& nc = rig.axis.NcToPlc;
    INFO("cycle " << i);
    for (const double value : {nc.ActPos, nc.ActVelo, nc.ActAcc, nc.SetPos, nc.SetVelo, nc.SetAcc,
                               nc.TargetPos, nc.TargetVelo})
      REQUIRE(std::isfinite(value));
    largest_acceleration = std::max(largest_acceleration, std::abs(nc.ActAcc));
  }
  CHECK(largest_acceleration == 1e15);
}
