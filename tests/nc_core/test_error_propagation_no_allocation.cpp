// No allocation per cycle in SPEC C7 / C8 (brief): a counting operator new over a DELAYED error
// with its local reaction, an MC_GearOut during the delay, the group reaction, resets and the
// release of the slave that left; and over a head master pushed by hand with its group following
// its actual values — 0 allocations. Runs only in the plain build (the sanitizers own the
// allocator).
#include <catch2/catch.hpp>

#include "counting_allocator.hpp"
#include "propagation_rig.hpp"

TEST_CASE("delayed error propagation and its group reaction allocate nothing",
          "[propagation][no_allocation]") {
  pr::Group g(4, [](std::size_t i, nc::AxisConfig& c) {
    if (i == 1) {
      pr::slow_drive(c);
      pr::delayed(c, 0.3);
      c.couple_slave_to_actual_values = true;
    }
  });
  ca::g_allocations = 0;
  ca::g_counting = true;
  g.post(1, gr::gear_in(0, 1.0));
  g.post(2, gr::gear_in(0, 0.5));
  g.post(3, gr::gear_in(1, 2.0));
  g.cycles(1);
  g.post(0, kt::move_absolute(20000.0, 1000.0));
  const int k = g.until_error(1);
  g.cycles(100);
  g.post(2, gr::gear_out());
  g.cycles(400);
  for (std::size_t a = 0; a < 4; ++a)
    g.post(a, kt::simple(plc::CommandType::kReset));
  g.cycles(1);
  g.post(1, gr::gear_out());
  g.cycles(10);
  ca::g_counting = false;

  CHECK(ca::g_allocations == 0);
  CHECK(k > 0);
  CHECK(g.at(1).NcToPlc.CoupleState == 1U);  // released; still A3's master
}

TEST_CASE("a head master pushed by hand with its group following allocates nothing",
          "[actual_values][no_allocation]") {
  pr::Group g(3, [](std::size_t i, nc::AxisConfig& c) {
    if (i == 0) c.couple_slave_to_actual_values = true;
  });
  ca::g_allocations = 0;
  ca::g_counting = true;
  g.post(1, gr::gear_in(0, 2.0));
  g.post(2, gr::gear_in(1, -1.0));
  g.cycles(2);
  kt::set_enables(g.at(0), false);
  g.cycles(1);
  const plc::ErrorCode pushed = g.kernel.push_by_hand(0, 100.0);
  g.cycles(500);
  (void)g.kernel.push_by_hand(0, 0.0);
  g.cycles(100);
  kt::set_enables(g.at(0), true);
  g.cycles(10);
  ca::g_counting = false;

  CHECK(ca::g_allocations == 0);
  CHECK(pushed == plc::ErrorCode::kNone);
  CHECK(g.at(2).NcToPlc.SetPos == Approx(-100.0).margin(0.05));
}
