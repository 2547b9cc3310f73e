// The modulo start (SPEC B1, seed 000 §2.1; MC_MoveModulo), modulo factor 360: below the factor
// the modulo position is reached in the given direction (shortest way: the shorter one, in the
// same or the next period); at or above it the extra whole turns come first; the end is always
// congruent to Position, and NcToPlc.ModuloSetPos / ModuloActPos lie in [0, 360).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandState;

namespace {

constexpr int kPositive = 1;
constexpr int kShortest = 2;
constexpr int kNegative = 3;
constexpr int kCurrent = 4;

struct Travel {
  double end = 0.0;
  double v_min = 0.0;  // lowest and highest set velocity on the way
  double v_max = 0.0;
};

// From rest at `from` (reached by a MoveAbsolute), a modulo start to Position `p`.
Travel modulo_from(double from, double p, int direction) {
  kt::Harness h;
  if (from != 0.0) {
    const uint16_t to = h.post(kt::move_absolute(from, 1000.0));
    REQUIRE(h.cycles_until([&] { return h.state_of(to) == CommandState::kDone; }) > 0);
  }
  kt::LimitChecker c = kt::LimitChecker::seed(1000.0);
  const uint16_t move = h.post(kt::move_modulo(p, 1000.0, direction));
  Travel t;
  REQUIRE(kt::checked_cycles_until(h, c, [&] {
            t.v_min = std::min(t.v_min, h.x->NcToPlc.SetVelo);
            t.v_max = std::max(t.v_max, h.x->NcToPlc.SetVelo);
            return h.state_of(move) == CommandState::kDone;
          }) > 0);
  t.end = h.x->NcToPlc.SetPos;
  const double modulo = p - 360.0 * std::floor(p / 360.0);
  CHECK(h.x->NcToPlc.ModuloSetPos == Approx(modulo).margin(1e-9));
  // The actual position is quantised (increment 1e-4 mm): compare round the circle.
  const double gap = std::fmod(std::fabs(h.x->NcToPlc.ModuloActPos - modulo), 360.0);
  CHECK(std::min(gap, 360.0 - gap) < 1e-3);
  CHECK(h.x->NcToPlc.ModuloSetPos >= 0.0);
  CHECK(h.x->NcToPlc.ModuloSetPos < 360.0);
  INFO(c.first);
  CHECK(c.ok());
  return t;
}

}  // namespace

TEST_CASE("Position 540 with factor 360 from 0 travels 540 and ends at modulo 180", "[modulo]") {
  const Travel up = modulo_from(0.0, 540.0, kPositive);
  CHECK(up.end == 540.0);
  CHECK(up.v_min >= 0.0);
  const Travel down = modulo_from(0.0, 540.0, kNegative);
  CHECK(down.end == -180.0 - 360.0);
  CHECK(down.v_max <= 0.0);
}

TEST_CASE("extra turns are counted after the first orientation in the direction", "[modulo]") {
  // From 90: the first 45 ahead is 405, then two whole turns (765 = 2·360 + 45).
  CHECK(modulo_from(90.0, 765.0, kPositive).end == 1125.0);
  // From 200: 540 means at least one turn, then 180 (the first 180 ahead of 560 is 900).
  CHECK(modulo_from(200.0, 540.0, kPositive).end == 900.0);
  // 360 is one whole turn back onto the same orientation.
  CHECK(modulo_from(90.0, 360.0 + 90.0, kPositive).end == 450.0);
}

TEST_CASE("0.0 with the positive direction goes forward to the next 0", "[modulo]") {
  const Travel t = modulo_from(90.0, 0.0, kPositive);
  CHECK(t.end == 360.0);
  CHECK(t.v_min >= 0.0);
}

TEST_CASE("-1e-6 with the negative direction reaches 0 going negative", "[modulo]") {
  const Travel t = modulo_from(90.0, -1e-6, kNegative);
  CHECK(t.end == -1e-6);
  CHECK(t.v_max <= 0.0);
  // 0.0 itself with the negative direction: exactly 0, going negative.
  CHECK(modulo_from(90.0, 0.0, kNegative).end == 0.0);
}

TEST_CASE("the negative direction goes back to the first orientation behind", "[modulo]") {
  CHECK(modulo_from(90.0, 45.0, kNegative).end == 45.0);
  CHECK(modulo_from(90.0, 135.0, kNegative).end == -225.0);
}

TEST_CASE("the shortest way goes across 0/360 when that is shorter", "[modulo]") {
  const Travel up = modulo_from(350.0, 10.0, kShortest);
  CHECK(up.end == 370.0);  // +20
  CHECK(up.v_min >= 0.0);
  const Travel down = modulo_from(10.0, 350.0, kShortest);
  CHECK(down.end == -10.0);  // -20
  CHECK(down.v_max <= 0.0);
  CHECK(modulo_from(0.0, 180.0, kShortest).end == 180.0);  // a tie goes positive
  // At or above the factor the sign gives the direction of the turns (the seed's rule).
  CHECK(modulo_from(0.0, 540.0, kShortest).end == 540.0);
  CHECK(modulo_from(0.0, -540.0, kShortest).end == -540.0);
}

TEST_CASE("the current direction follows the motion, which reaches the target without reversing",
          "[modulo]") {
  for (int sign : {1, -1}) {
    INFO("moving " << (sign > 0 ? "positive" : "negative"));
    kt::Harness h;
    h.post(kt::move_velocity(2000.0, sign > 0 ? 1 : 3));
    h.cycles(500);  // at ±500 mm, 2000 mm/s: the shortest stop ends at ±1000 mm
    REQUIRE(h.x->NcToPlc.SetPos == Approx(sign * 500.0).margin(1e-9));
    kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
    const uint16_t move = h.post(kt::move_modulo(180.0, 2000.0, kCurrent));
    double wrong_way = 0.0;
    REQUIRE(kt::checked_cycles_until(h, c, [&] {
              wrong_way = std::max(wrong_way, -sign * h.x->NcToPlc.SetVelo);
              return h.state_of(move) == CommandState::kDone;
            }) > 0);
    CHECK(wrong_way <= 0.0);
    // The first 180 beyond the stopping point: 1260 forward, -1260 backward.
    CHECK(h.x->NcToPlc.SetPos == sign * 1260.0);
    INFO(c.first);
    CHECK(c.ok());
  }
}
