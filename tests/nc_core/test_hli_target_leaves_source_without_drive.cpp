// K26 (docs/reliability.md, docs/behaviour.md "HLI axis coupling"): an HLI target whose source's
// drive goes off under the source's program motion — the source loses its controller enable
// while its set values move — leaves its list and brakes on its emergency ramp with 0x4260,
// instead of following the source's program position, which from then on follows its actual one
// (before: Y2's drive went from 1000 mm/s to 0 in one cycle behind an ideal drive, and behind a
// lagging one it jumped back by the source's following error).
#include <catch2/catch.hpp>

#include "brake_watch.hpp"
#include "hli_kernel_rig.hpp"

using namespace hlik;

namespace {

// Y2 (index 1, logical 8) follows X (index 0) DIRECT without a self entry; X moves towards
// 2000 mm at 1000 mm/s for 400 ticks, so Y2's drive runs at 1000 mm/s. `lag`: X's drive is a
// first-order lag of 5 ms.
Rig cruising(bool lag) {
  nc::AxisConfig x = axis(1, "X");
  if (lag) {
    x.drive_model = nc::DriveModel::kFirstOrderLag;
    x.drive_time_constant = 0.005;
  }
  Rig rig({x, axis(8, "Y2")});
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  rig.start_move(0, 2000.0, 1000.0);
  rig.ticks(400);
  REQUIRE(rig.axes[1]->NcToPlc.SetVelo == Approx(1000.0));
  return rig;
}

// Y2's drive (axis 1) over `n` ticks after X's enable went.
kt::BrakeWatch watch_target(Rig& rig, int n) {
  return kt::watch_brake(*rig.axes[1], n, [&rig] { rig.tick(); });
}

}  // namespace

TEST_CASE("an HLI target whose source's drive goes off brakes on its emergency ramp, 0x4260",
          "[hli][kernel][k26]") {
  Rig rig = cruising(false);
  const double a = rig.kernel.config("Y2").emergency_deceleration;  // 10000 mm/s²
  rig.power[0].Enable = false;
  const kt::BrakeWatch b = watch_target(rig, 300);
  CHECK(rig.error(1) == 0x4260U);
  CHECK_FALSE(rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.state_r.active_r);
  // The stage's brake: a constant deceleration, a * T = 10 mm/s per cycle, from 1000 mm/s to
  // rest in 100 cycles, and no reversal.
  CHECK(b.largest_step <= a * 0.001 + 1e-9);
  CHECK(b.cycles_to_rest == 100);
  CHECK(b.lowest_actual >= -1e-3);
  CHECK(b.last_set == 0.0);
}

TEST_CASE("an HLI target behind a lagging source drive that goes off does not jump back",
          "[hli][kernel][k26]") {
  Rig rig = cruising(true);
  REQUIRE(rig.axes[0]->NcToPlc.PosDiff > 1.0);  // what the target would have jumped back by
  rig.power[0].Enable = false;
  const kt::BrakeWatch b = watch_target(rig, 300);
  CHECK(rig.error(1) == 0x4260U);
  CHECK(b.largest_step <= 10.0 + 1e-9);
  CHECK(b.lowest_actual >= -1e-3);
  CHECK(b.last_set == 0.0);
}

TEST_CASE("an HLI target keeps its list when a source at rest loses its enable",
          "[hli][kernel][k26]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  rig.power[0].Enable = false;
  rig.ticks(5);
  CHECK(rig.error(1) == 0U);
  CHECK(rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.state_r.active_r);
}
