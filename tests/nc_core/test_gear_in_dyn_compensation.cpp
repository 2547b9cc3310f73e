// A compensation on a cyclic slave (SPEC C5 on C6; fuzz finding K20, where the fuzz checker had
// left it out): MC_MoveSuperImposed works on an MC_GearInDyn slave as on a linear one, on top of
// factor × its master's set values. Master 0 → 10000 mm at V 2000 (the seed axis), slave factor
// 2 with AccBound 20000 (above the stability bound 2 × 5000), compensation D 500, VK 300, AK+
// 500, AK- 1000, VP and L in the slave's own path (2 × 2000, 2 × 5000) requested once the master
// cruises: the slave runs at most VK faster than 2 × its master, the factor stays 2, and it ends
// 500 mm beyond 2 × 10000.
#include <catch2/catch.hpp>

#include <cmath>

#include "gear_dyn_rig.hpp"

TEST_CASE("a compensation on a cyclic slave adds on top of factor x master and ends D further",
          "[gear][cyclic][compensation]") {
  gr::Rig rig(2);
  plc::AXIS_REF& m = rig.at(0);
  plc::AXIS_REF& s = rig.at(1);
  REQUIRE(gd::couple(rig, 1, 0, 2.0, 20000.0).state == plc::CommandState::kActive);
  rig.post(0, kt::move_absolute(10000.0, 2000.0));
  rig.cycles(600);
  REQUIRE(m.NcToPlc.SetVelo == 2000.0);

  const uint16_t n =
      rig.post(1, kt::move_superimposed(500.0, 300.0, 500.0, 1000.0, 4000.0, 10000.0));
  rig.kernel.cycle();
  REQUIRE(rig.answer(1, n).state == plc::CommandState::kActive);
  CHECK(plc::test_bit(s.NcToPlc.StateDWord, plc::kStateCompensating));
  double peak = 0.0;
  for (int i = 0; i < 20000 && m.NcToPlc.SetVelo != 0.0; ++i) {
    rig.kernel.cycle();
    REQUIRE(s.NcToPlc.GearRatio == 2.0);
    const double extra = s.NcToPlc.SetVelo - 2.0 * m.NcToPlc.SetVelo;
    REQUIRE(extra >= -1e-9);
    REQUIRE(extra <= 300.0 + 1e-9);
    peak = std::fmax(peak, extra);
  }
  rig.cycles(10);
  CHECK(peak > 200.0);
  CHECK(rig.answer(1, n).state == plc::CommandState::kDone);
  CHECK(m.NcToPlc.SetPos == 10000.0);
  CHECK(s.NcToPlc.SetPos == Approx(20500.0).margin(1e-6));
  CHECK(s.NcToPlc.CompensationDistance == Approx(500.0).margin(1e-6));
  CHECK(s.NcToPlc.Warning == 0U);
}
