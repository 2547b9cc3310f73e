// Position compensation, the seed's three figures (seed 000 §2.5, SPEC B7): base motion 0 → 10000
// mm at V = 2000 mm/s (A± 5000, J 50000), compensation AK+ 500, AK- 1000 mm/s², VP 2000 mm/s,
// started at constant velocity. The compensation runs over T = L / VP and adds D (or the largest
// feasible D) to the basic positioning's end.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::ErrorCode;

namespace {

constexpr double kAkPlus = 500.0;
constexpr double kAkMinus = 1000.0;
constexpr double kVp = 2000.0;
constexpr double kCycle = 0.001;

struct Run {
  uint16_t move = 0;
  uint16_t compensation = 0;
  int compensation_cycles = -1;  // cycles from the start until the compensation answered kDone
  double peak_set_velocity = 0.0;
  double largest_velocity_step = 0.0;  // |ΔSetVelo| per cycle while compensating
  double final_position = 0.0;
  uint32_t warning_while_running = 0;
  bool compensating_seen = false;
  plc::NCTOPLC_AXIS_REF at_end{};
};

// Starts 0 → 10000 at 2000 mm/s, waits for the constant velocity, starts the compensation and
// runs the positioning to its end.
Run run(double distance, double velocity_diff, double length) {
  kt::Harness h;
  Run r;
  r.move = h.post(kt::move_absolute(10000.0, 2000.0));
  REQUIRE(h.cycles_until(
              [&] { return h.x->NcToPlc.SetVelo == 2000.0 && h.x->NcToPlc.SetAcc == 0.0; }) > 0);
  r.compensation =
      h.post(kt::move_superimposed(distance, velocity_diff, kAkPlus, kAkMinus, kVp, length));
  double previous_velocity = h.x->NcToPlc.SetVelo;
  for (int i = 1; i <= 20000; ++i) {
    h.cycles(1);
    const auto& o = h.x->NcToPlc;
    r.peak_set_velocity = std::max(r.peak_set_velocity, std::abs(o.SetVelo));
    if (kt::bit(*h.x, plc::kStateCompensating)) {
      r.compensating_seen = true;
      r.largest_velocity_step =
          std::max(r.largest_velocity_step, std::abs(o.SetVelo - previous_velocity));
      r.warning_while_running = o.Warning;
    }
    previous_velocity = o.SetVelo;
    if (r.compensation_cycles < 0 && h.state_of(r.compensation) == CommandState::kDone) {
      r.compensation_cycles = i;
    }
    if (h.state_of(r.move) == CommandState::kDone) break;
  }
  REQUIRE(h.state_of(r.move) == CommandState::kDone);
  r.final_position = h.x->NcToPlc.SetPos;
  r.at_end = h.x->NcToPlc;
  return r;
}

// The trapezoid's peak for a feasible D over T (slopes r1 opening, r2 closing): D = vp T -
// k vp² / 2 with k = 1/r1 + 1/r2, the smaller root.
double feasible_peak(double d, double T, double r1, double r2) {
  const double k = 1.0 / r1 + 1.0 / r2;
  return (T - std::sqrt(T * T - 2.0 * k * d)) / k;
}

}  // namespace

TEST_CASE("full compensation: L 5000, D 250, VK 300 ends at exactly 10250 mm",
          "[compensation][seed]") {
  const Run r = run(250.0, 300.0, 5000.0);
  CHECK(r.final_position == Approx(10250.0).margin(1e-9));
  CHECK(r.at_end.ActPos == Approx(10250.0).margin(1e-3));
  CHECK(r.compensating_seen);
  // Over the whole T = 5000 / 2000 = 2.5 s, i.e. 2500 NC cycles.
  CHECK(r.compensation_cycles == 2500);
  CHECK(r.at_end.CompensationDistance == Approx(250.0).margin(1e-9));
  CHECK(r.at_end.CompensationLength == 5000.0);
  const double peak = feasible_peak(250.0, 2.5, kAkPlus, kAkMinus);  // 106.85 mm/s < VK
  CHECK(r.at_end.CompensationVelocityDiff == Approx(peak).epsilon(1e-12));
  CHECK(r.peak_set_velocity == Approx(2000.0 + peak).epsilon(1e-12));
  CHECK(r.warning_while_running == 0);
  CHECK(r.at_end.Warning == 0);
  CHECK(r.at_end.TargetPos == Approx(10250.0).margin(1e-9));
  CHECK_FALSE(plc::test_bit(r.at_end.StateDWord, plc::kStateCompensating));
  // The extra motion is a trapezoid: its velocity changes by at most AK- · T per cycle.
  CHECK(r.largest_velocity_step <= kAkMinus * kCycle + 1e-9);
}

TEST_CASE(
    "partial compensation: L 2000, D 500, VK 500 does the largest feasible D, 500/3 mm, "
    "with warning 0x4243",
    "[compensation][seed]") {
  const Run r = run(500.0, 500.0, 2000.0);
  // T = 1 s; the triangle with slopes 500 and 1000 peaks at T / (1/500 + 1/1000) = 333.3 mm/s
  // (below VK) and covers half its peak times T: 500/3 mm. The seed reads "10165.0" off its plot.
  const double largest = 0.5 * (1.0 / (1.0 / kAkPlus + 1.0 / kAkMinus)) * 1.0;
  REQUIRE(largest == Approx(500.0 / 3.0).epsilon(1e-15));
  CHECK(r.final_position == Approx(10000.0 + 500.0 / 3.0).margin(1e-6));
  CHECK(r.compensation_cycles == 1000);
  CHECK(r.at_end.CompensationDistance == Approx(500.0 / 3.0).margin(1e-6));
  CHECK(r.at_end.CompensationVelocityDiff == Approx(1000.0 / 3.0).epsilon(1e-12));
  CHECK(r.warning_while_running == kt::id(ErrorCode::kCompensationIncomplete));
  CHECK(r.at_end.Warning == kt::id(ErrorCode::kCompensationIncomplete));
}

TEST_CASE("full negative compensation: L 5000, D -250 ends at exactly 9750 mm",
          "[compensation][seed]") {
  const Run r = run(-250.0, 300.0, 5000.0);
  CHECK(r.final_position == Approx(9750.0).margin(1e-9));
  CHECK(r.compensation_cycles == 2500);
  CHECK(r.at_end.CompensationDistance == Approx(-250.0).margin(1e-9));
  // D < 0 opens with the deceleration increase AK- and closes with AK+ (seed 000 §2.5 note 4).
  const double peak = feasible_peak(250.0, 2.5, kAkMinus, kAkPlus);
  CHECK(r.at_end.CompensationVelocityDiff == Approx(-peak).epsilon(1e-12));
  CHECK(r.at_end.Warning == 0);
  CHECK(r.peak_set_velocity == 2000.0);  // the axis only falls behind
}
