// No allocation in the two-speed cycle path (brief: real-time discipline): a counting global
// operator new over 40 000 NC cycles of sequencer and plant in closed loop, with positionings in
// both directions, looping legs, stops in each phase, override changes, refusals, a disable and
// a non-finite encoder value, counts 0. Runs only in the plain build.
#include <catch2/catch.hpp>

#include <limits>

#include "counting_allocator.hpp"
#include "two_speed_loop.hpp"

TEST_CASE("two-speed sequencer and plant allocate nothing per cycle",
          "[no_allocation][two_speed]") {
  nc::AxisConfig c = ts::issue_axis();
  c.looping_distance_enabled = true;
  ts::Loop loop(c);
  loop.record = false;
  int events = 0;
  ca::g_allocations = 0;
  ca::g_counting = true;
  for (int k = 0; k < 40000; ++k) {
    switch (k % 8000) {
      case 0:
        (void)loop.start(k % 16000 == 0 ? 1500.0 : 0.0, 2000.0);
        break;
      case 100:
        (void)loop.start(300.0, 40.0);  // busy: refused
        (void)loop.start(std::numeric_limits<double>::quiet_NaN(), 40.0);
        break;
      case 600:
        loop.set_override_percent(40.0);
        break;
      case 900:
        loop.set_override_percent(0.0);
        break;
      case 1200:
        loop.set_override_percent(100.0);
        break;
      case 5000:
        (void)loop.start(loop.actual() + 400.0, 2000.0);
        break;
      case 5600:
        (void)loop.stop();
        break;
      case 6500:
        (void)loop.start(loop.actual() - 300.0, 40.0);
        break;
      case 6700:
        loop.sequencer.set_enabled(false);
        break;
      case 6701:
        loop.sequencer.set_enabled(true);
        break;
      case 7000:
        (void)loop.sequencer.step(std::numeric_limits<double>::infinity(), 0.001);
        break;
      default:
        break;
    }
    if (loop.cycle().event != ts::TwoSpeedEvent::kNone) ++events;
  }
  ca::g_counting = false;
  CHECK(ca::g_allocations == 0);
  CHECK(events >= 10);  // the scenario really ran positionings and stops to their ends
}
