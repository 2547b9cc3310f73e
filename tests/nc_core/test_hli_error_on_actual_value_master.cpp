// Fuzz finding K14: an HLI list change refused with 70200 on a slave reaches its master by the
// group reaction (SPEC C7); the master runs DELAYED error propagation with its slaves on its
// actual values (C8 case 1), so from then on its slaves follow its filtered actual position. Its
// own set values must not change by that (docs/behaviour.md "Error propagation and actual-value
// coupling": "The axis's own NcToPlc set values are not changed"): it brakes on its error ramp
// (emergency deceleration 10000 mm/s²). Before the fix the HLI stage took the slave-facing
// values as the master's own: its image went 146 → 0 → 13.9 mm/s with 13 890 mm/s².
#include <catch2/catch.hpp>

#include <cmath>

#include "hli_kernel_rig.hpp"

TEST_CASE("a master on actual values for its slaves brakes on its own ramp after an HLI 70200",
          "[hli][error_propagation][actual_value]") {
  nc::AxisConfig master = hlik::axis(1, "M");
  master.error_propagation_mode = nc::ErrorPropagation::kDelayed;
  master.error_propagation_delay = 1.0;
  master.couple_slave_to_actual_values = true;
  hlik::Rig rig({master, hlik::axis(2, "S")});
  plc::AXIS_REF& m = *rig.axes[0];
  plc::AXIS_REF& s = *rig.axes[1];

  fb::MC_GearIn gear;
  gear.RatioNumerator = 0.5;
  gear.Execute = true;
  for (int n = 0; n < 10 && !gear.InGear; ++n) {
    gear(m, s);
    rig.tick();
  }
  REQUIRE(gear.InGear);
  rig.start_move(0, 30.0, 146.0);
  for (int n = 0; n < 124; ++n) {
    gear(m, s);
    rig.tick();
  }
  REQUIRE(m.NcToPlc.SetVelo == Approx(146.0));

  // The slave itself as its own HLI source while it moves: refused with 70200 (a list change
  // while a source moves), and the group reaction gives the master the same error.
  namespace h = plc::hli;
  rig.coupling[1].desc = {};
  rig.coupling[1].desc[0] = h::HLI_AX_COUPLING_DESC{2, h::HLI_AXIS_COUPLING_MIRROR, 0, 0};
  rig.coupling[1].Execute = true;
  double v = m.NcToPlc.SetVelo;
  bool errored = false;
  for (int n = 0; n < 200; ++n) {
    gear(m, s);
    rig.tick();
    INFO("cycle " << n << " v " << m.NcToPlc.SetVelo << " a " << m.NcToPlc.SetAcc);
    errored = errored || m.NcToPlc.ErrorCode != 0U;
    REQUIRE(std::abs(m.NcToPlc.SetAcc) <= 10000.0 * (1.0 + 1e-9));
    REQUIRE(m.NcToPlc.SetVelo <= v);  // braking: never faster again
    REQUIRE(m.NcToPlc.SetVelo >= 0.0);
    REQUIRE(std::abs(m.NcToPlc.SetVelo - v) <= 10000.0 * 0.001 * (1.0 + 1e-9) + 1e-9);
    v = m.NcToPlc.SetVelo;
  }
  CHECK(errored);
  CHECK(m.NcToPlc.ErrorCode == 70200U);
  CHECK(s.NcToPlc.ErrorCode == 70200U);
  CHECK(m.NcToPlc.SetVelo == 0.0);
}
