// Following-error (lag) monitoring (SPEC A4, A6): a drive that cannot follow raises 0x4550 once
// |set - actual| has been above the limit for longer than the filter time; the axis stops on its
// emergency ramp, shows ErrorStop, refuses motion, and MC_Reset clears it.
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

using plc::AxisState;
using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

namespace {

// The drive saturates at 100 mm/s: a 1000 mm/s job leaves it behind.
nc::AxisConfig slow_drive_axis() {
  nc::AxisConfig c = kt::seed_axis();
  c.drive_max_velocity = 100.0;
  c.following_error_limit = 5.0;
  c.following_error_filter_time = 0.02;  // 20 cycles
  return c;
}

}  // namespace

TEST_CASE("a drive saturated far below the set velocity raises 0x4550 after the filter time",
          "[following_error]") {
  kt::Harness h(slow_drive_axis());
  const uint16_t job = h.post(kt::move_velocity(1000.0, 1));
  const int first_above = h.cycles_until([&] { return std::abs(h.x->NcToPlc.PosDiff) > 5.0; });
  REQUIRE(first_above > 0);
  // That sample is the first of the 20 ms: 20 samples above (0.020 s) are not yet longer than
  // the filter time, the 21st is.
  h.cycles(19);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK(h.state_of(job) == CommandState::kActive);
  h.cycles(1);
  CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kFollowingErrorPosition));
  CHECK(kt::bit(*h.x, plc::kStateError));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateOperational));
  CHECK(kt::axis_state(*h.x) == AxisState::kErrorStop);
  CHECK(h.answer(job).state == CommandState::kError);
  CHECK(h.answer(job).error_code == kt::id(ErrorCode::kFollowingErrorPosition));
  CHECK(h.x->NcToPlc.CmdState == static_cast<uint16_t>(CommandState::kError));

  // The emergency ramp (D = 10000 mm/s², J = 100000 mm/s³) from (v, a): the acceleration is
  // taken down at J first, so the stop takes at most a/J + (v + a²/2J)/D + D/J.
  const double v = h.x->NcToPlc.SetVelo;
  const double a = h.x->NcToPlc.SetAcc;
  REQUIRE(v > 100.0);
  const double d = 10000.0;
  const double j = 100000.0;
  const double bound = a / j + (v + a * a / (2 * j)) / d + d / j;
  const int ramp_cycles = static_cast<int>(std::ceil(bound / 0.001));
  for (int i = 0; i < ramp_cycles; ++i) {
    h.cycles(1);
    REQUIRE(h.x->NcToPlc.SetVelo >= 0.0);  // no reversal
    REQUIRE(h.x->NcToPlc.SetAcc >= -d * (1 + 1e-9));
    REQUIRE(std::abs(h.x->NcToPlc.SetJerk) <= j * (1 + 1e-9));
  }
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHasJob));
  // The drive closes the gap at its 100 mm/s and comes to rest.
  REQUIRE(h.cycles_until([&] { return kt::bit(*h.x, plc::kStateNotMoving); }) > 0);
  CHECK(std::abs(h.x->NcToPlc.PosDiff) <= 1e-3);
  CHECK(kt::axis_state(*h.x) == AxisState::kErrorStop);

  // Motion refused until reset.
  const uint16_t refused = h.post(kt::move_absolute(0.0, 50.0));
  h.cycles(1);
  CHECK(h.answer(refused).error_code == kt::id(ErrorCode::kAxisInErrorState));

  const uint16_t reset = h.post(kt::simple(CommandType::kReset));
  h.cycles(1);
  CHECK(h.state_of(reset) == CommandState::kDone);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateError));
  CHECK(kt::bit(*h.x, plc::kStateOperational));
  CHECK(kt::axis_state(*h.x) == AxisState::kStandstill);
  CHECK(h.x->NcToPlc.SetPos == h.x->NcToPlc.ActPos);  // holds where it stands

  const uint16_t again = h.post(kt::move_relative(-20.0, 50.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(again) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
}

TEST_CASE("a first-order-lag drive with a large time constant raises 0x4550 and stops",
          "[following_error]") {
  nc::AxisConfig c = kt::seed_axis();
  c.drive_model = nc::DriveModel::kFirstOrderLag;
  c.drive_time_constant = 0.5;  // s: about v·tau = 1000 mm behind at 2000 mm/s
  c.drive_dead_time = 0.004;
  kt::Harness h(c);
  const uint16_t job = h.post(kt::move_absolute(1000.0, 2000.0));
  const int n = h.cycles_until([&] { return h.x->NcToPlc.ErrorCode != 0; }, 1000);
  REQUIRE(n > 0);
  CHECK(h.x->NcToPlc.ErrorCode == 0x4550);
  CHECK(h.answer(job).error_code == 0x4550);
  CHECK(kt::axis_state(*h.x) == AxisState::kErrorStop);
  REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetVelo == 0.0; }, 1000) > 0);
  CHECK(h.x->NcToPlc.SetPos < 1000.0);  // stopped short of the target on the error ramp
}

TEST_CASE("a filter time of 0 raises the error in the first cycle above the limit",
          "[following_error]") {
  nc::AxisConfig c = slow_drive_axis();
  c.following_error_filter_time = 0.0;
  kt::Harness h(c);
  h.post(kt::move_velocity(1000.0, 1));
  const int first_above = h.cycles_until([&] { return std::abs(h.x->NcToPlc.PosDiff) > 5.0; });
  REQUIRE(first_above > 0);
  CHECK(h.x->NcToPlc.ErrorCode == 0x4550);
}

TEST_CASE("a lag below the limit, or with monitoring off, raises nothing", "[following_error]") {
  SECTION("small lag") {
    nc::AxisConfig c = kt::seed_axis();
    c.drive_model = nc::DriveModel::kFirstOrderLag;
    c.drive_time_constant = 0.002;  // about 2000 mm/s · 2 ms = 4 mm < 5 mm
    kt::Harness h(c);
    const uint16_t job = h.post(kt::move_absolute(1000.0, 2000.0));
    double max_lag = 0.0;
    const int n = h.cycles_until([&] {
      max_lag = std::max(max_lag, std::abs(h.x->NcToPlc.PosDiff));
      return h.state_of(job) == CommandState::kDone;
    });
    REQUIRE(n > 0);
    CHECK(max_lag > 1.0);
    CHECK(max_lag < 5.0);
    CHECK(h.x->NcToPlc.ErrorCode == 0);
  }
  SECTION("monitoring off") {
    nc::AxisConfig c = slow_drive_axis();
    c.following_error_enabled = false;
    kt::Harness h(c);
    h.post(kt::move_velocity(1000.0, 1));
    h.cycles(2000);
    CHECK(h.x->NcToPlc.PosDiff > 1000.0);
    CHECK(h.x->NcToPlc.ErrorCode == 0);
  }
}
