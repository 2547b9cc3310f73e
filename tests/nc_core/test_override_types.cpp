// The four override types of seed 000 §2.2 (AxisConfig::override_type):
//   1, 3 refer to the level calculated (and possibly reduced) at the start, 2, 4 to the user's V;
//   1, 2 keep the old table when the new level is not achievable, 3, 4 take the best smaller one.
// Seed axis: A+ = A- = 5000 mm/s², J = 50000 mm/s³ (A²/J = 500 mm/s).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandState;

namespace {

nc::AxisConfig typed_axis(int type) {
  nc::AxisConfig c = kt::seed_axis();
  c.override_type = type;
  return c;
}

// Rest-to-rest peak over distance d when V is not reached and A is (v >= A²/J):
// d = v²/A + v·A/J.
double reachable_peak(double d) {
  const double a = 5000.0;
  const double k = a * a / 50000.0;
  return 0.5 * (-k + std::sqrt(k * k + 4.0 * a * d));
}

}  // namespace

TEST_CASE(
    "override 50 % on a short move: types 1 and 3 halve the reduced start level, types 2 and 4 "
    "the user's V",
    "[override][types]") {
  // 0 → 400 mm at V 2000: V is not reachable, the start level is reduced to 1186.14 mm/s.
  const double reduced = reachable_peak(400.0);
  REQUIRE(reduced == Approx(1186.1406616));
  for (int type = 1; type <= 4; ++type) {
    INFO("override type " << type);
    kt::Harness h(typed_axis(type));
    kt::set_override(*h.x, 50.0);
    kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
    const uint16_t move = h.post(kt::move_absolute(400.0, 2000.0));
    double peak = 0.0;
    double target_velo = 0.0;
    const int n = kt::checked_cycles_until(h, c, [&] {
      peak = std::max(peak, h.x->NcToPlc.SetVelo);
      target_velo = std::max(target_velo, h.x->NcToPlc.TargetVelo);
      return h.state_of(move) == CommandState::kDone;
    });
    REQUIRE(n > 0);
    const double expected = (type == 1 || type == 3) ? 0.5 * reduced : 1000.0;
    CHECK(peak == Approx(expected).epsilon(1e-9));
    CHECK(target_velo == Approx(expected).epsilon(1e-9));
    CHECK(h.x->NcToPlc.SetPos == 400.0);
    INFO(c.first);
    CHECK(c.ok());
  }
}

TEST_CASE(
    "a level that is no longer achievable: types 1 and 2 keep the old table, types 3 and 4 "
    "reach the best smaller level",
    "[override][types]") {
  // 0 → 5000 mm at V 2000, started at 50 % (1000 mm/s). At 4300 mm the override goes to 100 %:
  // 2000 mm/s would need 450 mm to get there and 500 mm to stop, only 700 mm are left.
  for (int type = 1; type <= 4; ++type) {
    INFO("override type " << type);
    kt::Harness h(typed_axis(type));
    kt::set_override(*h.x, 50.0);
    kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
    const uint16_t move = h.post(kt::move_absolute(5000.0, 2000.0));
    REQUIRE(kt::checked_cycles_until(h, c, [&] { return h.x->NcToPlc.SetPos >= 4300.0; }) > 0);
    CHECK(h.x->NcToPlc.SetVelo == Approx(1000.0).margin(1e-9));
    kt::set_override(*h.x, 100.0);
    double peak = 0.0;
    REQUIRE(kt::checked_cycles_until(h, c, [&] {
              peak = std::max(peak, h.x->NcToPlc.SetVelo);
              return h.state_of(move) == CommandState::kDone;
            }) > 0);
    if (type == 1 || type == 2) {
      CHECK(peak == Approx(1000.0).margin(1e-9));  // the old table, without notification
    } else {
      CHECK(peak > 1200.0);  // the best level the 700 mm allow
      CHECK(peak < 2000.0);
    }
    CHECK(h.x->NcToPlc.SetPos == 5000.0);
    CHECK(h.x->NcToPlc.Warning == 0);
    INFO(c.first);
    CHECK(c.ok());
  }
}
