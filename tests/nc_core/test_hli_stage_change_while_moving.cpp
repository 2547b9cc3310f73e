// SPEC D4, 70200: a new list while an involved axis moves (the target's drive, the program of an
// old or a new source, or for a list switched off the target's own program) stops the target:
// axis error 70200, its list off, its drive braking at the emergency deceleration to rest; other
// axes are not disturbed.
#include <catch2/catch.hpp>

#include "hli_stage_rig.hpp"

using namespace hlitest;

namespace {

constexpr double kDecel = 2000.0;  // mm/s²

Rig coupled_rig() {
  nc::hli::AxisSetup s;
  s.emergency_deceleration = kDecel;
  Rig rig({1, 2, 3}, s);
  rig.command(1, {direct(1), inactive()});
  rig.cycle();
  return rig;
}

// Runs axis 0 at `v` for `cycles`; the program keeps moving until the test stops it.
void run(Rig& rig, std::size_t axis, double v, int cycles) {
  for (int i = 0; i < cycles; ++i) {
    rig.q[axis] += v * kT;
    rig.qv[axis] = v;
    rig.cycle();
  }
}

}  // namespace

TEST_CASE("70200: an old source moving stops the target, which brakes to rest", "[hli]") {
  Rig rig = coupled_rig();
  run(rig, 0, 400.0, 100);
  const double d_at_change = rig.d[1];
  REQUIRE(d_at_change == Approx(40.0).margin(1e-9));

  rig.command(1, {direct(3), inactive()});
  rig.q[0] += 0.4;
  rig.cycle();
  CHECK(rig.stop[1] == plc::ErrorCode::kHliChangeWhileMoving);
  CHECK(rig.unit(1).state_r.error_r == 70200);
  CHECK_FALSE(rig.unit(1).state_r.active_r);
  CHECK_FALSE(rig.unit(1).command_w.semaphor_rw);
  CHECK(rig.stop[0] == plc::ErrorCode::kNone);
  const double d_stop = rig.d[1];
  CHECK(d_stop == Approx(40.4).margin(1e-9));
  CHECK(rig.dv[1] == 400.0);

  // Axis 0 runs on; the target's drive brakes at 2000 mm/s²: 0.2 s, 400² / 4000 = 40 mm.
  int braking = 0;
  while (rig.dv[1] != 0.0 && braking < 1000) {
    run(rig, 0, 400.0, 1);
    ++braking;
    CHECK(rig.stop[1] == plc::ErrorCode::kNone);
    CHECK(rig.da[1] == (rig.dv[1] != 0.0 ? -kDecel : 0.0));
  }
  CHECK(braking == 200);
  CHECK(rig.d[1] == Approx(d_stop + 40.0).margin(1e-9));
  run(rig, 0, 400.0, 50);
  CHECK(rig.d[1] == Approx(d_stop + 40.0).margin(1e-9));
  CHECK(rig.d[0] == Approx(rig.q[0]).margin(1e-9));  // the source is not disturbed
  // At rest, it follows its own program from where it stands.
  rig.move(1, 3.0, 100.0);
  CHECK(rig.d[1] == Approx(d_stop + 43.0).margin(1e-9));
}

TEST_CASE("70200: a new source moving, or the target's drive moving, stops the target", "[hli]") {
  {
    Rig rig = coupled_rig();
    run(rig, 2, -50.0, 3);  // axis 3 is not coupled yet
    rig.command(1, {direct(1), direct(3), inactive()});
    run(rig, 2, -50.0, 1);
    CHECK(rig.stop[1] == plc::ErrorCode::kHliChangeWhileMoving);
    CHECK(rig.unit(1).state_r.error_r == 70200);
  }
  {
    Rig rig({1, 2});
    run(rig, 1, 10.0, 3);  // an uncoupled axis moving: its drive moves with its program
    rig.command(1, {direct(1), inactive()});
    run(rig, 1, 10.0, 1);
    CHECK(rig.stop[1] == plc::ErrorCode::kHliChangeWhileMoving);
  }
  {
    Rig rig = coupled_rig();  // the target's own program moving, not a source: no error
    run(rig, 1, 10.0, 3);
    rig.command(1, {direct(1), direct(3), inactive()});
    run(rig, 1, 10.0, 1);
    CHECK(rig.stop[1] == plc::ErrorCode::kNone);
    CHECK(rig.unit(1).state_r.error_r == 0);
    CHECK(rig.unit(1).state_r.active_r);
  }
}

TEST_CASE("70200: switched off while the target's own program moves (K25), coupled or braking",
          "[hli]") {
  // Switched off, the drive follows the target's program: that program is an axis involved.
  Rig rig = coupled_rig();
  run(rig, 1, 300.0, 10);  // the program only (no self entry): the drive stays at 0
  REQUIRE(rig.d[1] == 0.0);
  rig.command(1, {inactive()});
  run(rig, 1, 300.0, 1);
  CHECK(rig.stop[1] == plc::ErrorCode::kHliChangeWhileMoving);
  CHECK(rig.unit(1).state_r.error_r == 70200);
  CHECK_FALSE(rig.unit(1).state_r.active_r);
  CHECK(rig.d[1] == 0.0);
  CHECK(rig.dv[1] == 0.0);  // before the fix: 300 mm/s in this cycle

  // The same on the brake's hold while the program still moves: the drive stays.
  rig.command(1, {inactive()});
  run(rig, 1, 300.0, 1);
  CHECK(rig.stop[1] == plc::ErrorCode::kHliChangeWhileMoving);
  CHECK(rig.dv[1] == 0.0);
  run(rig, 1, 300.0, 20);
  CHECK(rig.d[1] == 0.0);
  CHECK(rig.dv[1] == 0.0);

  // Once the program rests the drive follows it from where it stands; a switch-off is taken.
  rig.qv[1] = 0.0;
  rig.cycle();
  rig.move(1, 5.0, 100.0);
  CHECK(rig.d[1] == Approx(5.0).margin(1e-9));
  rig.command(1, {inactive()});
  rig.cycle();
  CHECK(rig.stop[1] == plc::ErrorCode::kNone);
  CHECK(rig.unit(1).state_r.error_r == 0);
}
