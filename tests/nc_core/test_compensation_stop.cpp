// Compensation stop (seed 000 §2.5 "Compensation stop", SPEC B7): MC_AbortSuperposition ends the
// trapezoid early — the extra velocity ramps down with the closing slope at once and D is
// replaced by what is then compensated; it is refused in the compensation's braking phase. A stop
// of the axis (MC_Stop, MC_Halt) requests the compensation stop at the same time, and the
// compensation ends at the latest at the stop's end of path.
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

namespace {

constexpr double kT = 0.001;

// Base 0 → 10000 at 2000 mm/s; returns once the constant velocity is reached.
uint16_t start_base(kt::Harness& h) {
  const uint16_t move = h.post(kt::move_absolute(10000.0, 2000.0));
  REQUIRE(h.cycles_until(
              [&] { return h.x->NcToPlc.SetVelo == 2000.0 && h.x->NcToPlc.SetAcc == 0.0; }) > 0);
  return move;
}

}  // namespace

TEST_CASE("abort half-way: D is replaced by what was done and the end is target + that part",
          "[compensation][stop]") {
  kt::Harness h;
  const uint16_t move = start_base(h);
  // D 250 over L 5000 (T 2.5 s): peak vp = 106.85 mm/s, reached after vp / AK+ = 0.214 s.
  const uint16_t comp = h.post(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
  h.cycles(1000);  // t = 1.0 s: in the hold
  const double k = 1.0 / 500.0 + 1.0 / 1000.0;
  const double vp = (2.5 - std::sqrt(2.5 * 2.5 - 2.0 * k * 250.0)) / k;
  const double t1 = vp / 500.0;
  const double done_at_abort = 0.5 * vp * t1 + vp * (1.0 - t1);
  CHECK(h.x->NcToPlc.CompensationDistance == Approx(done_at_abort).epsilon(1e-12));

  const uint16_t abort = h.post(kt::simple(CommandType::kAbortSuperposition));
  h.cycles(1);
  CHECK(h.state_of(abort) == CommandState::kDone);
  CHECK(h.state_of(comp) == CommandState::kActive);  // ramps down with AK- = 1000 for vp/1000 s
  const int ramp = h.cycles_until([&] { return h.state_of(comp) != CommandState::kActive; });
  CHECK(ramp + 1 == static_cast<int>(std::ceil(vp / 1000.0 / kT)));
  CHECK(h.state_of(comp) == CommandState::kAborted);
  const double done = done_at_abort + vp * vp / (2.0 * 1000.0);
  CHECK(h.x->NcToPlc.CompensationDistance == Approx(done).epsilon(1e-12));
  CHECK(h.x->NcToPlc.Warning == kt::id(ErrorCode::kCompensationIncomplete));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateCompensating));
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == Approx(10000.0 + done).epsilon(1e-14));
  CHECK(h.x->NcToPlc.TargetPos == Approx(10000.0 + done).epsilon(1e-14));
}

