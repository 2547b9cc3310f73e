// The simulated servo loop (SPEC A3): an ideal drive with velocity feed-forward follows the set
// position to within one encoder increment; the dead time delays the drive by whole cycles; the
// first-order lag closes the velocity gap by exp(-T/tau) per cycle; the drive saturates at
// drive_max_velocity; the encoder quantises to whole increments; an encoder (virtual) axis shows
// the set values as actual values.
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandState;

TEST_CASE("an ideal drive with feed-forward follows the set position within one encoder increment",
          "[kernel][drive]") {
  kt::Harness h;  // increment 1e-4 mm, Kv 1, feed-forward 1
  const uint16_t job = h.post(kt::move_absolute(1000.0, 2000.0));
  double worst = 0.0;
  const int n = h.cycles_until([&] {
    worst = std::max(worst, std::abs(h.x->NcToPlc.PosDiff));
    return h.state_of(job) == CommandState::kDone;
  });
  REQUIRE(n > 0);
  // Half an increment from the encoder's rounding, at most half more from the controller acting
  // on rounded positions: no lag from the sampling itself.
  CHECK(worst <= 1e-4);
}

TEST_CASE("the encoder shows whole increments of the true position", "[kernel][drive]") {
  nc::AxisConfig c = kt::seed_axis();
  c.encoder_increment = 0.01;
  kt::Harness h(c);
  h.post(kt::move_absolute(123.456789, 700.0));
  for (int i = 0; i < 600; ++i) {
    h.cycles(1);
    const double k = h.x->NcToPlc.ActPos / 0.01;
    REQUIRE(std::abs(k - std::round(k)) < 1e-6);
  }
  // At rest the true position is 123.456789: the encoder shows 123.46.
  CHECK(h.x->NcToPlc.ActPos == Approx(123.46).margin(1e-9));
  CHECK(h.x->NcToPlc.SetPos == 123.456789);
}

TEST_CASE("a dead time of 5 cycles starts the actual motion 5 cycles after the set motion",
          "[kernel][drive]") {
  nc::AxisConfig c = kt::seed_axis();
  c.drive_model = nc::DriveModel::kFirstOrderLag;
  c.drive_time_constant = 0.0;  // pure dead time
  c.drive_dead_time = 0.005;
  c.encoder_increment = 0.0;
  kt::Harness h(c);
  h.post(kt::move_absolute(100.0, 1000.0));
  h.cycles(1);
  CHECK(h.x->NcToPlc.SetPos > 0.0);
  for (int i = 2; i <= 5; ++i) {
    h.cycles(1);
    CHECK(h.x->NcToPlc.ActPos == 0.0);
  }
  h.cycles(1);
  CHECK(h.x->NcToPlc.ActPos > 0.0);
  // Without feedback the delayed drive reproduces the set position of 5 cycles before exactly
  // (to rounding): feed-forward of the mean set velocity integrates back to the set position.
  nc::AxisConfig open = c;
  open.position_kv = 0.0;
  kt::Harness g(open);
  g.post(kt::move_absolute(100.0, 1000.0));
  std::vector<double> set;
  for (int i = 0; i < 400; ++i) {
    g.cycles(1);
    set.push_back(g.x->NcToPlc.SetPos);
    if (i >= 5)
      REQUIRE(g.x->NcToPlc.ActPos == Approx(set[static_cast<std::size_t>(i - 5)]).margin(1e-9));
  }
}

TEST_CASE("a first-order lag closes the velocity gap by exp(-T/tau) per cycle", "[kernel][drive]") {
  nc::AxisConfig c = kt::seed_axis();
  c.drive_model = nc::DriveModel::kFirstOrderLag;
  c.drive_time_constant = 0.05;
  c.position_kv = 0.0;  // feed-forward only: the drive input is the set velocity
  c.following_error_enabled = false;
  c.encoder_increment = 0.0;
  kt::Harness h(c);
  const uint16_t job = h.post(kt::move_velocity(500.0, 1));
  REQUIRE(h.cycles_until([&] { return h.state_of(job) == CommandState::kReached; }) > 0);
  h.cycles(2);  // the held input is 500 mm/s from here on
  const double decay = std::exp(-0.001 / 0.05);
  double gap = 500.0 - h.x->NcToPlc.ActVelo;
  REQUIRE(gap > 10.0);
  for (int i = 0; i < 100; ++i) {
    h.cycles(1);
    const double next = 500.0 - h.x->NcToPlc.ActVelo;
    REQUIRE(next == Approx(gap * decay).epsilon(1e-9));
    gap = next;
  }
}

TEST_CASE("the drive never runs faster than drive_max_velocity", "[kernel][drive]") {
  nc::AxisConfig c = kt::seed_axis();
  c.drive_max_velocity = 800.0;
  c.following_error_limit = 500.0;
  kt::Harness h(c);
  const uint16_t job = h.post(kt::move_absolute(1500.0, 1000.0));
  const int n = h.cycles_until([&] {
    REQUIRE(std::abs(h.x->NcToPlc.ActVelo) <= 800.0);
    return h.state_of(job) == CommandState::kDone;
  });
  REQUIRE(n > 0);
  CHECK(std::abs(h.x->NcToPlc.ActPos - 1500.0) <= 2.0);
}

TEST_CASE("an encoder axis shows its set values as actual values", "[kernel][drive]") {
  nc::AxisConfig c = kt::seed_axis();
  c.kind = nc::AxisKind::kEncoder;
  kt::Harness h(c);
  const uint16_t job = h.post(kt::move_absolute(-321.5, 900.0));
  const int n = h.cycles_until([&] {
    REQUIRE(h.x->NcToPlc.ActPos == h.x->NcToPlc.SetPos);
    REQUIRE(h.x->NcToPlc.ActVelo == h.x->NcToPlc.SetVelo);
    REQUIRE(h.x->NcToPlc.PosDiff == 0.0);
    return h.state_of(job) == CommandState::kDone;
  });
  REQUIRE(n > 0);
  CHECK(h.x->NcToPlc.ActPos == -321.5);
}
