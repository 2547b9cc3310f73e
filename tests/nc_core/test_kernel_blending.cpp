// A start while the axis moves begins from the current set state (p, v, a): the set values go
// on without a jump in position, velocity or acceleration (seed 000 §2.1; the planner takes any
// start state), whatever the new command is.
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandType;

namespace {

// Between two cycles the set values may change only as the limits allow: |Δa| <= J·T and the
// velocity and position by what the (bounded) acceleration and velocity give.
void check_continuous(kt::Harness& h, const plc::Command& replacement, int cycles_before) {
  const double T = 0.001;
  const double J = 200000.0;  // largest jerk used below
  const double A = 20000.0;   // largest acceleration / deceleration used below
  const double V = 2200.0;
  h.post(kt::move_absolute(2000.0, 2000.0));
  h.cycles(cycles_before);
  kt::Sample prev = kt::sample(*h.x);
  h.post(replacement);
  for (int i = 0; i < 3000; ++i) {
    h.cycles(1);
    const kt::Sample s = kt::sample(*h.x);
    REQUIRE(std::abs(s.set_acc - prev.set_acc) <= J * T + 1e-9);
    REQUIRE(std::abs(s.set_velo - prev.set_velo) <= A * T + 1e-9);
    REQUIRE(std::abs(s.set_pos - prev.set_pos) <= V * T + 1e-9);
    prev = s;
  }
}

}  // namespace

TEST_CASE("an aborting command blends from the set state without a jump", "[kernel][blending]") {
  for (int before :
       {50, 150, 400, 800}) {  // accelerating, at the end of the jerk, cruising, braking
    INFO("replaced after " << before << " cycles");
    SECTION("reverse to a target behind " + std::to_string(before)) {
      kt::Harness h;
      check_continuous(h, kt::move_absolute(-500.0, 1500.0, 20000.0, 20000.0, 200000.0), before);
      CHECK(h.x->NcToPlc.SetPos == -500.0);
    }
    SECTION("a target the axis cannot stop before " + std::to_string(before)) {
      kt::Harness h;
      check_continuous(h, kt::move_relative(1.0, 500.0), before);
    }
    SECTION("velocity " + std::to_string(before)) {
      kt::Harness h;
      check_continuous(h, kt::move_velocity(300.0, -1), before);
      CHECK(h.x->NcToPlc.SetVelo == -300.0);
    }
    SECTION("halt " + std::to_string(before)) {
      kt::Harness h;
      check_continuous(h, kt::simple(CommandType::kHalt, 0.0, 0.0), before);
      CHECK(h.x->NcToPlc.SetVelo == 0.0);
    }
  }
}
