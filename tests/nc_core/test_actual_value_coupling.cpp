// SPEC C8, coupling to actual values (seed 000 §3.1 "Changeover to actual value coupling"; issue
// 10). Case 2: in a group without errors and all axes enabled, the head master's controller
// enable removed (couple_slave_to_actual_values) is no error, and the group follows the master's
// actual position pushed by hand (Kernel::push_by_hand): 100 mm by hand drive a factor-2 slave
// 200 mm, up to the documented rest of the filter's velocity window (below 2 × window ×
// filter time). Case 1: a DELAYED head master whose error lets its drive coast drives its slave
// by its filtered actual values until the group reaction.
#include <catch2/catch.hpp>

#include <cmath>

#include "propagation_rig.hpp"

using plc::AxisState;
using plc::CommandState;
using plc::ErrorCode;

namespace {

void by_actual_values(nc::AxisConfig& c) {
  c.couple_slave_to_actual_values = true;
  c.actual_value_velocity_window = 1.0;
  c.actual_value_filter_time = 0.01;
}

}  // namespace

TEST_CASE("case 2: a head master pushed 100 mm by hand drives its factor-2 slave 200 mm",
          "[actual_values][by_hand]") {
  pr::Group g(2, [](std::size_t i, nc::AxisConfig& c) {
    if (i == 0) by_actual_values(c);
  });
  REQUIRE(g.couple(1, 0, 2.0));
  g.cycles(10);
  const double master0 = g.at(0).NcToPlc.ActPos;
  const double slave0 = g.at(1).NcToPlc.SetPos;
  kt::set_enables(g.at(0), false);
  g.cycles(1);
  CHECK(g.error(0) == 0U);
  CHECK(g.error(1) == 0U);
  CHECK(kt::axis_state(g.at(0)) == AxisState::kDisabled);
  REQUIRE(g.kernel.push_by_hand(0, 100.0) == ErrorCode::kNone);
  g.cycles(1000);  // 1 s at 100 mm/s
  // The slave follows at factor × the filtered actual velocity.
  CHECK(g.at(1).NcToPlc.SetVelo == Approx(200.0).epsilon(1e-6));
  CHECK(g.error(0) == 0U);
  CHECK(g.error(1) == 0U);
  REQUIRE(g.kernel.push_by_hand(0, 0.0) == ErrorCode::kNone);
  g.cycles(200);
  const double pushed = g.at(0).NcToPlc.ActPos - master0;
  CHECK(pushed == Approx(100.0).margin(1e-4));
  const double window_rest = 2.0 * 1.0 * 0.01;  // factor × window × filter time
  CHECK(std::abs(g.at(1).NcToPlc.SetPos - slave0 - 2.0 * pushed) <= window_rest);
  CHECK(g.at(1).NcToPlc.SetVelo == 0.0);
  CHECK(std::abs(g.at(1).NcToPlc.ActPos - slave0 - 200.0) <= window_rest + 1e-3);
  CHECK(g.error(1) == 0U);

  // The enable back: the push ends, the master holds where it was pushed to, no error.
  kt::set_enables(g.at(0), true);
  g.cycles(10);
  CHECK(g.error(0) == 0U);
  CHECK(g.at(0).NcToPlc.SetPos == Approx(master0 + 100.0).margin(1e-4));
  CHECK(g.kernel.push_by_hand(0, 50.0) == ErrorCode::kPushByHandControllerEnabled);
}

TEST_CASE("case 2: a running command of the head master ends CommandAborted, without an error",
          "[actual_values][by_hand]") {
  pr::Group g(2, [](std::size_t i, nc::AxisConfig& c) {
    if (i == 0) by_actual_values(c);
  });
  REQUIRE(g.couple(1, 0, -1.0));
  const uint16_t move = g.post(0, kt::move_absolute(5000.0, 500.0));
  g.cycles(300);
  REQUIRE(g.answer(0, move).state == CommandState::kActive);
  kt::set_enables(g.at(0), false);
  g.cycles(1);
  CHECK(g.answer(0, move).state == CommandState::kAborted);
  CHECK(g.error(0) == 0U);
  g.cycles(300);  // the ideal drive is off at once: master and slave stand
  CHECK(g.error(1) == 0U);
  CHECK(g.at(1).NcToPlc.SetVelo == 0.0);
  CHECK(g.at(1).NcToPlc.SetPos == Approx(-g.at(0).NcToPlc.ActPos).margin(0.02));
}

