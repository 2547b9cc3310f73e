// Cyclic slave (SPEC C6, seed 000 §3.3; issue 10): a factor that follows a sine of ±20 % at 2 Hz
// around 1.0, written every cycle from the master's start (0 -> 1000 mm/s at A± 5000, jerk 50000,
// then cruising), with AccBound exactly at the seed's stability bound max|Cf| × max(A+, A-) =
// 1.2 × 5000. No slave acceleration above AccBound (to rounding, 1e-12 relative), the factor in
// force never moves away from the commanded one nor past it (no oscillation), and the lag it
// takes while the master accelerates decays: the largest |factor in force − commanded| of each
// 10 ms falls from window to window until it is 0, and stays 0 while the master cruises.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "gear_dyn_rig.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

double commanded(int k) {
  return 1.0 + 0.2 * std::sin(2.0 * kPi * 2.0 * 0.001 * k);
}

}  // namespace

TEST_CASE(
    "a sine factor ±20 % at 2 Hz with AccBound at the stability bound: bounded, no "
    "oscillation, the lag decays",
    "[gear][cyclic]") {
  double max_factor = 0.0;
  for (int k = 0; k < 3000; ++k)
    max_factor = std::max(max_factor, std::abs(commanded(k)));
  const double bound = max_factor * 5000.0;  // the stability bound

  gr::Rig rig(2);
  plc::AXIS_REF& m = rig.at(0);
  plc::AXIS_REF& s = rig.at(1);
  REQUIRE(gd::couple(rig, 1, 0, 1.0, bound).state == plc::CommandState::kActive);
  CHECK(s.NcToPlc.Warning == 0U);
  rig.post(0, kt::move_velocity(1000.0, 1));
  std::vector<double> window_max;
  double window = 0.0;
  double peak = 0.0;
  for (int k = 0; k < 3000; ++k) {
    const double c = commanded(k);
    s.PlcToNc.GearRatio1 = c;
    const double f0 = s.NcToPlc.GearRatio;
    rig.kernel.cycle();
    const double f = s.NcToPlc.GearRatio;
    REQUIRE(std::abs(s.NcToPlc.SetAcc) <= bound * (1.0 + 1e-12));
    peak = std::max(peak, std::abs(s.NcToPlc.SetAcc));
    // Between where it was and the commanded factor: never away from it, never past it.
    REQUIRE(std::min(f0, c) <= f);
    REQUIRE(f <= std::max(f0, c));
    window = std::max(window, std::abs(f - c));
    if ((k + 1) % 10 == 0) {
      window_max.push_back(window);
      window = 0.0;
    }
  }
  INFO("peak slave acceleration " << peak);
  // While the master accelerates (0.3 s) the bound leaves the factor little room: it lags there.
  const auto worst = std::max_element(window_max.begin(), window_max.end());
  CHECK(*worst > 1e-3);
  CHECK(*worst < 0.05);
  // From its worst window on the lag decays window by window until it is 0, and stays 0.
  const auto zero = std::find(worst, window_max.end(), 0.0);
  REQUIRE(zero != window_max.end());
  for (auto it = worst; it + 1 != zero; ++it)
    CHECK(*(it + 1) < *it);
  for (auto it = zero; it != window_max.end(); ++it)
    CHECK(*it == 0.0);
  CHECK(zero - window_max.begin() <= 40);  // 0 from 0.4 s on at the latest
  CHECK(m.NcToPlc.SetVelo == 1000.0);
}
