// Cyclic slave (SPEC C6, seed 000 §3.3; issue 10): a factor step 0.5 -> 1.5 on a master cruising
// at 1000 mm/s (A± 5000) with AccBound 8000 (above the stability bound 1.5 × 5000). Every cycle:
// the slave's acceleration within 8000, its velocity factor in force × the master's, its position
// continuous (it moves factor(k) × the master's step; offset re-set as docs/behaviour.md says),
// the factor in force moving only towards 1.5. It reaches 1.5 exactly after 1 / (8000 / 1000) =
// 0.125 s (126 cycles: the rate is held 1e-12 inside the bound) and stays; held, the slave is
// 1.5 × master + offset bit for bit.
#include <catch2/catch.hpp>

#include <cmath>

#include "gear_dyn_rig.hpp"

TEST_CASE("factor step 0.5 -> 1.5 at 1000 mm/s with AccBound 8000: bounded, continuous, exact",
          "[gear][cyclic]") {
  gr::Rig rig(2);
  plc::AXIS_REF& m = rig.at(0);
  plc::AXIS_REF& s = rig.at(1);
  REQUIRE(gd::couple(rig, 1, 0, 0.5, 8000.0).state == plc::CommandState::kActive);
  CHECK(s.NcToPlc.GearRatio == 0.5);
  CHECK(s.NcToPlc.CoupleState == 3U);
  CHECK(s.NcToPlc.Warning == 0U);  // 8000 >= 0.5 × 5000

  rig.post(0, kt::move_velocity(1000.0, 1));
  int cycles = 0;
  while (!(m.NcToPlc.SetVelo == 1000.0 && m.NcToPlc.SetAcc == 0.0) && cycles < 2000) {
    rig.kernel.cycle();
    ++cycles;
    REQUIRE(std::abs(s.NcToPlc.SetAcc) <= 8000.0);
    REQUIRE(s.NcToPlc.SetVelo == 0.5 * m.NcToPlc.SetVelo);
  }
  REQUIRE(cycles < 2000);  // cruising
  rig.cycles(10);

  s.PlcToNc.GearRatio1 = 1.5;
  double offset = s.NcToPlc.SetPos - 0.5 * m.NcToPlc.SetPos;
  int ramp = 0;
  double peak = 0.0;
  while (s.NcToPlc.GearRatio != 1.5 && ramp < 1000) {
    const double f0 = s.NcToPlc.GearRatio;
    const double s0 = s.NcToPlc.SetPos;
    const double m0 = m.NcToPlc.SetPos;
    rig.kernel.cycle();
    ++ramp;
    const double f = s.NcToPlc.GearRatio;
    REQUIRE(f > f0);  // towards 1.5 every cycle, never past it
    REQUIRE(f <= 1.5);
    REQUIRE(std::abs(s.NcToPlc.SetAcc) <= 8000.0);
    peak = std::max(peak, std::abs(s.NcToPlc.SetAcc));
    REQUIRE(s.NcToPlc.SetVelo == f * m.NcToPlc.SetVelo);
    // Continuous: the offset taken anew from the last positions, as the NC does, bit for bit.
    offset = s0 - f * m0;
    REQUIRE(s.NcToPlc.SetPos == f * m.NcToPlc.SetPos + offset);
    REQUIRE(std::abs((s.NcToPlc.SetPos - s0) - f * (m.NcToPlc.SetPos - m0)) < 1e-9);
  }
  CHECK(ramp == 126);
  CHECK(peak > 7999.0);  // the bound is used, not a slower ramp
  CHECK(s.NcToPlc.GearRatio == 1.5);

  for (int i = 0; i < 2000; ++i) {
    rig.kernel.cycle();
    REQUIRE(s.NcToPlc.GearRatio == 1.5);
    REQUIRE(s.NcToPlc.SetPos == 1.5 * m.NcToPlc.SetPos + offset);
    REQUIRE(s.NcToPlc.SetVelo == 1500.0);
    REQUIRE(s.NcToPlc.SetAcc == 0.0);
  }
  CHECK(m.NcToPlc.SetVelo == 1000.0);
  CHECK(s.NcToPlc.Warning == 0U);
}

TEST_CASE("a factor step down and a sign change: the same bound, reached exactly",
          "[gear][cyclic]") {
  gr::Rig rig(2);
  plc::AXIS_REF& m = rig.at(0);
  plc::AXIS_REF& s = rig.at(1);
  REQUIRE(gd::couple(rig, 1, 0, 1.0, 6000.0).state == plc::CommandState::kActive);
  rig.post(0, kt::move_velocity(1000.0, 1));
  rig.cycles(500);
  s.PlcToNc.GearRatio1 = -0.5;  // reverses the slave (C2)
  int ramp = 0;
  while (s.NcToPlc.GearRatio != -0.5 && ramp < 1000) {
    const double f0 = s.NcToPlc.GearRatio;
    rig.kernel.cycle();
    ++ramp;
    REQUIRE(s.NcToPlc.GearRatio < f0);
    REQUIRE(s.NcToPlc.GearRatio >= -0.5);
    REQUIRE(std::abs(s.NcToPlc.SetAcc) <= 6000.0);
  }
  // 1.5 / (6000 / 1000) = 0.25 s.
  CHECK(ramp == 251);
  CHECK(s.NcToPlc.SetVelo == -0.5 * m.NcToPlc.SetVelo);
  CHECK(s.NcToPlc.SetVelo == -500.0);
}
