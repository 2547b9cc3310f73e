// The NC→PLC image over one positioning (SPEC A7, API.md StateDWord bit numbers): which bits and
// fields are set in the acceleration, cruise and deceleration phases and at rest.
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandState;

TEST_CASE("StateDWord and image fields through a 0 → 2000 mm positioning at 2000 mm/s",
          "[kernel][state_word]") {
  // A = 5000, J = 50000: 0.5 s to reach 2000 mm/s over 500 mm, 0.5 s cruise, 0.5 s braking.
  kt::Harness h;
  const uint32_t counter_before = h.x->NcToPlc.CycleCounter;
  CHECK(kt::bit(*h.x, plc::kStateNotMoving));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHasJob));
  const uint16_t job = h.post(kt::move_absolute(2000.0, 2000.0));
  int constant_cycles = 0;
  for (int cycle = 1; cycle <= 1500; ++cycle) {
    h.cycles(1);
    const auto& o = h.x->NcToPlc;
    REQUIRE(o.CycleCounter == counter_before + static_cast<uint32_t>(cycle));
    REQUIRE(kt::bit(*h.x, plc::kStateHasJob));
    REQUIRE(kt::bit(*h.x, plc::kStateOperational));
    REQUIRE_FALSE(kt::bit(*h.x, plc::kStateNegativeDirection));
    REQUIRE(o.TargetPos == 2000.0);
    REQUIRE(o.TargetVelo == 2000.0);
    REQUIRE(o.CoupleState == 0);
    const double m = std::fmod(o.ActPos, 360.0);
    REQUIRE(o.ModuloActPos == Approx(m).margin(1e-9));
    const bool constant = kt::bit(*h.x, plc::kStateConstantVelocity);
    if (constant) ++constant_cycles;
    if (cycle < 500 || (cycle > 1000 && cycle < 1500)) {
      REQUIRE_FALSE(constant);
      REQUIRE_FALSE(kt::bit(*h.x, plc::kStateNotMoving));
      REQUIRE(kt::bit(*h.x, plc::kStatePositiveDirection));
    }
    if (cycle > 500 && cycle < 1000) {
      REQUIRE(constant);
      REQUIRE(o.SetVelo == Approx(2000.0).epsilon(1e-12));
    }
  }
  // The cruise lasts 0.5 s: 499 … 501 samples depending on how the boundaries fall.
  CHECK(constant_cycles >= 499);
  CHECK(constant_cycles <= 501);
  CHECK(h.x->NcToPlc.SetPos == 2000.0);
  CHECK_FALSE(kt::bit(*h.x, plc::kStatePositiveDirection));
  CHECK(kt::bit(*h.x, plc::kStateInPositionArea));
  REQUIRE(h.cycles_until([&] { return h.state_of(job) == CommandState::kDone; }) == 19);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHasJob));
  CHECK(kt::bit(*h.x, plc::kStateInTargetPosition));
  // NotMoving comes from the actual velocity (below standstill_window 1e-3 mm/s).
  CHECK(kt::bit(*h.x, plc::kStateNotMoving));
  CHECK(h.x->NcToPlc.TargetVelo == 0.0);
  CHECK(h.x->NcToPlc.ModuloSetPos == Approx(2000.0 - 5 * 360.0));
  CHECK(h.x->NcToPlc.AxisIndex == 0);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK(h.x->NcToPlc.StateDWord ==
        ((1U << plc::kStateOperational) | (1U << plc::kStateHomed) | (1U << plc::kStateNotMoving) |
         (1U << plc::kStateInPositionArea) | (1U << plc::kStateInTargetPosition) |
         (1U << plc::kStatePtpMode)));
}
