// Determinism with couplings (SPEC A2, issue 9): two kernels given the same script — a cascade
// coupled at rest, a master move, a slave compensation, a factor change, online decoupling of the
// middle axis, a new end position, an override change, a stop and a group error with its resets —
// publish bit-identical NC→PLC images at every cycle.
#include <catch2/catch.hpp>

#include <cstddef>
#include <functional>
#include <vector>

#include "gear_rig.hpp"

TEST_CASE("runs with couplings, decoupling, compensation and group errors are bit-identical",
          "[gear][determinism]") {
  const std::vector<gr::Step<gr::Rig>> script = {
      {0, [](gr::Rig& r) { r.post(1, gr::gear_in(0, 0.75)); }},
      {1, [](gr::Rig& r) { r.post(2, gr::gear_in(1, -0.5)); }},
      {1, [](gr::Rig& r) { r.post(3, gr::gear_in(0, 1.0 / 3.0)); }},
      {3, [](gr::Rig& r) { r.post(0, kt::move_absolute(20000.0, 2000.0)); }},
      {700,
       [](gr::Rig& r) {
         r.post(1, kt::move_superimposed(200.0, 300.0, 500.0, 1000.0, 1500.0, 3000.0));
       }},
      {1500, [](gr::Rig& r) { r.post(3, gr::gear_in(0, 0.4)); }},
      {2000, [](gr::Rig& r) { r.post(1, gr::gear_out()); }},
      {2100, [](gr::Rig& r) { r.post(1, kt::new_pos(r.at(1).NcToPlc.SetPos + 1000.0)); }},
      {2300, [](gr::Rig& r) { kt::set_override(r.at(0), 40.0); }},
      {3000, [](gr::Rig& r) { kt::set_enables(r.at(3), true, false, true); }},  // group error
      {3600,
       [](gr::Rig& r) {
         kt::set_enables(r.at(3), true);
         for (std::size_t a : {0U, 3U})
           r.post(a, kt::simple(plc::CommandType::kReset));
       }},
      {3700, [](gr::Rig& r) { r.post(0, kt::move_absolute(0.0, 1500.0)); }},
  };
  gr::Rig a(4);
  gr::Rig b(4);
  bool group_error_seen = false;
  CHECK(gr::first_difference(script, a, b, 6000, [&](gr::Rig& r) {
          group_error_seen = group_error_seen || r.at(0).NcToPlc.ErrorCode != 0U;
        }) == -1);
  CHECK(group_error_seen);
  CHECK(a.at(1).NcToPlc.CoupleState == 1U);  // decoupled, still Slave2's master
  CHECK(a.at(3).NcToPlc.CoupleState == 3U);
}
