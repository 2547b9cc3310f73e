// No allocation per cycle with couplings (brief; SPEC C1, C3): a counting operator new over
// coupling, 20 master moves (0 <-> 300 mm) with a cascade and a star following, and uncoupling — 0
// allocations. Runs only in the plain build (the sanitizers own the allocator).
#include <catch2/catch.hpp>

#include "counting_allocator.hpp"
#include "gear_rig.hpp"

TEST_CASE("couplings, their following and their uncoupling allocate nothing",
          "[gear][no_allocation]") {
  gr::Rig rig(5);  // cascade 0 -> 1 -> 2, star 0 -> {1, 3}, 4 -> 0 on top
  plc::Command moves[2] = {kt::move_absolute(300.0, 2000.0), kt::move_absolute(0.0, 2000.0)};

  ca::g_allocations = 0;
  ca::g_counting = true;
  rig.post(1, gr::gear_in(0, 0.75));
  rig.post(2, gr::gear_in(1, -0.5));
  rig.post(3, gr::gear_in(0, 2.0));
  rig.post(0, gr::gear_in(4, 1.0));
  rig.cycles(1);
  for (int k = 0; k < 20; ++k) {
    rig.post(4, moves[k % 2]);
    rig.cycles(700);  // each move ends (0.5 s)
  }
  for (std::size_t s = 0; s < 4; ++s)
    rig.post(s, gr::gear_out());
  rig.cycles(10);
  ca::g_counting = false;

  CHECK(ca::g_allocations == 0);
  CHECK(rig.at(2).NcToPlc.CoupleState == 0U);
  CHECK(rig.at(2).NcToPlc.SetPos == 0.0);  // back where it was coupled
  CHECK(rig.kernel.couplings().revision() >= 8);
}

TEST_CASE("online decoupling, and the stop and new end position after it, allocate nothing",
          "[gear][decouple][no_allocation]") {
  gr::Rig rig(4);  // cascade 0 -> 1 -> 2 and 0 -> 3
  rig.post(1, gr::gear_in(0, 0.75));
  rig.post(2, gr::gear_in(1, -0.5));
  rig.post(3, gr::gear_in(0, 2.0 / 3.0));
  rig.cycles(1);

  ca::g_allocations = 0;
  ca::g_counting = true;
  rig.post(0, kt::move_absolute(20000.0, 2000.0));
  rig.cycles(600);
  rig.post(1, gr::gear_out());  // the middle of the cascade: 2 now follows 1
  rig.cycles(100);
  rig.post(2, gr::gear_out());
  rig.post(3, gr::gear_out());
  rig.cycles(1);
  rig.post(3, kt::new_pos(rig.at(3).NcToPlc.SetPos - 500.0));  // against the direction
  rig.post(1, kt::simple(plc::CommandType::kStop));
  kt::set_override(rig.at(2), 50.0);
  rig.cycles(2000);
  ca::g_counting = false;

  CHECK(ca::g_allocations == 0);
  for (std::size_t a = 1; a < 4; ++a)
    CHECK(rig.at(a).NcToPlc.CoupleState == 0U);
  CHECK(rig.at(1).NcToPlc.SetVelo == 0.0);
  CHECK(rig.at(2).NcToPlc.SetVelo == Approx(-0.5 * 0.75 * 0.5 * 2000.0).epsilon(1e-12));
  CHECK(rig.at(3).NcToPlc.SetVelo == 0.0);
}
