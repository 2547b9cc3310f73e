// The NC→PLC image over one positioning (SPEC A7, API.md StateDWord bit numbers): which bits and
// fields are set in the acceleration, cruise and deceleration phases and at rest; and the image
// kept between events equal to its full recomputation after every cycle.
#include <catch2/catch.hpp>

#include <cmath>

#include "gear_rig.hpp"
#include "hli_kernel_rig.hpp"
#include "homing_rig.hpp"
#include "kernel_harness.hpp"
#include "propagation_rig.hpp"

using plc::CommandState;

TEST_CASE("StateDWord and image fields through a 0 → 2000 mm positioning at 2000 mm/s",
          "[kernel][state_word]") {
  // A = 5000, J = 50000: 0.5 s to reach 2000 mm/s over 500 mm, 0.5 s cruise, 0.5 s braking.
  kt::Harness h;
  const uint32_t counter_before = h.x->NcToPlc.CycleCounter;
  CHECK(kt::bit(*h.x, plc::kStateNotMoving));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHasJob));
  const uint16_t job = h.post(kt::move_absolute(2000.0, 2000.0));
  int constant_cycles = 0;
  for (int cycle = 1; cycle <= 1500; ++cycle) {
    h.cycles(1);
    const auto& o = h.x->NcToPlc;
    REQUIRE(o.CycleCounter == counter_before + static_cast<uint32_t>(cycle));
    REQUIRE(kt::bit(*h.x, plc::kStateHasJob));
    REQUIRE(kt::bit(*h.x, plc::kStateOperational));
    REQUIRE_FALSE(kt::bit(*h.x, plc::kStateNegativeDirection));
    REQUIRE(o.TargetPos == 2000.0);
    REQUIRE(o.TargetVelo == 2000.0);
    REQUIRE(o.CoupleState == 0);
    const double m = std::fmod(o.ActPos, 360.0);
    REQUIRE(o.ModuloActPos == Approx(m).margin(1e-9));
    const bool constant = kt::bit(*h.x, plc::kStateConstantVelocity);
    if (constant) ++constant_cycles;
    if (cycle < 500 || (cycle > 1000 && cycle < 1500)) {
      REQUIRE_FALSE(constant);
      REQUIRE_FALSE(kt::bit(*h.x, plc::kStateNotMoving));
      REQUIRE(kt::bit(*h.x, plc::kStatePositiveDirection));
    }
    if (cycle > 500 && cycle < 1000) {
      REQUIRE(constant);
      REQUIRE(o.SetVelo == Approx(2000.0).epsilon(1e-12));
    }
  }
  // The cruise lasts 0.5 s: 499 … 501 samples depending on how the boundaries fall.
  CHECK(constant_cycles >= 499);
  CHECK(constant_cycles <= 501);
  CHECK(h.x->NcToPlc.SetPos == 2000.0);
  CHECK_FALSE(kt::bit(*h.x, plc::kStatePositiveDirection));
  CHECK(kt::bit(*h.x, plc::kStateInPositionArea));
  REQUIRE(h.cycles_until([&] { return h.state_of(job) == CommandState::kDone; }) == 19);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHasJob));
  CHECK(kt::bit(*h.x, plc::kStateInTargetPosition));
  // NotMoving comes from the actual velocity (below standstill_window 1e-3 mm/s).
  CHECK(kt::bit(*h.x, plc::kStateNotMoving));
  CHECK(h.x->NcToPlc.TargetVelo == 0.0);
  CHECK(h.x->NcToPlc.ModuloSetPos == Approx(2000.0 - 5 * 360.0));
  CHECK(h.x->NcToPlc.AxisIndex == 0);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK(h.x->NcToPlc.StateDWord ==
        ((1U << plc::kStateOperational) | (1U << plc::kStateHomed) | (1U << plc::kStateNotMoving) |
         (1U << plc::kStateInPositionArea) | (1U << plc::kStateInTargetPosition) |
         (1U << plc::kStatePtpMode)));
}

// --- The kept image (docs/performance.md "Fourth pass") ---
// The StateDWord bits, AxisState, CoupleState and compensation values that only events change
// are kept between cycles and computed anew only after an event. After every cycle of scenarios
// that pass through each such event, every axis's kept image must equal its full recomputation
// (Kernel::published_image_consistent); an event site that forgets note_event() fails here.

