// Cyclic slave (SPEC C6) behind a master whose slaves follow its filtered actual values (SPEC C8),
// fuzz finding K27 (docs/reliability.md): the factor in force lies between its former value and
// the commanded one, so on its way from 2 to a commanded -3 it may pass 0, and with a tiny
// AccBound it stops on 0 for one cycle. The master is pushed by hand at 100 mm/s and let go; its
// filtered velocity decays by exp(-T / filter time) per cycle, so the factor is held (every rate
// that keeps |a| <= AccBound moves away from -3), until the filter's velocity window holds its
// output: the followed velocity steps from just above the window to 0 with an acceleration not
// 0, and a = f' × am + r × vm allows only f' = 0. The slave still shows as a slave (bit 15,
// CoupleState 3) with GearRatio 0, its set velocity steps from 2 × that velocity to 0 (C8's
// window: the slave's velocity is factor × the followed one), and in the next cycle, the master
// at rest, the factor becomes -3.
#include <catch2/catch.hpp>

#include <cmath>

#include "gear_dyn_rig.hpp"
#include "propagation_rig.hpp"

TEST_CASE("a cyclic slave's factor passes 0 on its way to a factor of the other sign",
          "[gear][cyclic][actual_values]") {
  pr::Group g(2, [](std::size_t i, nc::AxisConfig& c) {
    if (i != 0) return;
    c.couple_slave_to_actual_values = true;
    c.actual_value_velocity_window = 1.0;
    c.actual_value_filter_time = 0.01;
  });
  plc::AXIS_REF& s = g.at(1);
  REQUIRE(gd::couple(g, 1, 0, 2.0, 1e-300).state == plc::CommandState::kActive);
  g.cycles(10);
  kt::set_enables(g.at(0), false);  // case 2: the head master by hand, no error
  g.cycles(1);
  REQUIRE(g.kernel.push_by_hand(0, 100.0) == plc::ErrorCode::kNone);
  g.cycles(300);
  REQUIRE(s.NcToPlc.SetVelo == Approx(200.0).epsilon(1e-6));
  REQUIRE(g.kernel.push_by_hand(0, 0.0) == plc::ErrorCode::kNone);
  s.PlcToNc.GearRatio1 = -3.0;

  // The filtered velocity decays: the factor is held at 2 while the followed velocity moves.
  double last_velocity = s.NcToPlc.SetVelo;
  int cycles = 0;
  while (s.NcToPlc.GearRatio == 2.0 && cycles < 200) {
    last_velocity = s.NcToPlc.SetVelo;
    g.cycles(1);
    ++cycles;
  }
  INFO("cycles after the push " << cycles);
  REQUIRE(cycles < 200);
  // The window's hold: the factor in force 0, still a slave, its velocity 0 from above 2 × 1.
  CHECK(s.NcToPlc.GearRatio == 0.0);
  CHECK(kt::bit(s, plc::kStateCoupled));
  CHECK(s.NcToPlc.CoupleState == 3U);
  CHECK(s.NcToPlc.ErrorCode == 0U);
  CHECK(last_velocity >= 2.0 * 1.0);
  CHECK(last_velocity <= 2.0 * 1.0 / std::exp(-0.001 / 0.01) + 1e-9);
  CHECK(s.NcToPlc.SetVelo == 0.0);
  CHECK(s.NcToPlc.SetAcc == 0.0);
  const double held = s.NcToPlc.SetPos;

  // The master's followed values at rest: the commanded factor in force, the slave standing.
  g.cycles(1);
  CHECK(s.NcToPlc.GearRatio == -3.0);
  CHECK(s.NcToPlc.SetVelo == 0.0);
  CHECK(s.NcToPlc.SetPos == Approx(held).margin(1e-12));  // the new offset's rounding
}
