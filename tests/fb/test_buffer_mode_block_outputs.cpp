// BufferMode through the blocks on the real kernel (issue 14): the outputs of both blocks at every
// call — the buffered block Busy but not Active while it waits, the first block Done in the same
// call in which the buffered one becomes Active; a third buffered command while one waits is
// refused (0x4F60) and the waiting one still runs to its end; MC_Stop and an aborting MC_Halt
// drop the waiting command (CommandAborted); MoveRelative and MoveModulo count from the first
// target; MC_Halt buffered behind MC_MoveVelocity starts once InVelocity.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "fb/fb.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"

namespace {

// PLCopen: Busy, Done, Error and CommandAborted exclusive, Active only with Busy, ErrorID with
// Error — checked after every call.
template <class Block>
void check_rules(const Block& b) {
  bool done = false;
  if constexpr (requires { b.Done; }) done = b.Done;
  REQUIRE(int{b.Busy} + int{done} + int{b.Error} + int{b.CommandAborted} <= 1);
  if (b.Active) REQUIRE(b.Busy);
  REQUIRE(b.Error == (b.ErrorID != 0));
}

struct Rig {
  nc::Kernel kernel;
  plc::AXIS_REF* axis = nullptr;
  fb::MC_Power power;
  fb::MC_MoveAbsolute first;
  fb::MC_MoveAbsolute second;
  fb::MC_MoveRelative third;
  fb::MC_Stop stop;
  fb::MC_Halt halt;
  std::function<void()> each_call;  // checks after every PLC cycle's calls

  Rig() {
    nc::AxisConfig c;
    c.name = "X";
    c.max_velocity = c.ref_velocity = 2200.0;
    c.acceleration = c.deceleration = 5000.0;
    c.jerk = 50000.0;
    axis = &kernel.add_axis(c);
    first.Position = 1000.0;
    first.Velocity = 1000.0;
    second.Position = 2000.0;
    second.Velocity = 2000.0;
    third.Distance = 100.0;
    third.Velocity = 500.0;
    third.BufferMode = fb::MC_Buffered;
  }
  // One PLC cycle (the blocks in this order), then one NC cycle.
  void plc_cycle() {
    power.Enable = power.Enable_Positive = power.Enable_Negative = true;
    power(*axis);
    first(*axis);
    second(*axis);
    third(*axis);
    stop(*axis);
    halt(*axis);
    check_rules(first);
    check_rules(second);
    check_rules(third);
    check_rules(stop);
    check_rules(halt);
    if (each_call) each_call();
    kernel.cycle();
  }
  bool run_until(const std::function<bool()>& done, int limit = 10000) {
    for (int i = 0; i < limit; ++i) {
      plc_cycle();
      if (done()) return true;
    }
    return false;
  }
};

}  // namespace

TEST_CASE("a buffered MC_MoveAbsolute is Busy, not Active, until the first is Done",
          "[fb][buffer]") {
  const fb::MC_BufferMode mode =
      GENERATE(fb::MC_Buffered, fb::MC_BlendingLow, fb::MC_BlendingPrevious, fb::MC_BlendingNext,
               fb::MC_BlendingHigh);
  INFO("BufferMode " << static_cast<int>(mode));
  Rig r;
  r.plc_cycle();  // MC_Power on
  r.second.BufferMode = mode;
  r.first.Execute = true;
  r.second.Execute = true;  // posted in the same PLC cycle, behind the first
  bool took_over = false;
  r.each_call = [&] {
    if (r.first.Busy) {
      // The first runs: the second waits.
      REQUIRE(r.second.Busy);
      REQUIRE_FALSE(r.second.Active);
      REQUIRE_FALSE(r.second.Done);
    }
    if (r.second.Active && !took_over) {
      took_over = true;
      REQUIRE(r.first.Done);  // in the same call
      REQUIRE_FALSE(r.first.Busy);
    }
    if (took_over) REQUIRE_FALSE(r.first.Active);
  };
  r.plc_cycle();  // posted
  r.plc_cycle();  // answered: first Active, second buffered
  REQUIRE(r.first.Active);
  REQUIRE(r.second.Busy);
  REQUIRE_FALSE(r.second.Active);
  REQUIRE(r.run_until([&] { return r.second.Done; }));
  REQUIRE(took_over);
  REQUIRE(r.first.Done);  // Execute still high: the result stays
  REQUIRE(r.axis->NcToPlc.SetPos == 2000.0);
}

