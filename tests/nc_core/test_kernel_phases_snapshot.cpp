// The kernel's cycle in phases (issue 8 item 1 and 4): each axis's snapshot carries the set and
// actual values it published, its error and the error event of the cycle it was raised in, and
// its enables; a steady cycle never recomputes the coupling order.
#include <catch2/catch.hpp>

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
