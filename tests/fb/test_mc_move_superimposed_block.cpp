// MC_MoveSuperImposed (seed 000 §2.5): the command carries the seed's start parameters D, VK,
// AK+, AK-, VP and L; the compensation runs beside the basic motion, so Active follows the
// compensation's own answer while the basic move keeps CmdNo and stays Active; Warning shows the
// NC's 0x4243 (largest feasible D done) and follows the result; ActualDistance, ActualLength and
// ActualVelocityDiff come from the NC image while the compensation runs and stay after it.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "fb/mc_move_absolute.hpp"
#include "fb/mc_move_superimposed.hpp"
#include "plc_interface/axis_ref.hpp"
#include "scripted_nc.hpp"

namespace {

// A basic move running on a scripted NC, and a compensation block on the same axis.
struct Rig {
  plc::AXIS_REF axis{};
  fbtest::ScriptedNc nc{axis};
  fb::MC_MoveAbsolute move;
  fb::MC_MoveSuperImposed comp;

  Rig() {
    move.Position = 10000.0;
    move.Velocity = 2000.0;
    move.Execute = true;
    move(axis);
    nc.cycle();
    move(axis);
    // The seed's first figure: L 5000, D 250, VK 300, AK+ 500, AK- 1000, VP 2000.
    comp.Distance = 250.0;
    comp.VelocityDiff = 300.0;
    comp.Acceleration = 500.0;
    comp.Deceleration = 1000.0;
    comp.VelocityProcess = 2000.0;
    comp.Length = 5000.0;
  }
  void call(bool execute) {
    comp.Execute = execute;
    comp(axis);
    move(axis);
  }
};

}  // namespace

TEST_CASE("MC_MoveSuperImposed posts kMoveSuperImposed with D, VK, AK+, AK-, VP and L",
          "[fb][superimposed]") {
  Rig r;
  r.call(true);
  r.nc.cycle();
  const plc::Command c = r.nc.last(plc::CommandType::kMoveSuperImposed);
  REQUIRE(c.type == plc::CommandType::kMoveSuperImposed);
  REQUIRE(c.position == 250.0);
  REQUIRE(c.velocity == 300.0);
  REQUIRE(c.acceleration == 500.0);
  REQUIRE(c.deceleration == 1000.0);
  REQUIRE(c.process_velocity == 2000.0);
  REQUIRE(c.length == 5000.0);
  REQUIRE(c.jerk == 0.0);
}

TEST_CASE("MC_MoveSuperImposed checks nothing itself: a negative D and bad values reach the NC",
          "[fb][superimposed]") {
  Rig r;
  r.comp.Distance = -250.0;
  r.comp.Length = std::numeric_limits<double>::quiet_NaN();
  r.comp.VelocityDiff = 0.0;
  r.comp.Acceleration = -1.0;
  r.call(true);
  REQUIRE(r.comp.Busy);
  r.nc.cycle();
  const plc::Command c = r.nc.last(plc::CommandType::kMoveSuperImposed);
  REQUIRE(c.position == -250.0);
  REQUIRE(std::isnan(c.length));
  REQUIRE(c.velocity == 0.0);
  REQUIRE(c.acceleration == -1.0);
}

TEST_CASE(
    "the compensation runs beside the basic move: both blocks Busy and Active, CmdNo stays "
    "with the move",
    "[fb][superimposed]") {
  Rig r;
  r.call(true);
  REQUIRE(r.comp.Busy);
  REQUIRE_FALSE(r.comp.Active);  // posted, not yet taken
  r.nc.cycle();
  r.call(true);
  REQUIRE(r.comp.Busy);
  REQUIRE(r.comp.Active);
  REQUIRE(r.move.Busy);
  REQUIRE(r.move.Active);
  REQUIRE(r.axis.NcToPlc.CmdNo == r.move.command_number());

  r.nc.finish();  // the compensation ends first
  r.call(true);
  REQUIRE(r.comp.Done);
  REQUIRE_FALSE(r.comp.Busy);
  REQUIRE_FALSE(r.comp.Active);
  REQUIRE(r.move.Active);
}

TEST_CASE("a compensation stop ends the block with CommandAborted", "[fb][superimposed]") {
  Rig r;
  r.call(true);
  r.nc.cycle();
  r.call(true);
  plc::Command stop;
  stop.type = plc::CommandType::kAbortSuperposition;
  r.axis.Mailbox.post(stop);
  r.nc.cycle();
  r.call(true);
  REQUIRE(r.comp.CommandAborted);
  REQUIRE_FALSE(r.comp.Busy);
  REQUIRE_FALSE(r.comp.Active);
  REQUIRE_FALSE(r.comp.Error);
  REQUIRE(r.move.Active);
}