TEST_CASE("a third buffered command while one waits gives Error 0x4F60; the waiting one runs",
          "[fb][buffer]") {
  Rig r;
  r.plc_cycle();
  r.second.BufferMode = fb::MC_BlendingNext;
  r.first.Execute = r.second.Execute = true;
  r.plc_cycle();
  r.plc_cycle();
  REQUIRE(r.second.Busy);
  REQUIRE_FALSE(r.second.Active);
  r.third.Execute = true;
  REQUIRE(r.run_until([&] { return r.third.Error; }, 5));
  REQUIRE(r.third.ErrorID == 0x4F60);
  REQUIRE(r.first.Active);  // nothing else changed
  REQUIRE(r.second.Busy);
  REQUIRE_FALSE(r.second.Active);
  REQUIRE(r.run_until([&] { return r.second.Done; }));
  REQUIRE(r.axis->NcToPlc.SetPos == 2000.0);
  REQUIRE(r.third.Error);  // its Execute is still high: the error stays shown
}

TEST_CASE("MC_Stop and an aborting MC_Halt drop the waiting command (CommandAborted)",
          "[fb][buffer]") {
  const bool use_stop = GENERATE(true, false);
  INFO((use_stop ? "MC_Stop" : "MC_Halt"));
  Rig r;
  r.plc_cycle();
  r.second.BufferMode = fb::MC_Buffered;
  r.first.Execute = r.second.Execute = true;
  r.run_until([&] { return r.axis->NcToPlc.SetPos > 200.0; });
  REQUIRE(r.second.Busy);
  (use_stop ? r.stop.Execute : r.halt.Execute) = true;
  REQUIRE(r.run_until([&] { return r.second.CommandAborted; }, 3));
  REQUIRE(r.first.CommandAborted);
  REQUIRE(r.run_until([&] { return use_stop ? r.stop.Done : r.halt.Done; }));
  REQUIRE(r.axis->NcToPlc.SetVelo == 0.0);
  const double stopped = r.axis->NcToPlc.SetPos;
  REQUIRE(stopped < 1000.0);
  for (int i = 0; i < 200; ++i)
    r.plc_cycle();
  REQUIRE(r.axis->NcToPlc.SetPos == stopped);  // the dropped command never starts
  REQUIRE(r.second.CommandAborted);
}

namespace {

// Starts the rig's first move and `block` buffered behind it in the same PLC cycle; runs until
// `block` is Done (its outputs checked at every call, never Active while the first is Busy) and
// returns the set position there.
template <class Block>
double run_behind_first(Block& block) {
  Rig r;
  r.plc_cycle();
  r.first.Execute = true;
  block.Execute = true;
  r.each_call = [&] {
    block(*r.axis);
    check_rules(block);
    if (r.first.Busy) REQUIRE_FALSE(block.Active);
  };
  REQUIRE(r.run_until([&] { return block.Done; }));
  return r.axis->NcToPlc.SetPos;
}

}  // namespace

TEST_CASE("buffered MC_MoveRelative and MC_MoveModulo count from the first command's target",
          "[fb][buffer]") {
  SECTION("MoveRelative 500, MC_BlendingPrevious, ends at 1500") {
    fb::MC_MoveRelative rel;
    rel.Distance = 500.0;
    rel.Velocity = 2000.0;
    rel.BufferMode = fb::MC_BlendingPrevious;
    REQUIRE(run_behind_first(rel) == 1500.0);
  }
  SECTION("MoveModulo 200 positive, MC_BlendingNext, ends at 1280") {
    fb::MC_MoveModulo modulo;  // modulo factor 360: 1000 is 280, the next 200 ahead is 1280
    modulo.Position = 200.0;
    modulo.Velocity = 800.0;
    modulo.Direction = fb::MC_Positive_Direction;
    modulo.BufferMode = fb::MC_BlendingNext;
    REQUIRE(run_behind_first(modulo) == 1280.0);
  }
}

TEST_CASE("MC_Halt buffered behind MC_MoveVelocity starts once InVelocity", "[fb][buffer]") {
  Rig r;
  r.plc_cycle();
  fb::MC_MoveVelocity jog;
  jog.Velocity = 600.0;
  jog.Direction = fb::MC_Positive_Direction;
  jog.Execute = true;
  r.halt.BufferMode = fb::MC_Buffered;
  bool in_velocity_seen = false;
  r.each_call = [&] {
    jog(*r.axis);
    check_rules(jog);
    if (jog.InVelocity) in_velocity_seen = true;
    if (!in_velocity_seen && r.halt.Busy) REQUIRE_FALSE(r.halt.Active);
  };
  r.plc_cycle();  // the jog is posted first
  r.halt.Execute = true;
  REQUIRE(r.run_until([&] { return r.halt.Done; }));
  REQUIRE(in_velocity_seen);
  REQUIRE(jog.CommandAborted);
  REQUIRE(r.axis->NcToPlc.SetVelo == 0.0);
}
