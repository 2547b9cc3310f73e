// Looping distance in the kernel (SPEC E2; seed 004 "Positioning A → B, with loop movement > 0"),
// issue 12's numbers with looping 30 mm: 0 → 1000 overshoots towards 1030 and comes back, 2000 →
// 1000 needs no loop; both make their last approach to 1000 from the same (positive) side, with
// negative velocity, and end within the negative braking distance of 1000.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "two_speed_kernel_rig.hpp"

using tsk::C;
using tsk::Sample;

namespace {

nc::AxisConfig looping_axis() {
  nc::AxisConfig c = ts::issue_axis();
  c.looping_distance_enabled = true;
  c.looping_distance = 30.0;
  return c;
}

// The direction of the last travel before the brake came on: +1 / -1.
double last_travel_direction(const std::vector<Sample>& trace) {
  for (auto it = trace.rbegin(); it != trace.rend(); ++it) {
    if (it->bit(C::bPlusHigh) || it->bit(C::bPlusLow)) return 1.0;
    if (it->bit(C::bMinusHigh) || it->bit(C::bMinusLow)) return -1.0;
  }
  return 0.0;
}

double highest(const std::vector<Sample>& trace) {
  double top = trace.front().actual;
  for (const Sample& s : trace)
    top = std::max(top, s.actual);
  return top;
}

}  // namespace

TEST_CASE("looping 30 mm: 0 → 1000 passes 1000, reverses short of 1030 and comes back",
          "[two_speed][kernel][looping]") {
  tsk::Rig rig(looping_axis());
  REQUIRE(rig.position_to(1000.0));
  CHECK(ts::images_consistent(rig.trace));
  // The first leg ends at the reversal point 1030: creep off once the encoder passed 1025.
  const double top = highest(rig.trace);
  CHECK(top > 1025.0);
  CHECK(top < 1030.0);
  CHECK(last_travel_direction(rig.trace) == -1.0);
  CHECK(ts::state_sequence(rig.trace) == std::vector<uint32_t>{21, 22, 23, 24, 23, 24, 20});
  rig.cycles(300);
  CHECK(rig.actual() > 1000.0);  // approached from above
  CHECK(rig.actual() - 1000.0 <= 6.0);
}

TEST_CASE("looping 30 mm: 2000 → 1000 needs no loop and ends on the same side",
          "[two_speed][kernel][looping]") {
  tsk::Rig rig(looping_axis());
  REQUIRE(rig.position_to(2000.0));
  rig.cycles(300);
  REQUIRE(rig.position_to(1000.0));
  CHECK(ts::images_consistent(rig.trace));
  CHECK(last_travel_direction(rig.trace) == -1.0);
  CHECK(ts::state_sequence(rig.trace) == std::vector<uint32_t>{21, 22, 23, 24, 20});
  CHECK(highest(rig.trace) <= rig.trace.front().read);  // never above where it started
  rig.cycles(300);
  CHECK(rig.actual() > 1000.0);
  CHECK(rig.actual() - 1000.0 <= 6.0);
}
