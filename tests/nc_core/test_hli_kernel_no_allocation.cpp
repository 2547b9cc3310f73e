// No allocation per NC cycle with HLI lists in force: a counting operator new over 6000 ticks of
// 8 axes (4 targets with DIRECT / MIRROR / FRACT / self lists, every axis moving back and forth
// with its blocks, lists re-taken while at rest), counts 0. Plain build only.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "counting_allocator.hpp"
#include "hli_kernel_rig.hpp"

using namespace hlik;

TEST_CASE("6000 ticks of 8 axes with HLI lists in force allocate nothing", "[no_allocation]") {
  std::vector<nc::AxisConfig> configs;
  for (int i = 0; i < 8; ++i)
    configs.push_back(axis(i + 1, "axis" + std::to_string(i)));
  configs[5].sw_limit_max_enabled = true;  // a FRACT target watched for 70195
  configs[5].sw_limit_max = 1e6;
  Rig rig(configs);
  REQUIRE(rig.couple(
      4, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}, {5, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  REQUIRE(rig.couple(
      5, {{2, h::HLI_AXIS_COUPLING_FRACT, -5, 9}, {3, h::HLI_AXIS_COUPLING_MIRROR, 0, 0}}));
  REQUIRE(rig.couple(6, {{1, h::HLI_AXIS_COUPLING_ZERO, 0, 0}}));
  REQUIRE(rig.couple(
      7, {{5, h::HLI_AXIS_COUPLING_FRACT, 3, 2}, {8, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));

  ca::g_allocations = 0;
  ca::g_counting = true;
  int taken = 0;
  for (int n = 0; n < 6000; ++n) {
    const int phase = n % 1500;
    for (std::size_t i = 0; i < 8; ++i) {
      fb::MC_MoveAbsolute& m = rig.move[i];
      m.Position = (n / 1500) % 2 == 0 ? 100.0 + 10.0 * static_cast<double>(i) : 0.0;
      m.Velocity = 1500.0;
      m.Execute = phase > 10 && phase < 1400;
    }
    // At rest between the moves: target 4's list is taken again (its semaphore handshake).
    fb::HLI_AxisCoupling& c = rig.coupling[4];
    c.Execute = phase >= 1420 && phase < 1440;
    if (c.Done && phase == 1430) ++taken;
    rig.tick();
  }
  ca::g_counting = false;
  CHECK(ca::g_allocations == 0);
  CHECK(taken == 4);
  for (std::size_t i = 0; i < 8; ++i)
    CHECK(rig.error(i) == 0);
}

TEST_CASE("Targets losing their lists (axis error, enable off) and refused lists allocate nothing",
          "[no_allocation]") {
  Rig rig({axis(1, "X"), axis(8, "Y2"), axis(9, "Z")});
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  REQUIRE(rig.couple(2, {{1, h::HLI_AXIS_COUPLING_MIRROR, 0, 0}}));
  rig.start_move(0, 900.0);
  rig.ticks(300);

  ca::g_allocations = 0;
  ca::g_counting = true;
  // Y2's list taken again while axis 1 moves: 70200, Y2 brakes.
  rig.kernel.gpAx()[1]->lr_mc_control.axis_coupling.command_w.semaphor_rw = true;
  rig.tick();
  rig.power[2].Enable = false;  // Z's drive off while it moves: 0x4356, list off
  rig.ticks(2);
  rig.kernel.gpAx()[2]->lr_mc_control.axis_coupling.command_w.semaphor_rw = true;  // refused
  rig.ticks(1500);
  ca::g_counting = false;
  CHECK(ca::g_allocations == 0);
  CHECK(rig.error(1) == 70200);
  CHECK(rig.error(2) == 0x4356);
  CHECK(rig.kernel.gpAx()[2]->lr_mc_control.axis_coupling.state_r.error_r == 0x4F06);
  CHECK(rig.axes[0]->NcToPlc.CoupleState == 0);
}
