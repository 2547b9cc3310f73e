// Dead-time compensation of external setpoints (seed 000 §2.6 "Optimization options": "delay
// time between velocity and position", AxisConfig::ext_setpoint_delay): every taken packet is
// carried the delay d ahead along its own velocity and acceleration, p + v d + a d²/2 and
// v + a d, compensating the cycle the packet spent in transport. The position-only cycles carry
// no velocity and are not moved.
#include <catch2/catch.hpp>

#include <limits>

#include "kernel_harness.hpp"
#include "nc_core/config.hpp"

namespace {

nc::AxisConfig with_delay(double delay) {
  nc::AxisConfig c = kt::seed_axis();
  c.ext_setpoint_delay = delay;
  return c;
}

}  // namespace

TEST_CASE("a delay of one cycle carries each packet one cycle ahead", "[ext_setpoint][delay]") {
  kt::Harness h(with_delay(0.001));
  h.post(kt::ext_enable(0.0, 1));
  for (int i = 1; i <= 50; ++i) {
    kt::feed(*h.x, 0.5 * i, 500.0, 0.0, 1);
    h.cycles(1);
    REQUIRE(h.x->NcToPlc.SetPos == Approx(0.5 * (i + 1)).epsilon(1e-15));
    REQUIRE(h.x->NcToPlc.SetVelo == 500.0);
  }
  kt::feed(*h.x, 25.5, 0.0, 0.0, 0);  // the first cycle with direction 0: the position as fed
  h.cycles(1);
  CHECK(h.x->NcToPlc.SetPos == 25.5);
}

TEST_CASE("the delay uses the packet's acceleration too", "[ext_setpoint][delay]") {
  kt::Harness h(with_delay(0.004));
  h.post(kt::ext_enable(0.0, 2));  // relative: the carried-ahead offset is added
  kt::feed(*h.x, 1.0, 100.0, 2000.0, 1);
  h.cycles(1);
  // 1 + 100 · 0.004 + 2000 · 0.004² / 2 = 1.416 mm, 100 + 2000 · 0.004 = 108 mm/s.
  CHECK(h.x->NcToPlc.SetPos == Approx(1.416).epsilon(1e-14));
  CHECK(h.x->NcToPlc.SetVelo == Approx(108.0).epsilon(1e-14));
  CHECK(h.x->NcToPlc.SetAcc == 2000.0);
}

TEST_CASE("without a delay the fed values are taken exactly", "[ext_setpoint][delay]") {
  kt::Harness h;
  CHECK(h.kernel.config("X").ext_setpoint_delay == 0.0);
  h.post(kt::ext_enable(0.0, 1));
  kt::feed(*h.x, 0.1, 0.3, 0.7, -1);
  h.cycles(1);
  CHECK(h.x->NcToPlc.SetPos == 0.1);
  CHECK(h.x->NcToPlc.SetVelo == 0.3);
  CHECK(h.x->NcToPlc.SetAcc == 0.7);
}

TEST_CASE("the delay is refused outside [0, 1] s at /ext_setpoint_delay", "[ext_setpoint][delay]") {
  for (double bad : {-0.001, 1.001, std::numeric_limits<double>::quiet_NaN()}) {
    INFO("delay " << bad);
    nc::AxisConfig c = with_delay(bad);
    try {
      nc::validate(c);
      FAIL("accepted");
    } catch (const nc::ConfigError& e) {
      CHECK(e.pointer() == "/ext_setpoint_delay");
    }
  }
  CHECK_NOTHROW(nc::validate(with_delay(1.0)));
}
