// The superposition blocks on the real kernel: MC_MoveSuperImposed runs beside the basic move
// (both Active), reports the distance as it grows and ends Done after T = L / VP with D done;
// MC_AbortSuperposition half-way ends it with CommandAborted, less than D and the warning 0x4243;
// MC_Stop during a compensation ends it too (a stop requests the compensation stop, seed 000
// §2.5); MC_ExtSetPointGenEnable / Disable show Enabled as the NC publishes it (seed 000 §2.6).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>

#include "fb/fb.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"

namespace {

constexpr double kCycle = 0.001;  // s

// One axis moving 0 → 5000 mm at 1000 mm/s (cruising from 0.3 s on) with a compensation block
// configured for D 100 mm over L 1000 mm at VP 1000 mm/s (T = 1 s), VK 200, AK± 1000 mm/s².
struct Rig {
  nc::Kernel kernel{nc::KernelConfig{kCycle}};
  plc::AXIS_REF& axis = kernel.add_axis([] {
    nc::AxisConfig c;
    c.name = "X";
    return c;
  }());
  fb::MC_Power power;
  fb::MC_MoveAbsolute move;
  fb::MC_MoveSuperImposed comp;
  uint64_t ticks = 0;

  Rig() {
    move.Position = 5000.0;
    move.Velocity = 1000.0;
    comp.Distance = 100.0;
    comp.Length = 1000.0;
    comp.VelocityProcess = 1000.0;
    comp.VelocityDiff = 200.0;
    comp.Acceleration = 1000.0;
    comp.Deceleration = 1000.0;
  }
  // One PLC cycle then one NC cycle; `extra` runs after the program's blocks.
  template <class Extra>
  void tick(Extra&& extra) {
    power.Enable = power.Enable_Positive = power.Enable_Negative = true;
    power(axis);
    move.Execute = ticks >= 2;
    move(axis);
    comp(axis);
    extra();
    kernel.cycle();
    ++ticks;
  }
  void tick() {
    tick([] {});
  }
  void run_to(double seconds) {
    while (static_cast<double>(ticks) * kCycle < seconds - 1e-12)
      tick();
  }
};

}  // namespace

TEST_CASE(
    "MC_MoveSuperImposed on the kernel: Active beside the move, ActualDistance grows, Done "
    "after T = L / VP with D done",
    "[fb][kernel][superimposed]") {
  Rig r;
  r.run_to(0.5);
  REQUIRE(r.move.Active);
  r.comp.Execute = true;
  r.tick();  // posted and taken in this tick
  const uint64_t start = r.ticks;
  r.tick();
  REQUIRE(r.comp.Busy);
  REQUIRE(r.comp.Active);
  REQUIRE(r.move.Active);  // the basic move keeps the axis
  REQUIRE(plc::test_bit(r.axis.NcToPlc.StateDWord, plc::kStateCompensating));
  CHECK(r.comp.ActualLength == 1000.0);

  double before = r.comp.ActualDistance;
  while (!r.comp.Done && r.ticks < start + 2000) {
    r.tick();
    REQUIRE_FALSE(r.comp.Error);
    REQUIRE(r.comp.ActualDistance >= before);
    before = r.comp.ActualDistance;
  }
  REQUIRE(r.comp.Done);
  // Ends after T = 1 s (plus the cycle the answer takes to reach the block).
  const double took = static_cast<double>(r.ticks - start) * kCycle;
  CHECK(took >= 1.0 - 1e-9);
  CHECK(took <= 1.0 + 2 * kCycle + 1e-9);
  CHECK(r.comp.ActualDistance == Approx(100.0).margin(1e-9));
  CHECK(r.comp.ActualVelocityDiff > 0.0);
  CHECK(r.comp.ActualVelocityDiff <= 200.0);
  CHECK_FALSE(r.comp.Warning);
  CHECK_FALSE(r.comp.Active);
  CHECK(r.move.Active);

  r.run_to(6.5);
  REQUIRE(r.move.Done);
  CHECK(r.axis.NcToPlc.SetPos == Approx(5100.0).margin(1e-9));
  CHECK(r.comp.Done);  // Execute still high: the result stays
  CHECK(r.comp.ActualDistance == Approx(100.0).margin(1e-9));  // and the value with it
}