TEST_CASE("a second compensation while one runs shows the NC's Error 0x4245",
          "[fb][superimposed]") {
  Rig r;
  fb::MC_MoveSuperImposed second;
  second.Distance = 100.0;
  r.call(true);
  r.nc.cycle();
  second.Execute = true;
  second(r.axis);
  r.nc.cycle();
  second(r.axis);
  r.call(true);
  REQUIRE(second.Error);
  REQUIRE(second.ErrorID == 0x4245);
  REQUIRE(r.comp.Active);
}

TEST_CASE(
    "ActualDistance, ActualLength and ActualVelocityDiff follow the NC image while the "
    "compensation runs and stay after it",
    "[fb][superimposed]") {
  Rig r;
  r.axis.NcToPlc.CompensationDistance = 99.0;  // a previous compensation's value
  r.call(true);
  REQUIRE(r.comp.ActualDistance == 0.0);  // not yet this block's compensation
  r.nc.cycle();
  r.axis.NcToPlc.CompensationDistance = 12.5;
  r.axis.NcToPlc.CompensationLength = 5000.0;
  r.axis.NcToPlc.CompensationVelocityDiff = 300.0;
  r.call(true);
  REQUIRE(r.comp.ActualDistance == 12.5);
  REQUIRE(r.comp.ActualLength == 5000.0);
  REQUIRE(r.comp.ActualVelocityDiff == 300.0);

  r.axis.NcToPlc.CompensationDistance = 250.0;  // published in the cycle it ends
  r.nc.finish();
  r.call(true);
  REQUIRE(r.comp.Done);
  REQUIRE(r.comp.ActualDistance == 250.0);

  r.axis.NcToPlc.CompensationDistance = 0.0;  // the NC moves on; the block keeps the result
  r.axis.NcToPlc.CompensationLength = 0.0;
  r.call(false);
  REQUIRE(r.comp.ActualDistance == 250.0);
  REQUIRE(r.comp.ActualLength == 5000.0);
  r.call(false);
  REQUIRE_FALSE(r.comp.Done);
  REQUIRE(r.comp.ActualDistance == 250.0);
  REQUIRE(r.comp.ActualVelocityDiff == 300.0);

  r.call(true);  // a new start clears them
  REQUIRE(r.comp.Busy);
  REQUIRE(r.comp.ActualDistance == 0.0);
  REQUIRE(r.comp.ActualLength == 0.0);
  REQUIRE(r.comp.ActualVelocityDiff == 0.0);
}

TEST_CASE(
    "Warning 0x4243 (largest feasible D instead of D) shows while Busy and with Done, and "
    "resets with the result",
    "[fb][superimposed]") {
  Rig r;
  r.comp.Distance = 500.0;
  r.comp.VelocityDiff = 500.0;
  r.comp.Length = 2000.0;
  r.axis.NcToPlc.Warning = 0x4243;  // a warning left from before: not this block's
  r.call(true);
  REQUIRE_FALSE(r.comp.Warning);
  r.axis.NcToPlc.Warning = 0;
  r.nc.cycle();
  r.call(true);
  REQUIRE_FALSE(r.comp.Warning);
  REQUIRE(r.comp.WarningID == 0);

  r.axis.NcToPlc.Warning = 0x4243;
  r.call(true);
  REQUIRE(r.comp.Warning);
  REQUIRE(r.comp.WarningID == 0x4243);
  REQUIRE(r.comp.Busy);

  r.nc.finish();
  r.call(false);  // result after Execute fell: shown once, with the warning
  REQUIRE(r.comp.Done);
  REQUIRE(r.comp.Warning);
  REQUIRE(r.comp.WarningID == 0x4243);
  r.call(false);
  REQUIRE_FALSE(r.comp.Done);
  REQUIRE_FALSE(r.comp.Warning);
  REQUIRE(r.comp.WarningID == 0);
}

TEST_CASE("other warnings of the axis are not the compensation's", "[fb][superimposed]") {
  Rig r;
  r.call(true);
  r.nc.cycle();
  r.axis.NcToPlc.Warning = 0x4224;  // movement smaller than one increment
  r.call(true);
  REQUIRE(r.comp.Busy);
  REQUIRE_FALSE(r.comp.Warning);
  REQUIRE(r.comp.WarningID == 0);
}

TEST_CASE("an axis error during the compensation ends it with Error and the axis's code",
          "[fb][superimposed]") {
  Rig r;
  r.call(true);
  r.nc.cycle();
  r.call(true);
  r.nc.fail(plc::ErrorCode::kFollowingErrorPosition);
  r.call(true);
  REQUIRE(r.comp.Error);
  REQUIRE(r.comp.ErrorID == 0x4550);
  REQUIRE(r.move.Error);
  REQUIRE(r.move.ErrorID == 0x4550);
}
