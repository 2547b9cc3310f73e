// VP against the real velocity (SPEC B7 decision, seed 000 §2.5 start-parameter note 3): the
// compensation runs in time over T = L / VP with its velocity scaled by min(1, v / VP). So with
// v >= VP the full D is done, with v < VP only D · v / VP (at constant v), and the warning 0x4243
// tells that less than D was carried out.
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::ErrorCode;

namespace {

struct Result {
  double end = 0.0;
  double distance = 0.0;
  uint32_t warning_running = 0;
  uint32_t warning_end = 0;
  CommandState answer = CommandState::kFree;
  int cycles = -1;
};

// Base 0 → 10000 at `v`; at constant velocity a compensation D over L with VK 300, AK+ 500,
// AK- 1000 and the given VP.
Result run(double v, double d, double vp, double length) {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(10000.0, v));
  REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetVelo == v && h.x->NcToPlc.SetAcc == 0.0; }) >
          0);
  const uint16_t comp = h.post(kt::move_superimposed(d, 300.0, 500.0, 1000.0, vp, length));
  Result r;
  h.cycles(2);
  r.warning_running = h.x->NcToPlc.Warning;
  r.cycles = 2 + h.cycles_until([&] { return h.state_of(comp) != CommandState::kActive; });
  r.answer = h.state_of(comp);
  r.warning_end = h.x->NcToPlc.Warning;
  r.distance = h.x->NcToPlc.CompensationDistance;
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  r.end = h.x->NcToPlc.SetPos;
  return r;
}

}  // namespace

TEST_CASE("VP below the real velocity gives the full D", "[compensation][process_velocity]") {
  // v = 2000, VP = 1000: T = 2000 / 1000 = 2 s, the scale stays 1.
  const Result r = run(2000.0, 250.0, 1000.0, 2000.0);
  CHECK(r.answer == CommandState::kDone);
  CHECK(r.cycles == 2000);
  CHECK(r.distance == Approx(250.0).margin(1e-9));
  CHECK(r.end == Approx(10250.0).margin(1e-9));
  CHECK(r.warning_end == 0);
}

TEST_CASE("VP above the real velocity gives D times v / VP, with warning 0x4243",
          "[compensation][process_velocity]") {
  SECTION("v 2000, VP 4000: half of D = 100") {
    const Result r = run(2000.0, 100.0, 4000.0, 5000.0);
    CHECK(r.answer == CommandState::kDone);  // it ran its whole time T = 1.25 s
    CHECK(r.cycles == 1250);
    CHECK(r.warning_running == 0);  // D itself is feasible: the shortfall shows at the end
    CHECK(r.warning_end == kt::id(ErrorCode::kCompensationIncomplete));
    CHECK(r.distance == Approx(50.0).margin(1e-9));
    CHECK(r.end == Approx(10050.0).margin(1e-9));
  }
  SECTION("v 1000, VP 2000, D -200: half of D, -100") {
    const Result r = run(1000.0, -200.0, 2000.0, 4000.0);
    CHECK(r.cycles == 2000);
    CHECK(r.distance == Approx(-100.0).margin(1e-9));
    CHECK(r.end == Approx(9900.0).margin(1e-9));
    CHECK(r.warning_end == kt::id(ErrorCode::kCompensationIncomplete));
  }
}
