// The simulated two-speed drive (SPEC E6): it reads only nControlByte; two motor speeds in the
// commanded direction, ramping at rapid_velocity / two_speed_ramp_time, the brake stopping it ten
// times as hard, an encoder with its increment. Numbers for rapid 500 mm/s, creep 50 mm/s, ramp
// 0.1 s (5000 mm/s²), brake 50000 mm/s².
#include <catch2/catch.hpp>

#include <cmath>

#include "two_speed/two_speed_plant.hpp"
#include "two_speed_loop.hpp"

using nc::detail::TwoSpeedPlant;
using plc::TwoSpeedDirection;
using plc::TwoSpeedVelocity;

namespace {

plc::NCTOIO_DRIVE_TWO_SPEED image(TwoSpeedDirection d, TwoSpeedVelocity v, bool brake) {
  plc::NCTOIO_DRIVE_TWO_SPEED i{};
  plc::write_control_bytes(i, {d, v, brake});
  return i;
}

const auto kRapidPlus = image(TwoSpeedDirection::kPositive, TwoSpeedVelocity::kHigh, false);
const auto kCreepMinus = image(TwoSpeedDirection::kNegative, TwoSpeedVelocity::kLow, false);
const auto kCoast = image(TwoSpeedDirection::kNone, TwoSpeedVelocity::kOff, false);
const auto kBrake = image(TwoSpeedDirection::kNone, TwoSpeedVelocity::kOff, true);

void run(TwoSpeedPlant& plant, const plc::NCTOIO_DRIVE_TWO_SPEED& i, int cycles) {
  for (int k = 0; k < cycles; ++k)
    plant.step(i, 0.001);
}

}  // namespace

TEST_CASE("rapid ramps to 500 mm/s in 0.1 s and covers the ramp's 25 mm", "[two_speed][plant]") {
  TwoSpeedPlant plant(ts::issue_axis(), 0.0);
  run(plant, kRapidPlus, 50);
  CHECK(plant.velocity() == Approx(250.0));
  run(plant, kRapidPlus, 50);
  CHECK(plant.velocity() == Approx(500.0));
  CHECK(plant.exact_position() == Approx(25.0));
  run(plant, kRapidPlus, 100);
  CHECK(plant.velocity() == 500.0);
  CHECK(plant.exact_position() == Approx(75.0));
}

TEST_CASE("creep drives -50 mm/s; without a travel bit the motor runs down at the ramp",
          "[two_speed][plant]") {
  TwoSpeedPlant plant(ts::issue_axis(), 100.0);
  run(plant, kCreepMinus, 10);
  CHECK(plant.velocity() == Approx(-50.0));
  CHECK(plant.exact_position() == Approx(100.0 - 0.25));
  run(plant, kCreepMinus, 1000);
  CHECK(plant.exact_position() == Approx(100.0 - 0.25 - 50.0));
  run(plant, kCoast, 5);
  CHECK(plant.velocity() == Approx(-25.0));
  run(plant, kCoast, 100);
  CHECK(plant.velocity() == 0.0);
  CHECK(plant.exact_position() == Approx(100.0 - 0.25 - 50.0 - 0.25));
}

TEST_CASE("the brake stops the axis ten times as hard as the ramp, travel bits or not",
          "[two_speed][plant]") {
  TwoSpeedPlant plant(ts::issue_axis(), 0.0);
  run(plant, kRapidPlus, 200);
  const double p0 = plant.exact_position();
  run(plant, kBrake, 5);
  CHECK(plant.velocity() == Approx(250.0));
  run(plant, kBrake, 100);
  CHECK(plant.velocity() == 0.0);
  CHECK(plant.exact_position() - p0 == Approx(500.0 * 500.0 / (2.0 * 50000.0)));  // 2.5 mm
  // A travel bit with the brake applied does not move it.
  run(plant, image(TwoSpeedDirection::kPositive, TwoSpeedVelocity::kHigh, true), 100);
  CHECK(plant.velocity() == 0.0);
}

TEST_CASE("the plant reads nControlByte only; contradicting bits drive nothing",
          "[two_speed][plant]") {
  TwoSpeedPlant plant(ts::issue_axis(), 0.0);
  auto odd = kRapidPlus;
  odd.nExtControlByte = 0x85;  // says minus, creep, brake: ignored
  odd.nOutData1 = 123;
  run(plant, odd, 200);
  CHECK(plant.velocity() == 500.0);

  TwoSpeedPlant other(ts::issue_axis(), 0.0);
  auto both = kCoast;
  both.nControlByte |= plc::bit_mask(plc::ControlByteBit::bPlusHigh);
  both.nControlByte |= plc::bit_mask(plc::ControlByteBit::bMinusHigh);
  run(other, both, 100);
  CHECK(other.velocity() == 0.0);
  CHECK(other.exact_position() == 0.0);
}

TEST_CASE("ramp time 0 switches speeds in one step; the encoder rounds to its increment",
          "[two_speed][plant]") {
  nc::AxisConfig c = ts::issue_axis();
  c.two_speed_ramp_time = 0.0;
  c.encoder_increment = 0.01;
  TwoSpeedPlant plant(c, 0.0);
  run(plant, kRapidPlus, 1);
  CHECK(plant.velocity() == 500.0);
  CHECK(plant.exact_position() == Approx(0.5));
  run(plant, kBrake, 1);
  CHECK(plant.velocity() == 0.0);
  CHECK(plant.exact_position() == Approx(0.5));

  TwoSpeedPlant fine(c, 0.0);
  run(fine, image(TwoSpeedDirection::kPositive, TwoSpeedVelocity::kLow, false), 1);
  run(fine, kBrake, 1);
  CHECK(fine.exact_position() == Approx(0.05));
  for (const double p : {0.004, 0.006, -0.016}) {
    TwoSpeedPlant at(c, p);
    CHECK(at.position() == Approx(std::round(p / 0.01) * 0.01));
  }
}
