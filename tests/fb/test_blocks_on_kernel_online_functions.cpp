// The blocks of issue 4 on the real kernel, seen from the PLC: which block shows what while an
// online function acts (seed 000 §2.2–§2.4). MC_NewPos / MC_NewPosAndVelo are Done once the NC
// has taken the change over, and the positioning's own block shows Done at the new end; a stop
// holding the axis refuses new end positions (0x4242) and goes on; override 0 % keeps the move
// Busy and Active at rest; MC_MoveModulo ends Done on the modulo target.
#include <catch2/catch.hpp>

#include <cstdint>
#include <functional>

#include "fb/fb.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"

namespace {

constexpr double kCycle = 0.001;  // s

// One axis with the seed's dynamics (A± 5000 mm/s², J 50000 mm/s³), enabled by MC_Power in the
// PLC task (every NC cycle) before `program` runs.
struct Bench {
  nc::Kernel kernel{nc::KernelConfig{kCycle}};
  plc::AXIS_REF& axis;
  nc::CycleDriver driver{kernel};
  fb::MC_Power power;
  std::function<void()> program;

  Bench() : axis(kernel.add_axis(config())) {
    driver.add_task("plc", kCycle, [this] {
      power.Enable = power.Enable_Positive = power.Enable_Negative = true;
      power(axis);
      if (program) program();
    });
  }
  static nc::AxisConfig config() {
    nc::AxisConfig c;
    c.name = "X";
    return c;
  }
  double time() const { return kernel.time(); }
};

}  // namespace

TEST_CASE(
    "MC_NewPos is Done when the NC takes the new end over; MC_MoveAbsolute shows Done at the new "
    "end position",
    "[fb][kernel][online]") {
  // Seed 000 §2.3: 0 → 3000 mm at V 2000 mm/s, at 1.7 s (braking) the new end 5000 mm.
  Bench b;
  fb::MC_MoveAbsolute move;
  fb::MC_NewPos change;
  move.Position = 3000.0;
  move.Velocity = 2000.0;
  change.NewPos = 5000.0;
  double change_done_at = -1.0;
  double move_done_at = -1.0;
  bool move_left = false;  // the move showed anything but Busy/Active before its Done
  b.program = [&] {
    move.Execute = b.power.Status;
    move(b.axis);
    change.Execute = b.time() >= 1.7;
    change(b.axis);
    REQUIRE_FALSE(change.Error);
    REQUIRE_FALSE(move.Error);
    REQUIRE_FALSE(move.CommandAborted);
    REQUIRE_FALSE(change.CommandAborted);
    if (change.Done && change_done_at < 0.0) change_done_at = b.time();
    if (move.Done && move_done_at < 0.0) move_done_at = b.time();
    if (b.time() > 0.01 && move_done_at < 0.0 && !(move.Busy && move.Active)) move_left = true;
  };
  REQUIRE(b.driver.run_until([&] { return move.Done; }, 6.0));
  REQUIRE_FALSE(move_left);
  REQUIRE(change_done_at > 1.7 - 1e-9);
  REQUIRE(change_done_at < 1.7 + 0.0025);  // answered in the cycle that took it
  REQUIRE(move_done_at > 2.0);             // the old end (3000 mm) was due at 2.0 s
  REQUIRE(b.axis.NcToPlc.SetPos == 5000.0);
  REQUIRE(b.axis.NcToPlc.CmdNo == move.command_number());
}

TEST_CASE(
    "MC_NewPosAndVelo is Done when taken over; the move ends Done at EPos with VNew from APos on",
    "[fb][kernel][online]") {
  // Seed 000 §2.4 case 1: at 0.75 s (about 1000 mm, 2000 mm/s) APos 2000, EPos 4000, VNew 1000.
  Bench b;
  fb::MC_MoveAbsolute move;
  fb::MC_NewPosAndVelo change;
  move.Position = 3000.0;
  move.Velocity = 2000.0;
  change.NewPos = 4000.0;
  change.NewVelo = 1000.0;
  change.ActivationPos = 2000.0;
  double velocity_at_apos = -1.0;
  double velocity_late = -1.0;
  b.program = [&] {
    move.Execute = b.power.Status;
    move(b.axis);
    change.Execute = b.time() >= 0.75;
    change(b.axis);
    REQUIRE_FALSE(change.Error);
    REQUIRE_FALSE(move.Error);
    REQUIRE_FALSE(move.CommandAborted);
    if (velocity_at_apos < 0.0 && b.axis.NcToPlc.SetPos >= 2000.0) {
      velocity_at_apos = b.axis.NcToPlc.SetVelo;
    }
    if (b.axis.NcToPlc.SetPos < 3500.0) velocity_late = b.axis.NcToPlc.SetVelo;
  };
  REQUIRE(b.driver.run_until([&] { return move.Done; }, 6.0));
  REQUIRE(b.axis.NcToPlc.SetPos == 4000.0);
  REQUIRE(velocity_at_apos == Approx(2000.0).margin(1e-6));  // VOld up to APos
  REQUIRE(velocity_late == Approx(1000.0).margin(1e-6));     // VNew after it
}