TEST_CASE("abort in the opening ramp ends the ramp at once and closes with AK-",
          "[compensation][stop]") {
  kt::Harness h;
  start_base(h);
  const uint16_t comp = h.post(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
  h.cycles(100);  // 0.1 s into the ramp: extra velocity 50 mm/s, 2.5 mm done
  CHECK(h.x->NcToPlc.SetVelo == Approx(2050.0).epsilon(1e-12));
  h.post(kt::simple(CommandType::kAbortSuperposition));
  REQUIRE(h.cycles_until([&] { return h.state_of(comp) != CommandState::kActive; }) > 0);
  // 2.5 mm + the closing ramp 50² / (2 · 1000) = 1.25 mm.
  CHECK(h.x->NcToPlc.CompensationDistance == Approx(3.75).epsilon(1e-12));
}

TEST_CASE(
    "compensation stop is refused in the compensation's braking phase (0x4258) and "
    "without a compensation (0x4246)",
    "[compensation][stop]") {
  kt::Harness h;
  start_base(h);
  const uint16_t none = h.post(kt::simple(CommandType::kAbortSuperposition));
  h.cycles(1);
  CHECK(h.answer(none).state == CommandState::kError);
  CHECK(h.answer(none).error_code == kt::id(ErrorCode::kCompensationNotActive));

  const uint16_t comp = h.post(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
  h.cycles(2450);  // the closing ramp takes the last 0.107 s of T = 2.5 s
  const plc::NCTOPLC_AXIS_REF before = h.x->NcToPlc;
  const uint16_t late = h.post(kt::simple(CommandType::kAbortSuperposition));
  h.cycles(1);
  CHECK(h.answer(late).state == CommandState::kError);
  CHECK(h.answer(late).error_code == kt::id(ErrorCode::kCompensationStopNotAllowed));
  CHECK(h.state_of(comp) == CommandState::kActive);
  REQUIRE(h.cycles_until([&] { return h.state_of(comp) != CommandState::kActive; }) > 0);
  CHECK(h.state_of(comp) == CommandState::kDone);
  CHECK(h.x->NcToPlc.CompensationDistance == Approx(250.0).margin(1e-9));
  CHECK(before.Warning == 0);
}

TEST_CASE(
    "a stop during compensation requests the compensation stop; the end is the stop's end "
    "plus what was compensated",
    "[compensation][stop]") {
  for (CommandType type : {CommandType::kStop, CommandType::kHalt}) {
    INFO((type == CommandType::kStop ? "MC_Stop" : "MC_Halt"));
    // Twin without compensation: the basic motion and its stop alone.
    kt::Harness twin;
    start_base(twin);
    kt::Harness h;
    start_base(h);
    const uint16_t comp =
        h.post(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
    h.cycles(1000);
    twin.cycles(1000);
    const double done_at_stop = h.x->NcToPlc.CompensationDistance;
    const uint16_t stop = h.post(kt::simple(type));
    twin.post(kt::simple(type));
    h.cycles(1);
    twin.cycles(1);
    CHECK(kt::bit(*h.x, plc::kStateCompensating));  // ramps down, scaled by v / VP
    REQUIRE(h.cycles_until([&] { return h.state_of(stop) == CommandState::kDone; }) > 0);
    REQUIRE(twin.cycles_until([&] { return twin.x->NcToPlc.SetVelo == 0.0; }) >= 0);
    CHECK(h.state_of(comp) == CommandState::kAborted);
    const double done = h.x->NcToPlc.CompensationDistance;
    CHECK(done > done_at_stop);
    CHECK(done < done_at_stop + 106.85 * 106.85 / 2000.0);  // less than the unscaled ramp
    CHECK(h.x->NcToPlc.Warning == kt::id(ErrorCode::kCompensationIncomplete));
    CHECK(h.x->NcToPlc.SetPos == Approx(twin.x->NcToPlc.SetPos + done).epsilon(1e-14));
    CHECK(h.x->NcToPlc.SetVelo == 0.0);
  }
}

TEST_CASE("a stop ends the compensation at the stop's end of path when its ramp is longer",
          "[compensation][stop]") {
  kt::Harness h;
  start_base(h);
  // AK- = 50: the compensation's closing ramp would take 2 s, the stop takes 0.5 s.
  const uint16_t comp = h.post(kt::move_superimposed(100.0, 300.0, 500.0, 50.0, 2000.0, 5000.0));
  h.cycles(1000);
  const uint16_t stop = h.post(kt::simple(CommandType::kStop));
  int cycles_to_comp_end = -1;
  for (int i = 1; i < 5000; ++i) {
    h.cycles(1);
    if (cycles_to_comp_end < 0 && h.state_of(comp) != CommandState::kActive) {
      cycles_to_comp_end = i;
      CHECK(h.state_of(stop) == CommandState::kDone);  // in the same cycle
      CHECK(h.x->NcToPlc.SetVelo == 0.0);
    }
    if (h.state_of(stop) == CommandState::kDone) break;
  }
  CHECK(cycles_to_comp_end > 0);
  CHECK(h.state_of(comp) == CommandState::kAborted);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateCompensating));
}
