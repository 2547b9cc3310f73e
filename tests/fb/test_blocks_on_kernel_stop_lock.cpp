// MC_Stop on the real kernel: the axis brakes to standstill, Done; while its Execute stays high
// every motion command is refused with 0x42EF and StateDWord bit 29 is set; Execute low → the
// release is posted once and the next move is accepted (Tc2_MC2 MC_Stop; brief, command
// semantics). MC_MoveVelocity shows InVelocity on the same kernel.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>

#include "fb/fb.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"

namespace {

bool locked(const plc::AXIS_REF& axis) {
  return plc::test_bit(axis.NcToPlc.StateDWord, plc::kStateMotionCommandsLocked);
}

}  // namespace

TEST_CASE(
    "MC_Stop on the kernel: Done at standstill, locked while Execute is high, released "
    "once when it falls",
    "[fb][kernel][stop]") {
  nc::Kernel kernel;
  nc::AxisConfig config;
  config.name = "X";
  plc::AXIS_REF& axis = kernel.add_axis(config);
  nc::CycleDriver driver(kernel);

  fb::MC_Power power;
  fb::MC_MoveVelocity jog;
  fb::MC_Stop stop;
  fb::MC_MoveAbsolute move;
  jog.Velocity = 1'000.0;
  move.Position = 0.0;
  move.Velocity = 500.0;
  bool stop_execute = false;
  bool move_execute = false;
  driver.add_task("plc", kernel.cycle_time(), [&] {
    power.Enable = power.Enable_Positive = power.Enable_Negative = true;
    power(axis);
    jog.Execute = power.Status;
    jog(axis);
    stop.Execute = stop_execute;
    stop(axis);
    move.Execute = move_execute;
    move(axis);
  });

  REQUIRE(driver.run_until([&] { return jog.InVelocity; }, 2.0));
  REQUIRE(jog.Busy);
  REQUIRE(jog.Active);
  REQUIRE(axis.NcToPlc.SetVelo == Approx(1'000.0));

  stop_execute = true;
  REQUIRE(driver.run_until([&] { return stop.Done; }, 2.0));
  REQUIRE(jog.CommandAborted);  // jog's Execute is still high: the abort stays shown
  REQUIRE(std::abs(axis.NcToPlc.SetVelo) == 0.0);
  REQUIRE(locked(axis));
  REQUIRE(axis.NcToPlc.AxisState == static_cast<uint32_t>(plc::AxisState::kStopping));

  // Locked while Execute stays high: a move is refused, nothing moves.
  const double stopped_at = axis.NcToPlc.SetPos;
  move_execute = true;
  driver.run_for(0.05);
  REQUIRE(move.Error);
  REQUIRE(move.ErrorID == 0x42EF);
  REQUIRE(stop.Done);
  REQUIRE_FALSE(stop.Busy);
  REQUIRE(locked(axis));
  REQUIRE(axis.NcToPlc.SetPos == stopped_at);

  // Execute low: released; the next rising edge of the move is accepted and reaches 0.
  stop_execute = false;
  move_execute = false;
  driver.run_for(0.002);
  REQUIRE_FALSE(locked(axis));
  REQUIRE_FALSE(stop.Done);
  move_execute = true;
  REQUIRE(driver.run_until([&] { return move.Done; }, 10.0));
  REQUIRE(axis.NcToPlc.SetPos == 0.0);
  REQUIRE_FALSE(move.Error);
}
