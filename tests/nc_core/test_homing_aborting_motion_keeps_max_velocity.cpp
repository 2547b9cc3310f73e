// A default homing that aborts a hard-accelerating motion, and a command that aborts such a
// homing, keep the axis's max velocity (fuzz finding K8, docs/behaviour.md "Homing"): the homing
// starts from the set state with the aborted motion's larger jerk where its own would ramp the
// acceleration down too slowly (v + a·|a| / 2J above the max velocity), as a move does (K4); and
// a running homing counts as the running motion for what aborts it (a move, MC_Halt, MC_Stop,
// the error ramp), so they take over its jerk in turn.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "homing_rig.hpp"

namespace {

// Homing axis (max velocity 2200 mm/s, A 5000 mm/s², J 50000 mm/s³, homing 100 mm/s towards the
// cam at 100 … 110 mm; here far away so that the homing only runs towards it). A positioning at
// 2200 mm/s with A 20000 and J 1e6 until v >= 1700 mm/s (a = 20000 mm/s² there), then MC_Home.
struct Run {
  kt::Harness h{far_cam_axis()};
  uint16_t home = 0;
  double v0 = 0.0, a0 = 0.0;  // the set state the homing starts from

  static nc::AxisConfig far_cam_axis() {
    nc::AxisConfig c = kt::homing_axis();
    c.homing_cam_position = 90000.0;
    c.homing_search_distance = 95000.0;
    return c;
  }
  Run() {
    h.post(kt::move_absolute(100000.0, 2200.0, 20000.0, 20000.0, 1e6));
    REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetVelo >= 1700.0; }, 1000) > 0);
    REQUIRE(h.x->NcToPlc.SetAcc == Approx(20000.0));
    v0 = h.x->NcToPlc.SetVelo;
    a0 = h.x->NcToPlc.SetAcc;
    home = h.post(kt::home(plc::MC_DefaultHoming));
  }
  // The highest |SetVelo| in the next `n` cycles.
  double peak(int n) {
    double p = 0.0;
    for (int i = 0; i < n; ++i) {
      kt::cam_cycle(h);
      p = std::max(p, std::abs(h.x->NcToPlc.SetVelo));
    }
    return p;
  }
};

}  // namespace

TEST_CASE("a default homing aborting a hard acceleration keeps Vmax and reaches its velocity",
          "[homing][starts]") {
  Run r;
  // With its own J 50000 the acceleration of 20000 would add 20000² / (2·50000) = 4000 mm/s
  // (5700 mm/s); with the aborted move's J 1e6 it adds 200 (at most 1900 mm/s).
  const double peak = r.peak(3000);
  CHECK(peak == Approx(r.v0 + r.a0 * r.a0 / (2.0 * 1e6)).margin(1.0));
  CHECK(peak <= 2200.0);
  CHECK(r.h.state_of(r.home) == plc::CommandState::kActive);
  CHECK(kt::bit(*r.h.x, plc::kStateHomingBusy));
  CHECK(r.h.x->NcToPlc.SetVelo == Approx(100.0));
}

TEST_CASE("a move aborting a homing that still brings back a hard acceleration keeps Vmax",
          "[homing][starts]") {
  Run r;
  r.h.cycles(1);  // the homing runs; a is still near 20000 mm/s²
  REQUIRE(r.h.x->NcToPlc.SetAcc > 15000.0);
  const uint16_t n = r.h.post(kt::move_velocity(500.0, 1));  // its own J 50000
  CHECK(r.peak(5000) <= 2200.0);
  CHECK(r.h.state_of(r.home) == plc::CommandState::kAborted);
  CHECK(r.h.state_of(n) == plc::CommandState::kReached);
}

TEST_CASE("MC_Halt and MC_Stop aborting such a homing keep Vmax", "[homing][starts]") {
  for (const plc::CommandType type : {plc::CommandType::kHalt, plc::CommandType::kStop}) {
    Run r;
    r.h.cycles(1);
    REQUIRE(r.h.x->NcToPlc.SetAcc > 15000.0);
    const uint16_t n = r.h.post(kt::simple(type));  // 0: the running motion's D and J
    CHECK(r.peak(5000) <= 2200.0);
    CHECK(r.h.x->NcToPlc.SetVelo == 0.0);
    CHECK(r.h.state_of(r.home) == plc::CommandState::kAborted);
    CHECK(r.h.state_of(n) == plc::CommandState::kDone);
  }
}

TEST_CASE("the error ramp of such a homing keeps Vmax", "[homing][starts]") {
  Run r;
  r.h.cycles(1);
  REQUIRE(r.h.x->NcToPlc.SetAcc > 15000.0);
  kt::set_enables(*r.h.x, true, false, true);  // the feed enable of the direction of travel lost
  CHECK(r.peak(5000) <= 2200.0);
  CHECK(r.h.state_of(r.home) == plc::CommandState::kError);
  CHECK(r.h.x->NcToPlc.SetVelo == 0.0);
}