namespace {

// Four seed axes: A0 a master with a software limit at 3000 mm, A1 its DELAYED slave (C7, 20 ms),
// A2 for external setpoints and MC_Stop, A3 not homed for MC_Home.
struct CheckedRig : pr::Group {
  CheckedRig()
      : pr::Group(4, [](std::size_t i, nc::AxisConfig& c) {
          if (i == 0) {
            c.sw_limit_max_enabled = true;
            c.sw_limit_max = 3000.0;
          }
          if (i == 1) pr::delayed(c, 0.02);
          if (i == 3) c.homed_at_start = false;
        }) {}
  int inconsistent = 0;  // axis-cycles whose kept image differed from its recomputation
  void check() {
    for (std::size_t i = 0; i < axes.size(); ++i) {
      if (!kernel.published_image_consistent(i)) ++inconsistent;
    }
  }
  void run(int n) {
    for (int k = 0; k < n; ++k) {
      kernel.cycle();
      check();
    }
  }
  uint16_t act(std::size_t axis, const plc::Command& c, int n) {
    const uint16_t number = post(axis, c);
    run(n);
    return number;
  }
  void home_cycles(int n) {  // MC_Home's PLC side: the cam input of A3 before each cycle
    for (int k = 0; k < n; ++k) {
      at(3).PlcToNc.ControlDWord = plc::with_bit(
          at(3).PlcToNc.ControlDWord, plc::kControlHomingSensor, kernel.reference_cam("A3"));
      kernel.cycle();
      check();
    }
  }
};

}  // namespace

