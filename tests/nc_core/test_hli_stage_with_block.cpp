// The PLC side and the NC side of the HLI control unit together: fb::HLI_AxisCoupling writes the
// seed's example 3 through gpAx[i] (PLC before NC in a tick, as the cycle driver runs them), the
// stage takes it in its next cycle; a refused list shows the stage's ID at the block.
#include <catch2/catch.hpp>

#include "fb/hli_axis_coupling.hpp"
#include "hli_stage_rig.hpp"

using namespace hlitest;

TEST_CASE("HLI_AxisCoupling and the stage: Done one tick after the edge, then Y2 follows",
          "[hli]") {
  Rig rig({1, 8});
  auto gpAx = rig.stage.gpAx();
  fb::HLI_AxisCoupling coupling;
  coupling.desc[0] = {8, h::HLI_AXIS_COUPLING_DIRECT, 0, 0};
  coupling.desc[1] = {1, h::HLI_AXIS_COUPLING_FRACT, -5, 9};
  coupling.Execute = true;
  coupling(gpAx[1]);
  rig.cycle();
  coupling(gpAx[1]);
  CHECK(coupling.Done);
  CHECK(gpAx[1]->lr_mc_control.axis_coupling.state_r.active_r);
  rig.move(0, 900.0, 1000.0);
  CHECK(rig.d[1] == Approx(-500.0).margin(1e-9));

  fb::HLI_AxisCoupling bad;
  bad.desc[0] = {1, h::HLI_AXIS_COUPLING_FRACT, 3, 0};
  bad.Execute = true;
  bad(gpAx[1]);
  rig.cycle();
  bad(gpAx[1]);
  CHECK(bad.Error);
  CHECK(bad.ErrorID == 70396);
  rig.move(0, -9.0, 1000.0);  // the list in force stays
  CHECK(rig.d[1] == Approx(-495.0).margin(1e-9));
}