TEST_CASE(
    "while MC_Stop holds the axis MC_NewPos and MC_NewPosAndVelo are refused with 0x4242 and "
    "the stop goes on to standstill",
    "[fb][kernel][online]") {
  Bench b;
  fb::MC_MoveAbsolute move;
  fb::MC_Stop stop;
  fb::MC_NewPos new_pos;
  fb::MC_NewPosAndVelo npv;
  move.Position = 5000.0;
  move.Velocity = 2000.0;
  new_pos.NewPos = 4000.0;
  npv.NewPos = 4000.0;
  npv.NewVelo = 500.0;
  npv.ActivationPos = 3000.0;
  double stop_from = -1.0;
  b.program = [&] {
    move.Execute = b.power.Status;
    move(b.axis);
    stop.Execute = b.time() >= 1.0;
    stop(b.axis);
    if (stop.Busy && stop_from < 0.0) stop_from = b.axis.NcToPlc.SetPos;
    new_pos.Execute = b.time() >= 1.1;  // braking
    new_pos(b.axis);
    npv.Execute = b.time() >= 1.2;
    npv(b.axis);
  };
  REQUIRE(b.driver.run_until([&] { return stop.Done; }, 4.0));
  b.driver.run_for(0.05);
  REQUIRE(new_pos.Error);
  REQUIRE(new_pos.ErrorID == 0x4242);
  REQUIRE(npv.Error);
  REQUIRE(npv.ErrorID == 0x4242);
  REQUIRE(move.CommandAborted);
  // The running 5000 mm/s² / 50000 mm/s³ stop from 2000 mm/s: 500 mm (one cycle of slack).
  REQUIRE(b.axis.NcToPlc.SetPos - stop_from == Approx(500.0).margin(2.5));
  REQUIRE(b.axis.NcToPlc.SetVelo == 0.0);
}

TEST_CASE("at override 0 % the move rests on its path, Busy and Active, and ends Done at 100 %",
          "[fb][kernel][online]") {
  Bench b;
  fb::MC_MoveAbsolute move;
  fb::MC_SetOverride set;
  move.Position = 5000.0;
  move.Velocity = 2000.0;
  double rest_pos = -1.0;
  b.program = [&] {
    set.Enable = true;
    set.VelFactor = b.time() >= 1.0 && b.time() < 2.0 ? 0.0 : 1.0;
    set(b.axis);
    REQUIRE(set.Enabled);
    move.Execute = b.power.Status;
    move(b.axis);
    REQUIRE_FALSE(move.Error);
    if (b.time() > 1.9 && b.time() < 2.0) {
      REQUIRE(move.Busy);
      REQUIRE(move.Active);
      REQUIRE(b.axis.NcToPlc.SetVelo == 0.0);
      if (rest_pos < 0.0) rest_pos = b.axis.NcToPlc.SetPos;
      REQUIRE(b.axis.NcToPlc.SetPos == rest_pos);
    }
  };
  REQUIRE(b.driver.run_until([&] { return move.Done; }, 8.0));
  REQUIRE(rest_pos > 1500.0);
  REQUIRE(rest_pos < 5000.0);
  REQUIRE(b.axis.NcToPlc.SetPos == 5000.0);
}

TEST_CASE("MC_MoveModulo 540 from 0 with factor 360 travels 540 and ends Done at modulo 180",
          "[fb][kernel][online]") {
  Bench b;
  fb::MC_MoveModulo move;
  move.Position = 540.0;
  move.Velocity = 720.0;
  move.Direction = fb::MC_Positive_Direction;
  double min_velocity = 0.0;
  b.program = [&] {
    move.Execute = b.power.Status;
    move(b.axis);
    REQUIRE_FALSE(move.Error);
    if (b.axis.NcToPlc.SetVelo < min_velocity) min_velocity = b.axis.NcToPlc.SetVelo;
  };
  REQUIRE(b.driver.run_until([&] { return move.Done; }, 4.0));
  REQUIRE(b.axis.NcToPlc.SetPos == 540.0);
  REQUIRE(b.axis.NcToPlc.ModuloSetPos == Approx(180.0).margin(1e-9));
  REQUIRE(min_velocity == 0.0);
}