TEST_CASE(
    "MC_AbortSuperposition half-way: Done; the compensation ends with CommandAborted, less than "
    "D and the warning 0x4243",
    "[fb][kernel][superimposed]") {
  Rig r;
  fb::MC_AbortSuperposition abort;
  r.run_to(0.5);
  r.comp.Execute = true;
  r.run_to(0.9);  // 0.4 s into the 1 s compensation: before its braking phase
  REQUIRE(r.comp.Active);
  const double at_stop = r.comp.ActualDistance;
  REQUIRE(at_stop > 0.0);
  abort.Execute = true;
  r.tick([&] { abort(r.axis); });
  for (int i = 0; i < 1500 && !r.comp.CommandAborted; ++i) {
    r.tick([&] { abort(r.axis); });
  }
  CHECK(abort.Done);
  REQUIRE(r.comp.CommandAborted);
  CHECK_FALSE(r.comp.Error);
  CHECK(r.comp.ActualDistance > at_stop);  // the extra velocity ramps down first
  CHECK(r.comp.ActualDistance < 100.0);
  CHECK(r.comp.Warning);
  CHECK(r.comp.WarningID == 0x4243);
  CHECK(r.move.Active);  // the basic move goes on

  r.run_to(6.5);
  REQUIRE(r.move.Done);
  CHECK(r.axis.NcToPlc.SetPos == Approx(5000.0 + r.comp.ActualDistance).margin(1e-9));
}

TEST_CASE("MC_Stop during a compensation ends the compensation with CommandAborted",
          "[fb][kernel][superimposed]") {
  Rig r;
  fb::MC_Stop stop;
  r.run_to(0.5);
  r.comp.Execute = true;
  r.run_to(0.8);
  REQUIRE(r.comp.Active);
  stop.Execute = true;
  for (int i = 0; i < 2000 && !stop.Done; ++i) {
    r.tick([&] { stop(r.axis); });
  }
  REQUIRE(stop.Done);
  CHECK(r.comp.CommandAborted);
  CHECK(r.move.CommandAborted);
  CHECK(r.comp.ActualDistance > 0.0);
  CHECK(r.comp.ActualDistance < 100.0);
  CHECK(r.axis.NcToPlc.SetVelo == 0.0);
}

TEST_CASE("MC_ExtSetPointGenEnable / Disable on the kernel: Done at once, Enabled follows bit 14",
          "[fb][kernel][extsetpoint]") {
  nc::Kernel kernel{nc::KernelConfig{kCycle}};
  nc::AxisConfig config;
  config.name = "X";
  plc::AXIS_REF& axis = kernel.add_axis(config);
  fb::MC_Power power;
  fb::MC_ExtSetPointGenEnable enable;
  fb::MC_ExtSetPointGenDisable disable;
  const auto tick = [&] {
    power.Enable = power.Enable_Positive = power.Enable_Negative = true;
    power(axis);
    enable(axis);
    disable(axis);
    kernel.cycle();
  };
  tick();
  tick();
  REQUIRE(power.Status);
  enable.Position = 100.0;
  enable.PositionType = fb::POSITIONTYPE_ABSOLUTE;
  enable.Execute = true;
  tick();  // posted, taken and answered in this NC cycle
  tick();
  CHECK(enable.Done);
  CHECK(enable.Enabled);
  CHECK(disable.Enabled);
  CHECK(axis.NcToPlc.TargetPos == 100.0);

  // Re-enabling with the other start type is refused (seed 000 §2.6): 0x4239.
  fb::MC_ExtSetPointGenEnable relative;
  relative.PositionType = fb::POSITIONTYPE_RELATIVE;
  relative.Execute = true;
  relative(axis);
  kernel.cycle();
  relative(axis);
  CHECK(relative.Error);
  CHECK(relative.ErrorID == 0x4239);
  CHECK(relative.Enabled);

  disable.Execute = true;
  tick();
  tick();
  CHECK(disable.Done);
  CHECK_FALSE(disable.Enabled);
  CHECK_FALSE(enable.Enabled);
}
