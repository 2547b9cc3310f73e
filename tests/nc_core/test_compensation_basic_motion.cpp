// How a compensation lives with its basic motion (seed 000 §2.5 general notes and start-parameter
// note 5, SPEC B7): the remaining distance replaces a longer L, the basic motion's end of path
// ends the compensation, a MoveVelocity carries one, D refers to the direction of travel, a new
// motion command aborts it without a jump, an axis error fails it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

namespace {

void reach_constant_velocity(kt::Harness& h, double v) {
  REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetVelo == v && h.x->NcToPlc.SetAcc == 0.0; }) >
          0);
}

}  // namespace

TEST_CASE("the remaining distance replaces a longer compensation length",
          "[compensation][basic_motion]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(10000.0, 2000.0));
  REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetPos >= 7000.0; }) > 0);
  const double remaining = 10000.0 - h.x->NcToPlc.SetPos;
  const uint16_t comp = h.post(kt::move_superimposed(100.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
  h.cycles(1);
  CHECK(h.x->NcToPlc.CompensationLength == remaining);
  // T = remaining / VP; the compensation ends in the basic motion's brake phase, where v < VP
  // already scales it down: kDone after T with less than D.
  const int cycles = 1 + h.cycles_until([&] { return h.state_of(comp) != CommandState::kActive; });
  CHECK(cycles == static_cast<int>(std::ceil(remaining / 2000.0 / 0.001 - 1e-6)));
  CHECK(h.state_of(comp) == CommandState::kDone);
  const double done = h.x->NcToPlc.CompensationDistance;
  CHECK(done < 100.0);
  CHECK(done > 90.0);
  CHECK(h.x->NcToPlc.Warning == kt::id(ErrorCode::kCompensationIncomplete));
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == Approx(10000.0 + done).epsilon(1e-14));
}

TEST_CASE("the basic motion's end of path ends the compensation", "[compensation][basic_motion]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(10000.0, 2000.0));
  reach_constant_velocity(h, 2000.0);
  // VP 500 below v: T = 3000 / 500 = 6 s, but the basic motion ends after about 4.75 s.
  const uint16_t comp = h.post(kt::move_superimposed(100.0, 300.0, 500.0, 1000.0, 500.0, 3000.0));
  int end_of_path = -1;
  for (int i = 1; i < 10000 && end_of_path < 0; ++i) {
    h.cycles(1);
    if (h.state_of(comp) != CommandState::kActive) end_of_path = i;
  }
  REQUIRE(end_of_path > 0);
  CHECK(end_of_path < 6000);
  CHECK(h.state_of(comp) == CommandState::kAborted);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);  // ended with the basic motion's set values
  CHECK(h.x->NcToPlc.CompensationDistance < 100.0);
  CHECK(h.x->NcToPlc.Warning == kt::id(ErrorCode::kCompensationIncomplete));
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) >= 0);
  CHECK(h.x->NcToPlc.SetPos == Approx(10000.0 + h.x->NcToPlc.CompensationDistance).epsilon(1e-14));
}

TEST_CASE("a MoveVelocity carries a compensation over the whole L: it leads its twin by D",
          "[compensation][basic_motion]") {
  kt::Harness h;
  kt::Harness twin;
  for (kt::Harness* k : {&h, &twin}) {
    k->post(kt::move_velocity(1500.0, 1));
    reach_constant_velocity(*k, 1500.0);
  }
  const uint16_t comp = h.post(kt::move_superimposed(40.0, 100.0, 500.0, 1000.0, 1500.0, 3000.0));
  for (int i = 0; i < 2500; ++i) {
    h.cycles(1);
    twin.cycles(1);
  }
  CHECK(h.state_of(comp) == CommandState::kDone);
  CHECK(h.x->NcToPlc.CompensationLength == 3000.0);
  CHECK(h.x->NcToPlc.SetPos - twin.x->NcToPlc.SetPos == Approx(40.0).margin(1e-9));
  CHECK(h.x->NcToPlc.SetVelo == 1500.0);
  CHECK(h.x->NcToPlc.Warning == 0);
}

TEST_CASE("D refers to the direction of travel: on a negative motion D 250 ends 250 further out",
          "[compensation][basic_motion]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(-10000.0, 2000.0));
  reach_constant_velocity(h, -2000.0);
  const uint16_t comp = h.post(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
  double fastest = 0.0;
  for (int i = 0; i < 2600; ++i) {
    h.cycles(1);
    fastest = std::min(fastest, h.x->NcToPlc.SetVelo);
  }
  CHECK(h.state_of(comp) == CommandState::kDone);
  CHECK(h.x->NcToPlc.CompensationDistance == Approx(250.0).margin(1e-9));  // as D: made up
  CHECK(fastest < -2100.0);
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == Approx(-10250.0).margin(1e-9));
}

TEST_CASE(
    "a new motion command aborts the compensation and starts from the compensated set "
    "state without a jump",
    "[compensation][basic_motion]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(10000.0, 2000.0));
  reach_constant_velocity(h, 2000.0);
  const uint16_t comp = h.post(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
  h.cycles(1000);
  const double velocity_before = h.x->NcToPlc.SetVelo;
  CHECK(velocity_before > 2100.0);  // base + extra velocity
  kt::Sample previous = kt::sample(*h.x);
  const uint16_t next = h.post(kt::move_absolute(6000.0, 1000.0));
  h.cycles(1);
  CHECK(h.state_of(comp) == CommandState::kAborted);
  CHECK(h.state_of(move) == CommandState::kAborted);
  CHECK(h.state_of(next) == CommandState::kActive);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateCompensating));
  for (int i = 0; i < 10000 && h.state_of(next) != CommandState::kDone; ++i) {
    const kt::Sample s = kt::sample(*h.x);
    REQUIRE(std::abs(s.set_velo - previous.set_velo) <= 5000.0 * 0.001 + 1e-9);
    REQUIRE(std::abs(s.set_pos - previous.set_pos) <= 2400.0 * 0.001);
    previous = s;
    h.cycles(1);
  }
  CHECK(h.state_of(next) == CommandState::kDone);
  CHECK(h.x->NcToPlc.SetPos == 6000.0);  // the new absolute target, nothing added
}

TEST_CASE("an axis error during compensation fails it with the axis's code",
          "[compensation][basic_motion]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(10000.0, 2000.0));
  reach_constant_velocity(h, 2000.0);
  const uint16_t comp = h.post(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
  h.cycles(500);
  kt::set_enables(*h.x, true, false, true);
  h.cycles(1);
  CHECK(h.answer(comp).state == CommandState::kError);
  CHECK(h.answer(comp).error_code == kt::id(ErrorCode::kFeedEnablePlusMissing));
  CHECK(h.answer(move).error_code == kt::id(ErrorCode::kFeedEnablePlusMissing));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateCompensating));
  REQUIRE(h.cycles_until([&] { return h.x->NcToPlc.SetVelo == 0.0; }) > 0);
}