TEST_CASE(
    "case 2 needs the whole group enabled: with a slave disabled the group does not "
    "follow by actual values",
    "[actual_values][by_hand]") {
  pr::Group g(3, [](std::size_t i, nc::AxisConfig& c) {
    if (i == 0) by_actual_values(c);
  });
  REQUIRE(g.couple(1, 0, 2.0));
  REQUIRE(g.couple(2, 0, 1.0));
  kt::set_enables(g.at(2), false);
  g.cycles(2);
  kt::set_enables(g.at(0), false);
  g.cycles(1);
  REQUIRE(g.kernel.push_by_hand(0, 100.0) == ErrorCode::kNone);
  g.cycles(200);
  // No filtered actual velocity reaches the enabled slave.
  CHECK(g.at(1).NcToPlc.SetVelo == 0.0);
}

TEST_CASE(
    "case 1: a DELAYED head master coasting after its error drives its slave by its "
    "actual values",
    "[actual_values][delayed]") {
  // A0's drive lags (tau 0.1 s). Cruising at 1000 mm/s it loses its feed enable + (an error,
  // 0x4358); the PLC then takes its controller enable away too and the drive coasts.
  pr::Group g(2, [](std::size_t i, nc::AxisConfig& c) {
    if (i != 0) return;
    by_actual_values(c);
    pr::delayed(c, 2.0);
    c.drive_model = nc::DriveModel::kFirstOrderLag;
    c.drive_time_constant = 0.1;
    c.following_error_enabled = false;
    c.position_kv = 10.0;
  });
  REQUIRE(g.couple(1, 0, 2.0));
  g.post(0, kt::move_absolute(20000.0, 1000.0));
  g.cycles(2000);
  REQUIRE(g.at(0).NcToPlc.ActVelo == Approx(1000.0).epsilon(1e-3));
  const double offset = g.at(1).NcToPlc.SetPos - 2.0 * g.at(0).NcToPlc.SetPos;
  kt::set_enables(g.at(0), true, false, true);
  g.cycles(1);
  REQUIRE(g.error(0) == kt::id(ErrorCode::kFeedEnablePlusMissing));
  REQUIRE(g.delayed_bit(0));
  REQUIRE(g.error(1) == 0U);
  kt::set_enables(g.at(0), false);
  // The drive coasts about 1000 mm/s × 0.1 s = 100 mm; the slave follows the filtered actual
  // position (from the set position it followed: the filter has caught up after 50 cycles).
  double previous_actual = g.at(0).NcToPlc.ActPos;
  for (int k = 0; k < 1000; ++k) {
    g.cycles(1);
    INFO("cycle " << k);
    REQUIRE(g.error(1) == 0U);
    if (k >= 50) {
      // The filter lags a moving actual position by v × filter time, 2 × that in slave terms.
      REQUIRE(std::abs(g.at(1).NcToPlc.SetPos - (2.0 * previous_actual + offset)) <=
              2.0 * 1000.0 * 0.01 + 1e-6);
    }
    if (k == 50) {
      // Still coasting: the slave's set velocity is factor × the filtered actual velocity.
      REQUIRE(g.at(0).NcToPlc.ActVelo > 100.0);
      CHECK(g.at(1).NcToPlc.SetVelo > 2.0 * 0.8 * g.at(0).NcToPlc.ActVelo);
      CHECK(g.at(1).NcToPlc.SetVelo < 2.0 * 1.5 * g.at(0).NcToPlc.ActVelo);
    }
    previous_actual = g.at(0).NcToPlc.ActPos;
  }
  CHECK(g.at(0).NcToPlc.ActVelo == Approx(0.0).margin(0.1));  // 1000 · e^-10
  CHECK(std::abs(g.at(1).NcToPlc.SetPos - (2.0 * g.at(0).NcToPlc.ActPos + offset)) <=
        2.0 * 1.0 * 0.01 + 1e-3);
  CHECK(g.delayed_bit(0));
  CHECK(g.error(1) == 0U);
}
