// The kernel's cycle in phases (issue 8 item 1 and 4): each axis's snapshot carries the set and
// actual values it published, its error and the error event of the cycle it was raised in, and
// its enables; a steady cycle never recomputes the coupling order. Between cycles the snapshot
// shows the axis as the cycle left it, with or without couplings (docs/performance.md "Fifth
// pass": a cycle in which no axis reads another leaves the snapshots to Kernel::snapshot()).
#include <catch2/catch.hpp>

#include "gear_rig.hpp"
#include "kernel_harness.hpp"

TEST_CASE("the snapshot of an axis shows what its NcToPlc shows after the cycle",
          "[kernel][snapshot]") {
  nc::Kernel kernel;
  plc::AXIS_REF& a = kernel.add_axis(kt::seed_axis("a"));
  plc::AXIS_REF& b = kernel.add_axis(kt::seed_axis("b"));
  kt::set_enables(a, true);
  kt::set_enables(b, true);
  REQUIRE(kernel.couplings().axis_count() == 2);
  REQUIRE(a.Mailbox.post(kt::move_absolute(100.0, 1000.0)) != 0);
  for (int i = 0; i < 50; ++i) {
    kernel.cycle();
    const nc::AxisSnapshot& s = kernel.snapshot(0);
    REQUIRE(s.set_position == a.NcToPlc.SetPos);
    REQUIRE(s.set_velocity == a.NcToPlc.SetVelo);
    REQUIRE(s.set_acceleration == a.NcToPlc.SetAcc);
    REQUIRE(s.actual_position == a.NcToPlc.ActPos);
    REQUIRE(s.actual_velocity == a.NcToPlc.ActVelo);
    REQUIRE(s.controller_enabled);
    REQUIRE(s.feed_enabled_plus);
    REQUIRE(s.feed_enabled_minus);
    REQUIRE(s.error == plc::ErrorCode::kNone);
  }
  REQUIRE(kernel.snapshot(0).set_velocity > 0.0);
  REQUIRE(kernel.snapshot(1).set_velocity == 0.0);
  REQUIRE(kernel.couplings().revision() == 0);
}

TEST_CASE("the error event is set only in the cycle the error is raised", "[kernel][snapshot]") {
  nc::Kernel kernel;
  plc::AXIS_REF& a = kernel.add_axis(kt::seed_axis("a"));
  kt::set_enables(a, true);
  REQUIRE(a.Mailbox.post(kt::move_absolute(500.0, 1000.0)) != 0);
  for (int i = 0; i < 20; ++i)
    kernel.cycle();
  // The controller enable gone while the job runs: an axis error (0x4260, kControllerEnableLost).
  a.PlcToNc.ControlDWord = 0;
  kernel.cycle();
  REQUIRE(kernel.snapshot(0).error == plc::ErrorCode::kControllerEnableLost);
  REQUIRE(kernel.snapshot(0).error_event);
  REQUIRE_FALSE(kernel.snapshot(0).controller_enabled);
  kernel.cycle();
  REQUIRE(kernel.snapshot(0).error == plc::ErrorCode::kControllerEnableLost);
  REQUIRE_FALSE(kernel.snapshot(0).error_event);
}

namespace {

// Axis `i`'s snapshot shows what its NcToPlc shows after the cycle (no HLI coupling: the set
// values are the drive's), and the enables `enabled` of that cycle.
int differences(const nc::Kernel& kernel, std::size_t i, const plc::AXIS_REF& a, bool enabled) {
  const nc::AxisSnapshot& s = kernel.snapshot(i);
  const plc::NCTOPLC_AXIS_REF& out = a.NcToPlc;
  int n = 0;
  n += s.set_position != out.SetPos;
  n += s.set_velocity != out.SetVelo;
  n += s.set_acceleration != out.SetAcc;
  n += s.set_jerk != out.SetJerk;
  n += s.actual_position != out.ActPos;
  n += s.actual_velocity != out.ActVelo;
  n += s.actual_acceleration != out.ActAcc;
  n += s.target_position != out.TargetPos;
  n += s.target_velocity != out.TargetVelo;
  n += plc::to_id(s.error) != out.ErrorCode;
  n += s.controller_enabled != enabled;
  n += s.feed_enabled_plus != enabled;
  n += s.feed_enabled_minus != enabled;
  return n;
}

}  // namespace

TEST_CASE("between cycles the snapshot shows the axis as the cycle left it, coupled or not",
          "[kernel][snapshot]") {
  gr::Rig rig(3);
  int diff = 0;
  const auto run = [&](int n) {
    for (int k = 0; k < n; ++k) {
      rig.kernel.cycle();
      for (std::size_t i = 0; i < 3; ++i)
        diff += differences(rig.kernel, i, rig.at(i), true);
    }
  };
  // No coupling: A0 moves to 100 mm and ends there (the cycle of its Done included).
  const uint16_t move = rig.post(0, kt::move_absolute(100.0, 1000.0));
  run(1);
  CHECK(rig.kernel.snapshot(0).path_positioning);
  CHECK(rig.kernel.snapshot(0).path_has_target);
  CHECK(rig.kernel.snapshot(0).target_position == 100.0);
  for (int k = 0; k < 2000 && rig.answer(0, move).state != plc::CommandState::kDone; ++k)
    run(1);
  REQUIRE(rig.answer(0, move).state == plc::CommandState::kDone);
  CHECK_FALSE(rig.kernel.snapshot(0).path_running);
  CHECK_FALSE(rig.kernel.snapshot(0).path_positioning);
  CHECK(rig.kernel.snapshot(0).actual_position == rig.at(0).NcToPlc.ActPos);
  // A2 follows A1 at 0.5 (phase by phase); A1 moves.
  REQUIRE(rig.couple(2, 1, 0.5).state == plc::CommandState::kReached);  // InGear
  const uint16_t master_move = rig.post(1, kt::move_absolute(200.0, 1000.0));
  run(100);
  CHECK(rig.kernel.snapshot(1).path_running);
  CHECK(rig.kernel.snapshot(2).target_position == 100.0);  // 0.5 x the master's target
  CHECK(rig.kernel.snapshot(2).set_velocity == 0.5 * rig.kernel.snapshot(1).set_velocity);
  CHECK(rig.kernel.snapshot(2).set_velocity > 0.0);
  for (int k = 0; k < 2000 && rig.answer(1, master_move).state != plc::CommandState::kDone; ++k)
    run(1);
  CHECK(rig.answer(1, master_move).state == plc::CommandState::kDone);
  CHECK(diff == 0);
  // The PLC's writes after a cycle do not change what the cycle left: the enables are that
  // cycle's.
  kt::set_enables(rig.at(0), false, false, false);
  CHECK(rig.kernel.snapshot(0).controller_enabled);
  CHECK(rig.kernel.snapshot(0).feed_enabled_plus);
  rig.kernel.cycle();
  CHECK_FALSE(rig.kernel.snapshot(0).controller_enabled);
  CHECK_FALSE(rig.kernel.snapshot(0).feed_enabled_minus);
}
