// Seed 002 §2: an INACTIVE entry ends the list (the 4-row table), the kernel resets semaphor_rw
// in the cycle it evaluates the list, state_r shows the couplings in force, active_rev_r is the
// command velocity in 1e-3 mm/s.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <vector>

#include "hli_stage_rig.hpp"

using namespace hlitest;

namespace {
// Seed's table: X2 target; X2 DIRECT, X DIRECT, Y inactive, Z DIRECT (inactive as well).
constexpr int kX = 1, kY = 2, kZ = 3, kX2 = 4;
constexpr std::size_t kTarget = 3;
}  // namespace

TEST_CASE("coupling 3 inactive makes coupling 4 inactive: state_r lists exactly 1 and 2", "[hli]") {
  Rig rig({kX, kY, kZ, kX2});
  rig.command(kTarget,
              {direct(kX2), direct(kX), {kY, h::HLI_AXIS_COUPLING_INACTIVE, 0, 0}, direct(kZ)});
  rig.cycle();
  const h::HLI_AX_COUPLING_STATE& s = rig.unit(kTarget).state_r;
  REQUIRE(s.error_r == 0);
  CHECK(s.active_r);
  CHECK(s.desc[0].ax_nr == kX2);
  CHECK(s.desc[0].mode == h::HLI_AXIS_COUPLING_DIRECT);
  CHECK(s.desc[1].ax_nr == kX);
  CHECK(s.desc[1].mode == h::HLI_AXIS_COUPLING_DIRECT);
  for (std::size_t i = 2; i < s.desc.size(); ++i) {
    CHECK(s.desc[i].ax_nr == 0);
    CHECK(s.desc[i].mode == h::HLI_AXIS_COUPLING_INACTIVE);
  }
  // Z moves: coupling 4 is not in force.
  rig.move(2, 50.0, 500.0);
  CHECK(rig.d[kTarget] == 0.0);
  rig.move(0, 20.0, 500.0);
  CHECK(rig.d[kTarget] == Approx(20.0).margin(1e-9));
}

TEST_CASE("the semaphore is reset in the cycle that evaluates the list", "[hli]") {
  Rig rig({1, 2});
  rig.cycle();
  CHECK_FALSE(rig.unit(1).state_r.active_r);
  rig.command(1, {direct(1), inactive()});
  CHECK(rig.unit(1).command_w.semaphor_rw);
  rig.cycle();
  CHECK_FALSE(rig.unit(1).command_w.semaphor_rw);
  CHECK(rig.unit(1).state_r.active_r);
  CHECK(rig.unit(1).state_r.desc[0].ax_nr == 1);
  // Without the semaphore a list written into command_w is not evaluated.
  rig.unit(1).command_w.desc[0] = inactive();
  rig.cycles(3);
  CHECK(rig.unit(1).state_r.active_r);
  // A refused list also resets the semaphore.
  rig.command(1, {fract(1, 1, 0)});
  rig.cycle();
  CHECK_FALSE(rig.unit(1).command_w.semaphor_rw);
  CHECK(rig.unit(1).state_r.error_r == 70396);
}

TEST_CASE("active_rev_r is the drive's command velocity in 1e-3 mm/s", "[hli]") {
  Rig rig({1, 2});
  rig.command(1, {fract(1, 3, 2), inactive()});
  rig.cycle();
  rig.q[0] += 0.1234;
  rig.qv[0] = 123.4;
  rig.cycle();
  CHECK(rig.active_rev_r(0) == 123400);
  CHECK(rig.active_rev_r(1) == 185100);  // 1.5 · 123.4 mm/s
  rig.qv[0] = 0.0;
  rig.cycle();
  CHECK(rig.active_rev_r(1) == 0);
}

TEST_CASE("gpAx is indexed by axis index; ax_nr is the logical number", "[hli]") {
  Rig rig({8, 1});
  REQUIRE(rig.stage.gpAx().size() == 2);
  CHECK(rig.stage.index_of(8) == 0);
  CHECK(rig.stage.index_of(1) == 1);
  CHECK(rig.stage.index_of(5) == nc::hli::HliStage::kNoAxis);
  rig.command(0, {direct(1), inactive()});  // axis index 0 (number 8) follows number 1
  rig.cycle();
  rig.move(1, 12.0, 100.0);
  CHECK(rig.d[0] == Approx(12.0).margin(1e-9));
  // A cycle with inputs of the wrong size does nothing.
  std::vector<double> one(1, 0.0);
  bool ref = false;
  CHECK_FALSE(rig.stage.cycle(nc::hli::Inputs{one, one, one, {&ref, 1}},
                              nc::hli::Outputs{rig.d, rig.dv, rig.da, rig.stop}));
}

TEST_CASE("axes added while a list is in force keep the list; new axes are free", "[hli]") {
  nc::hli::HliStage stage(kT);  // no reserve: the matrix grows as axes are added
  for (int nr : {1, 2})
    stage.add_axis(nc::hli::AxisSetup{nr});
  stage.gpAx()[1]->lr_mc_control.axis_coupling.command_w.desc[0] = fract(1, 3, 2);
  stage.gpAx()[1]->lr_mc_control.axis_coupling.command_w.semaphor_rw = true;
  std::vector<double> q(2, 0.0), v(2, 0.0), d(2, 0.0), dv(2, 0.0), da(2, 0.0);
  bool ref[8] = {};
  std::vector<plc::ErrorCode> stop(2);
  REQUIRE(stage.cycle({q, v, v, {ref, 2}}, {d, dv, da, stop}));
  for (int nr : {3, 4, 5, 6, 7})
    stage.add_axis(nc::hli::AxisSetup{nr});
  CHECK(stage.factor(1, 0) == 1.5);
  CHECK(stage.factor(6, 6) == 1.0);
  CHECK(stage.factor(1, 6) == 0.0);
  CHECK_THROWS_AS(stage.add_axis(nc::hli::AxisSetup{3}), std::invalid_argument);
  CHECK_THROWS_AS(stage.add_axis(nc::hli::AxisSetup{0}), std::invalid_argument);
  q.assign(7, 0.0);
  v.assign(7, 0.0);
  d.assign(7, 0.0);
  dv.assign(7, 0.0);
  da.assign(7, 0.0);
  stop.assign(7, plc::ErrorCode::kNone);
  q[0] = 4.0;
  q[6] = 2.0;
  REQUIRE(stage.cycle({q, v, v, {ref, 7}}, {d, dv, da, stop}));
  CHECK(d[1] == Approx(6.0).margin(1e-9));
  CHECK(d[6] == 2.0);
}
