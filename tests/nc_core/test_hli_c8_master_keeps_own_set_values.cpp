// A gear master that drives its slaves by its actual values (C8, DELAYED, case 1) keeps its own
// set values while the HLI stage is engaged (fuzz finding K14, docs/reliability.md): the HLI
// phase takes each axis's program set values q from its snapshot's set values, which its slaves
// no longer read while they follow the filtered actual values (AxisSnapshot::followed_*()).
// Before the fix a slave's 70200 (an HLI list set on
// it while it moves) reached the master by the group reaction, and the master's image showed the
// slaves' filter (v 146 -> 0 -> 13.9 mm/s, a 13 890 mm/s²) instead of its emergency ramp.
#include <catch2/catch.hpp>

#include <cmath>

#include "gear_rig.hpp"
#include "plc_interface/hli.hpp"

using plc::CommandState;

TEST_CASE("A DELAYED actual-value master brakes on its own ramp after its slave's HLI 70200",
          "[hli][propagation][gear]") {
  gr::Rig rig(2, [](std::size_t i, nc::AxisConfig& c) {
    if (i == 0) {
      c.error_propagation_mode = nc::ErrorPropagation::kDelayed;
      c.error_propagation_delay = 0.05;
      c.couple_slave_to_actual_values = true;
    }
  });
  const uint16_t gear = rig.post(1, gr::gear_in(0, 0.5));
  rig.cycles(1);
  REQUIRE(rig.answer(1, gear).state == CommandState::kReached);
  rig.post(0, kt::move_absolute(30.0, 146.0));
  rig.cycles(120);
  const double v0 = rig.at(0).NcToPlc.SetVelo;
  REQUIRE(v0 > 100.0);

  // A list on the slave while it moves: 70200 on the slave, the group's on the master.
  plc::hli::HLI_AX_COUPLING_COMMAND& command =
      rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.command_w;
  command.desc[0] = {rig.kernel.config("A1").id, plc::hli::HLI_AXIS_COUPLING_MIRROR, 0, 0};
  command.desc[1] = {};
  command.semaphor_rw = true;
  rig.cycles(1);
  const uint32_t k70200 = plc::to_id(plc::ErrorCode::kHliChangeWhileMoving);
  REQUIRE(rig.at(1).NcToPlc.ErrorCode == k70200);
  REQUIRE(rig.at(0).NcToPlc.ErrorCode == k70200);

  // The master's set values go down its ramp, continuous, within its emergency deceleration.
  const nc::AxisConfig& master = rig.kernel.config("A0");
  double v = rig.at(0).NcToPlc.SetVelo;
  double p = rig.at(0).NcToPlc.SetPos;
  CHECK(v > 0.9 * v0);
  int cycles = 0;
  while (rig.at(0).NcToPlc.SetVelo != 0.0 && cycles < 5000) {
    rig.cycles(1);
    ++cycles;
    const plc::NCTOPLC_AXIS_REF& n = rig.at(0).NcToPlc;
    REQUIRE(n.SetVelo <= v);    // never faster again
    REQUIRE(n.SetVelo >= 0.0);  // nor backwards
    REQUIRE(n.SetVelo >= v - 0.001 * master.emergency_deceleration * 1.000001);  // 1 ms cycle
    REQUIRE(std::abs(n.SetAcc) <= master.emergency_deceleration * 1.000001);
    REQUIRE(n.SetPos >= p);  // no step back
    v = n.SetVelo;
    p = n.SetPos;
  }
  REQUIRE(cycles < 5000);
  CHECK(cycles > 5);  // a ramp, not a jump to 0
}
