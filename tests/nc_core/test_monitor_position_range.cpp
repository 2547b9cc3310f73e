// Position range window (SPEC A4): InPositionArea while |actual - target| <= window after the end
// of set-value generation (TwinCAT checks it only once the positioning phase is over).
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

TEST_CASE(
    "InPositionArea is set at the end of set-value generation, not before, even when "
    "the actual position is already in the range",
    "[monitor][position_range]") {
  kt::Harness h;  // ideal drive, range window 5 mm
  h.post(kt::move_absolute(1000.0, 2000.0));
  for (int cycle = 1; cycle < 1000; ++cycle) {
    h.cycles(1);
    REQUIRE_FALSE(kt::bit(*h.x, plc::kStateInPositionArea));
  }
  // In cycle 999 the actual position was already within 5 mm of the target.
  CHECK(std::abs(h.x->NcToPlc.ActPos - 1000.0) < 5.0);
  h.cycles(1);
  CHECK(h.x->NcToPlc.SetPos == 1000.0);
  CHECK(kt::bit(*h.x, plc::kStateInPositionArea));
}

TEST_CASE(
    "with a lagging drive InPositionArea follows |actual - target| <= 5 mm after the end "
    "of generation, before the 2 mm target window",
    "[monitor][position_range]") {
  nc::AxisConfig c = kt::seed_axis();
  c.drive_model = nc::DriveModel::kFirstOrderLag;
  c.drive_time_constant = 0.05;
  // Pure P control, critically damped (Kv·tau = 0.25): the actual position approaches the
  // target from behind without overshoot.
  c.velocity_feed_forward = 0.0;
  c.position_kv = 5.0;
  c.following_error_limit = 1000.0;
  c.position_range_window = 5.0;
  c.target_window = 2.0;
  kt::Harness h(c);
  h.post(kt::move_absolute(1000.0, 2000.0));
  h.cycles(1000);
  REQUIRE(h.x->NcToPlc.SetPos == 1000.0);
  int in_area = -1;
  int in_target = -1;
  for (int cycle = 1; cycle <= 5000 && in_target < 0; ++cycle) {
    h.cycles(1);
    const double distance = std::abs(h.x->NcToPlc.ActPos - 1000.0);
    REQUIRE(kt::bit(*h.x, plc::kStateInPositionArea) == (distance <= 5.0));
    if (in_area < 0 && kt::bit(*h.x, plc::kStateInPositionArea)) in_area = cycle;
    if (in_target < 0 && kt::bit(*h.x, plc::kStateInTargetPosition)) in_target = cycle;
  }
  REQUIRE(in_area > 0);
  REQUIRE(in_target > 0);
  CHECK(in_area < in_target);
}

TEST_CASE("with the position range switched off InPositionArea is set at the end of generation",
          "[monitor][position_range]") {
  nc::AxisConfig c = kt::seed_axis();
  c.drive_model = nc::DriveModel::kFirstOrderLag;
  c.drive_time_constant = 0.05;
  // Pure P control, critically damped (Kv·tau = 0.25): the actual position approaches the
  // target from behind without overshoot.
  c.velocity_feed_forward = 0.0;
  c.position_kv = 5.0;
  c.following_error_limit = 1000.0;
  c.position_range_enabled = false;
  kt::Harness h(c);
  h.post(kt::move_absolute(1000.0, 2000.0));
  h.cycles(999);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateInPositionArea));
  h.cycles(1);
  CHECK(std::abs(h.x->NcToPlc.ActPos - 1000.0) > 5.0);
  CHECK(kt::bit(*h.x, plc::kStateInPositionArea));
}
