// Cyclic slaves in the real-time cycle (SPEC A2, C6; issue 10): a script of a cyclic slave under a
// linear slave (cascade 0 -> 1 -> 2, 2 cyclic), its factor following a PLC sine and a step, a
// refused GearRatio1, the master moving and stopping, the cyclic slave decoupled in motion and
// coupled again at rest — run with a counting operator new (0 allocations from the first coupling
// on) and twice side by side (bit-identical NC→PLC images at every cycle).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>

#include "counting_allocator.hpp"
#include "gear_dyn_rig.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

// One cycle of the script: what the PLC writes and posts before NC cycle `k`.
void script(gr::Rig& r, int k) {
  if (k == 0) {
    r.post(1, gr::gear_in(0, 2.0));
    r.at(2).PlcToNc.GearRatio1 = 0.5;
    r.post(2, gd::gear_in_dyn(1, 0.5, 12000.0));
  }
  if (k == 2) r.post(0, kt::move_absolute(3000.0, 800.0));
  if (k >= 2 && k < 1500) r.at(2).PlcToNc.GearRatio1 = 0.5 + 0.1 * std::sin(2.0 * kPi * 0.002 * k);
  if (k == 1500) r.at(2).PlcToNc.GearRatio1 = std::nan("");  // not taken: warning 0x4F81
  if (k == 1600) r.at(2).PlcToNc.GearRatio1 = -0.4;
  if (k == 2200) r.post(2, gr::gear_out());  // online: it goes on as a master
  if (k == 2300) r.post(2, kt::simple(plc::CommandType::kStop));
  if (k == 6000) {
    r.post(2, kt::simple(plc::CommandType::kStopRelease));
    r.post(2, kt::simple(plc::CommandType::kReset));
  }
  if (k == 6001) {
    r.at(2).PlcToNc.GearRatio1 = 1.0;
    r.post(2, gd::gear_in_dyn(0, 1.0, 5000.0));  // both at rest again
  }
}

}  // namespace

TEST_CASE("a cyclic slave's cycle allocates nothing", "[gear][cyclic][no_allocation]") {
  gr::Rig rig(3);
  ca::g_allocations = 0;
  ca::g_counting = true;
  for (int k = 0; k < 6100; ++k) {
    script(rig, k);
    rig.kernel.cycle();
  }
  ca::g_counting = false;
  CHECK(ca::g_allocations == 0);
  CHECK(rig.at(2).NcToPlc.CoupleState == 3U);  // coupled again, to axis 0
  CHECK(rig.at(2).NcToPlc.GearRatio == 1.0);
}

TEST_CASE("runs with a cyclic slave are bit-identical", "[gear][cyclic][determinism]") {
  gr::Rig a(3);
  gr::Rig b(3);
  bool decoupled_moving = false;
  for (int k = 0; k < 6100; ++k) {
    script(a, k);
    script(b, k);
    a.kernel.cycle();
    b.kernel.cycle();
    for (std::size_t i = 0; i < 3; ++i)
      REQUIRE(kt::same_image(a.at(i).NcToPlc, b.at(i).NcToPlc));
    if (k == 2201)
      decoupled_moving = a.at(2).NcToPlc.CoupleState == 0U && a.at(2).NcToPlc.SetVelo != 0.0;
  }
  CHECK(decoupled_moving);
}
