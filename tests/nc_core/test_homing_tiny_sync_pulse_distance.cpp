// A sync pulse distance far below the position's resolution (fuzz finding K9: the smallest
// denormal, 4.9e-324 mm, which the configuration takes as >= 0) made the pulse index of the cam
// edge overflow, the reference position infinite and the set position inf. Such a pulse grid
// puts the next pulse within rounding of the edge, so the edge is the reference, as with no sync
// pulse (docs/behaviour.md "Homing").
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "homing_rig.hpp"

namespace {

// Default homing (cam 100 … 110 mm from 0, Position 0) with this sync pulse distance, run to its
// outcome; the axis's final state.
struct Result {
  plc::CommandState state;
  double set_pos, act_pos;
};

Result home_with_pulse_distance(double distance) {
  nc::AxisConfig c = kt::homing_axis();
  c.homing_sync_pulse_distance = distance;
  kt::Harness h(c);
  const uint16_t n = h.post(kt::home(plc::MC_DefaultHoming, 0.0));
  for (int i = 0; i < 20000; ++i) {
    kt::cam_cycle(h);
    const plc::CommandState s = h.state_of(n);
    if (s == plc::CommandState::kDone || s == plc::CommandState::kError) break;
  }
  return {h.state_of(n), h.x->NcToPlc.SetPos, h.x->NcToPlc.ActPos};
}

}  // namespace

TEST_CASE("a denormal sync pulse distance homes on the cam edge like no pulse",
          "[homing][default]") {
  const Result edge = home_with_pulse_distance(0.0);
  REQUIRE(edge.state == plc::CommandState::kDone);
  for (const double tiny : {std::numeric_limits<double>::denorm_min(), 1e-300}) {
    const Result r = home_with_pulse_distance(tiny);
    CHECK(r.state == plc::CommandState::kDone);
    CHECK(std::isfinite(r.set_pos));
    CHECK(r.set_pos == edge.set_pos);
    CHECK(r.act_pos == edge.act_pos);
  }
  // A fine but resolvable grid still takes the pulse beyond the edge: seen one cycle later, so
  // the axis stops one cycle's travel at the off-cam velocity (10 mm/s × 1 ms) further on.
  const Result fine = home_with_pulse_distance(1e-6);
  CHECK(fine.state == plc::CommandState::kDone);
  CHECK(fine.set_pos != edge.set_pos);
  CHECK(fine.set_pos == Approx(edge.set_pos - 0.01).margin(1e-4));
}
