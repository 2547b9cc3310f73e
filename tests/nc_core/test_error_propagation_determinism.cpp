// Determinism with error propagation and actual-value coupling (SPEC A2, C7, C8): two kernels
// given the same script — a DELAYED error with a faulty slave coupling its own slave by actual
// values, an MC_GearOut during the delay, the group reaction, resets, the release of the slave
// that left, then a head master pushed by hand — publish bit-identical NC→PLC images at every
// cycle.
#include <catch2/catch.hpp>

#include <cstddef>
#include <functional>
#include <vector>

#include "propagation_rig.hpp"

namespace {

void tune(std::size_t i, nc::AxisConfig& c) {
  c.couple_slave_to_actual_values = true;
  if (i == 1) {
    pr::slow_drive(c);
    pr::delayed(c, 0.4);
  }
}

}  // namespace

TEST_CASE("runs with delayed propagation and actual-value coupling are bit-identical",
          "[propagation][determinism]") {
  const std::vector<gr::Step<pr::Group>> script = {
      {0, [](pr::Group& g) { g.post(1, gr::gear_in(0, 1.0)); }},
      {0, [](pr::Group& g) { g.post(2, gr::gear_in(0, 0.5)); }},
      {0, [](pr::Group& g) { g.post(3, gr::gear_in(1, 2.0)); }},
      {2, [](pr::Group& g) { g.post(0, kt::move_absolute(20000.0, 1000.0)); }},
      {900, [](pr::Group& g) { g.post(2, gr::gear_out()); }},
      {2500,
       [](pr::Group& g) {
         for (std::size_t a = 0; a < 4; ++a)
           g.post(a, kt::simple(plc::CommandType::kReset));
       }},
      {2501, [](pr::Group& g) { g.post(1, gr::gear_out()); }},
      {2600, [](pr::Group& g) { g.post(3, gr::gear_out()); }},
      {2601, [](pr::Group& g) { g.post(3, gr::gear_in(0, 1.5)); }},
      {2700, [](pr::Group& g) { kt::set_enables(g.at(0), false); }},
      {2701, [](pr::Group& g) { (void)g.kernel.push_by_hand(0, -300.0); }},
      {3200, [](pr::Group& g) { (void)g.kernel.push_by_hand(0, 0.0); }},
  };
  pr::Group a(4, tune);
  pr::Group b(4, tune);
  bool delayed_seen = false;
  CHECK(gr::first_difference(script, a, b, 3600, [&](pr::Group& g) {
          delayed_seen = delayed_seen || g.delayed_bit(1);
        }) == -1);
  CHECK(delayed_seen);
  CHECK(a.at(3).NcToPlc.SetVelo == 0.0);
  CHECK(a.at(3).NcToPlc.SetPos != 0.0);  // it followed the push
}
