// Target position window (SPEC A4): InTargetPosition once the actual position has stayed within
// the window for the window time after the end of set-value generation; a positioning is
// answered kDone in that cycle (command contract).
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandState;

namespace {

// The cycle (counted from the command's acceptance) in which set-value generation ends.
int generation_end(kt::Harness& h, double target) {
  return h.cycles_until(
      [&] { return h.x->NcToPlc.SetPos == target && h.x->NcToPlc.SetVelo == 0.0; });
}

}  // namespace

TEST_CASE(
    "with an ideal drive InTargetPosition and kDone come window-time after the end of "
    "set-value generation",
    "[monitor][target_window]") {
  for (double window_time : {0.0, 0.001, 0.02, 0.05}) {
    nc::AxisConfig c = kt::seed_axis();
    c.target_window_time = window_time;
    kt::Harness h(c);
    const uint16_t job = h.post(kt::move_absolute(1000.0, 2000.0));
    const int end = generation_end(h, 1000.0);
    CHECK(end == 1000);  // Dynamics 1.1
    // A sample counts for one cycle: in target once window_time is covered (at least 1 sample).
    const int samples = std::max(1, static_cast<int>(std::lround(window_time / 0.001)));
    INFO("window time " << window_time);
    for (int i = 1; i < samples; ++i) {
      CHECK_FALSE(kt::bit(*h.x, plc::kStateInTargetPosition));
      CHECK(h.state_of(job) == CommandState::kActive);
      h.cycles(1);
    }
    CHECK(kt::bit(*h.x, plc::kStateInTargetPosition));
    CHECK(h.state_of(job) == CommandState::kDone);
  }
}

TEST_CASE(
    "with a lagging drive InTargetPosition waits until the actual position has stayed in "
    "the window for the window time",
    "[monitor][target_window]") {
  nc::AxisConfig c = kt::seed_axis();
  c.drive_model = nc::DriveModel::kFirstOrderLag;
  c.drive_time_constant = 0.05;
  // Pure P control, critically damped (Kv·tau = 0.25): the actual position approaches the
  // target from behind without overshoot.
  c.velocity_feed_forward = 0.0;
  c.position_kv = 5.0;
  c.following_error_limit = 1000.0;
  c.target_window = 2.0;
  c.target_window_time = 0.02;
  kt::Harness h(c);
  const uint16_t job = h.post(kt::move_absolute(1000.0, 2000.0));
  REQUIRE(generation_end(h, 1000.0) == 1000);
  CHECK(std::abs(h.x->NcToPlc.ActPos - 1000.0) > 2.0);  // still far behind
  CHECK_FALSE(kt::bit(*h.x, plc::kStateInTargetPosition));

  const int entered = h.cycles_until([&] { return std::abs(h.x->NcToPlc.ActPos - 1000.0) <= 2.0; });
  REQUIRE(entered > 0);
  // The approach is monotonic: the actual position stays in the window from here on.
  for (int i = 1; i < 20; ++i) {
    CHECK_FALSE(kt::bit(*h.x, plc::kStateInTargetPosition));
    CHECK(h.state_of(job) == CommandState::kActive);
    h.cycles(1);
    REQUIRE(std::abs(h.x->NcToPlc.ActPos - 1000.0) <= 2.0);
  }
  CHECK(kt::bit(*h.x, plc::kStateInTargetPosition));
  CHECK(h.state_of(job) == CommandState::kDone);
}

TEST_CASE(
    "with the target window switched off a positioning is done when set-value generation "
    "ends, however far behind the drive is",
    "[monitor][target_window]") {
  nc::AxisConfig c = kt::seed_axis();
  c.drive_model = nc::DriveModel::kFirstOrderLag;
  c.drive_time_constant = 0.05;
  // Pure P control, critically damped (Kv·tau = 0.25): the actual position approaches the
  // target from behind without overshoot.
  c.velocity_feed_forward = 0.0;
  c.position_kv = 5.0;
  c.following_error_limit = 1000.0;
  c.target_window_enabled = false;
  kt::Harness h(c);
  const uint16_t job = h.post(kt::move_absolute(1000.0, 2000.0));
  REQUIRE(generation_end(h, 1000.0) == 1000);
  CHECK(h.state_of(job) == CommandState::kDone);
  CHECK(std::abs(h.x->NcToPlc.ActPos - 1000.0) > 2.0);
}

TEST_CASE("InTargetPosition is false while moving and again once a new positioning starts",
          "[monitor][target_window]") {
  kt::Harness h;
  h.cycles(20);
  CHECK(kt::bit(*h.x, plc::kStateInTargetPosition));  // holding at 0, target 0
  const uint16_t job = h.post(kt::move_absolute(10.0, 100.0));
  h.cycles(1);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateInTargetPosition));
  REQUIRE(h.cycles_until([&] { return h.state_of(job) == CommandState::kDone; }) > 0);
  CHECK(kt::bit(*h.x, plc::kStateInTargetPosition));
  h.post(kt::move_velocity(100.0, 1));
  h.cycles(1);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateInTargetPosition));
  h.cycles(500);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateInTargetPosition));
}