TEST_CASE("The kept image equals its recomputation through every kind of event",
          "[kernel][state_word]") {
  CheckedRig r;
  r.check();
  // Jobs: a positioning to its end, a velocity move to its level, an override change, MC_Halt.
  const uint16_t move = r.act(0, kt::move_absolute(500.0, 2000.0), 800);
  CHECK(r.answer(0, move).state == plc::CommandState::kDone);
  r.act(0, kt::move_velocity(800.0, 1), 400);
  CHECK(r.at(0).NcToPlc.AxisState == static_cast<uint32_t>(plc::AxisState::kContinuousMotion));
  kt::set_override(r.at(0), 50.0);
  r.run(200);
  kt::set_override(r.at(0), 100.0);
  // An override above 100 % is not taken: its warning shows (a change of the channel, not a
  // note_event()) and goes with the next valid one.
  r.at(0).PlcToNc.Override = plc::kOverrideFull + 1;
  r.run(3);
  CHECK(r.at(0).NcToPlc.Warning == kt::id(plc::ErrorCode::kOverrideNotAllowed));
  kt::set_override(r.at(0), 100.0);
  r.run(3);
  CHECK(r.at(0).NcToPlc.Warning == 0);
  r.act(0, kt::simple(plc::CommandType::kHalt), 600);
  CHECK(r.at(0).NcToPlc.AxisState == static_cast<uint32_t>(plc::AxisState::kStandstill));
  // Online functions: a new end position, a new position and velocity at an activation point.
  r.act(0, kt::move_absolute(1500.0, 1000.0), 100);
  r.act(0, kt::new_pos(1200.0), 50);
  r.act(0, kt::new_pos_and_velo(400.0, 500.0, 1100.0), 3000);
  // A compensation on a moving axis, to its end.
  r.act(0, kt::move_absolute(2500.0, 1000.0), 50);
  r.act(0, kt::move_superimposed(20.0, 200.0, 2000.0, 2000.0, 1000.0, 500.0), 3000);
  CHECK_FALSE(kt::bit(r.at(0), plc::kStateCompensating));
  // MC_Stop on A2 while it moves (locked), MC_Stop's release, then a move again.
  r.act(2, kt::move_velocity(500.0, 1), 200);
  r.act(2, kt::simple(plc::CommandType::kStop), 400);
  CHECK(kt::bit(r.at(2), plc::kStateMotionCommandsLocked));
  r.act(2, kt::simple(plc::CommandType::kStopRelease), 5);
  CHECK_FALSE(kt::bit(r.at(2), plc::kStateMotionCommandsLocked));
  // External setpoints on A2: relative, fed for a while, then disabled; absolute, fed, disabled.
  r.act(2, kt::ext_enable(0.0, 2), 3);
  CHECK(kt::bit(r.at(2), plc::kStateExtSetPointGenEnabled));
  for (int k = 0; k < 100; ++k) {
    kt::feed(r.at(2), 0.1 * k, 100.0, 0.0, 1);
    r.run(1);
  }
  kt::feed(r.at(2), 10.0, 0.0, 0.0, 0);
  r.act(2, kt::simple(plc::CommandType::kExtSetPointGenDisable), 20);
  CHECK_FALSE(kt::bit(r.at(2), plc::kStateExtSetPointGenEnabled));
  r.act(2, kt::ext_enable(r.at(2).NcToPlc.SetPos, 1), 3);
  for (int k = 0; k < 100; ++k) {
    kt::feed(r.at(2), r.at(2).NcToPlc.SetPos + 0.05, 50.0, 0.0, 1);
    r.run(1);
  }
  kt::feed(r.at(2), r.at(2).NcToPlc.SetPos, 0.0, 0.0, 0);
  r.act(2, kt::simple(plc::CommandType::kExtSetPointGenDisable), 20);
  // Homing A3 (not homed at start) with MC_Home's default sequence.
  CHECK_FALSE(kt::bit(r.at(3), plc::kStateHomed));
  r.post(3, kt::home(plc::MC_DefaultHoming));
  r.home_cycles(6000);
  CHECK(kt::bit(r.at(3), plc::kStateHomed));
  // Couplings, each with a master before and after its slave in the axes' order (a master
  // whose commands phase runs first and one whose runs last in the cycle the link changes): A1
  // follows the master, which moves; the slave loses its feed enable while moving (its error,
  // DELAYED: bit 6, then the group reaction on the master); reset both; MC_GearOut of the slave
  // that left on its error. Then A2 follows A3 and is decoupled at rest.
  for (const std::size_t master : {std::size_t{0}, std::size_t{3}}) {
    r.act(1, gr::gear_in(master, 1.0), 2);
    CHECK(r.at(1).NcToPlc.CoupleState == static_cast<uint32_t>(plc::CoupleState::kSlave));
    CHECK(r.at(master).NcToPlc.CoupleState == static_cast<uint32_t>(plc::CoupleState::kMaster));
    r.act(master, kt::move_relative(-400.0, 1000.0), 300);
    kt::set_enables(r.at(1), true, true, false);
    r.run(200);
    CHECK(r.at(1).NcToPlc.ErrorCode != 0);
    CHECK(r.at(master).NcToPlc.ErrorCode != 0);
    kt::set_enables(r.at(1), true);
    r.act(master, kt::simple(plc::CommandType::kReset), 2);
    r.act(1, kt::simple(plc::CommandType::kReset), 2);
    r.act(1, gr::gear_out(), 5);
    CHECK(r.at(master).NcToPlc.CoupleState == static_cast<uint32_t>(plc::CoupleState::kSingle));
  }
  r.run(1000);  // both at rest (MC_GearIn's precondition)
  r.act(2, gr::gear_in(3, 1.0), 2);
  CHECK(r.at(3).NcToPlc.CoupleState == static_cast<uint32_t>(plc::CoupleState::kMaster));
  r.act(2, gr::gear_out(), 2);
  CHECK(r.at(3).NcToPlc.CoupleState == static_cast<uint32_t>(plc::CoupleState::kSingle));
  // A buffered move behind a running one (the waiting command takes over in phase a).
  r.post(0, kt::move_absolute(600.0, 1000.0));
  r.run(10);
  plc::Command buffered = kt::move_absolute(100.0, 1000.0);
  buffered.buffer_mode = plc::MC_Buffered;
  const uint16_t next = r.act(0, buffered, 3000);
  CHECK(r.answer(0, next).state == plc::CommandState::kDone);
  // Errors: the software limit during motion, reset; the controller enable lost while moving,
  // back, reset.
  r.act(0, kt::move_velocity(2000.0, 1), 3000);
  CHECK(r.at(0).NcToPlc.ErrorCode == kt::id(plc::ErrorCode::kSoftLimitMaxDuringMotion));
  r.act(0, kt::simple(plc::CommandType::kReset), 2);
  r.act(0, kt::move_absolute(0.0, 2000.0), 100);
  kt::set_enables(r.at(0), false);
  r.run(50);
  CHECK(r.at(0).NcToPlc.AxisState == static_cast<uint32_t>(plc::AxisState::kErrorStop));
  kt::set_enables(r.at(0), true);
  r.act(0, kt::simple(plc::CommandType::kReset), 50);
  CHECK(r.at(0).NcToPlc.AxisState == static_cast<uint32_t>(plc::AxisState::kStandstill));
  // The controller enable taken and given back at rest (its edges are events: Operational,
  // AxisState).
  kt::set_enables(r.at(2), false);
  r.run(3);
  CHECK(r.at(2).NcToPlc.AxisState == static_cast<uint32_t>(plc::AxisState::kDisabled));
  CHECK_FALSE(kt::bit(r.at(2), plc::kStateOperational));
  kt::set_enables(r.at(2), true);
  r.run(3);
  CHECK(r.at(2).NcToPlc.AxisState == static_cast<uint32_t>(plc::AxisState::kStandstill));
  CHECK(kt::bit(r.at(2), plc::kStateOperational));
  CHECK(r.inconsistent == 0);
}

TEST_CASE("The kept image equals its recomputation through an HLI coupling",
          "[kernel][state_word][hli]") {
  hlik::Rig r({hlik::axis(1, "X1"), hlik::axis(8, "Y2")});
  int inconsistent = 0;
  const auto ticks = [&](int n) {
    for (int k = 0; k < n; ++k) {
      r.tick();
      for (std::size_t i = 0; i < r.axes.size(); ++i) {
        if (!r.kernel.published_image_consistent(i)) ++inconsistent;
      }
    }
  };
  REQUIRE(r.couple(1, {{1, hlik::h::HLI_AXIS_COUPLING_DIRECT, 0, 0},
                       {8, hlik::h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  ticks(2);
  CHECK(r.axes[1]->NcToPlc.CoupleState == static_cast<uint32_t>(plc::CoupleState::kSlave));
  CHECK(r.axes[0]->NcToPlc.CoupleState == static_cast<uint32_t>(plc::CoupleState::kMaster));
  r.start_move(0, 900.0);
  ticks(1500);
  REQUIRE(r.couple(1, {}));
  ticks(5);
  CHECK(r.axes[0]->NcToPlc.CoupleState == static_cast<uint32_t>(plc::CoupleState::kSingle));
  CHECK(inconsistent == 0);
}
