// New velocity and new end position (SPEC B6, seed 000 §2.4; MC_NewPosAndVelo), the six cases by
// the order of Pos, APos and EPos along the logical direction, for positive motion and mirrored
// for negative motion. Every scenario: 0 → ±5000 mm at VOld = 1000 mm/s (A+ = A- = 5000 mm/s²,
// J = 50000 mm/s³), the request at 1.3 s when the axis cruises at Pos = ±1150 mm, VNew = 2000.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "kernel_harness.hpp"

using plc::CommandState;

namespace {

struct Run {
  kt::Harness h;
  kt::LimitChecker checker = kt::LimitChecker::seed(2000.0);
  double s;  // +1 positive motion, -1 the mirror
  uint16_t move = 0;
  uint16_t request = 0;

  explicit Run(double sign) : s(sign) {
    move = h.post(kt::move_absolute(s * 5000.0, 1000.0));
    kt::checked_cycles(h, checker, 1300);
    REQUIRE(h.x->NcToPlc.SetPos == Approx(s * 1150.0).margin(1e-9));
    REQUIRE(h.x->NcToPlc.SetVelo == Approx(s * 1000.0).margin(1e-9));
  }
  // Posts the request (positions in the logical frame, multiplied by s here) and runs one cycle.
  void ask(double end_position, double velocity, double activation_position) {
    request = h.post(kt::new_pos_and_velo(s * end_position, velocity, s * activation_position));
    step();
    CHECK(h.state_of(request) == CommandState::kDone);
    CHECK(h.x->NcToPlc.TargetPos == s * end_position);
  }
  void step() {
    h.kernel.cycle();
    checker.check(*h.x);
  }
  double pos() const { return s * h.x->NcToPlc.SetPos; }    // along the logical direction
  double velo() const { return s * h.x->NcToPlc.SetVelo; }  // along the logical direction
  bool done() const { return h.state_of(move) == CommandState::kDone; }

  // Extremes along the logical direction from now until the move is Done.
  struct Trace {
    double fastest_forward = 0.0;   // largest velocity
    double fastest_backward = 0.0;  // smallest (most negative) velocity
    double furthest = 0.0;          // largest position
  };
  // Runs the move to its end, then asserts the end position and that the limits held throughout.
  Trace finish(double end_position) {
    Trace t;
    while (!done()) {
      t.fastest_forward = std::max(t.fastest_forward, velo());
      t.fastest_backward = std::min(t.fastest_backward, velo());
      t.furthest = std::max(t.furthest, pos());
      step();
    }
    CHECK(pos() == end_position);
    INFO(checker.first);
    CHECK(checker.ok());
    return t;
  }
};

const char* name(double s) {
  return s > 0.0 ? "positive motion" : "negative motion (mirror)";
}

}  // namespace

TEST_CASE("case 1, Pos <= APos <= EPos: VNew from APos on", "[new_pos_and_velo]") {
  for (double s : {1.0, -1.0}) {
    INFO(name(s));
    Run r(s);
    r.ask(4000.0, 2000.0, 2000.0);  // Pos 1150 < APos 2000 < EPos 4000
    double before = 0.0;
    while (r.pos() < 2000.0) {
      REQUIRE(r.velo() == Approx(1000.0).margin(1e-9));  // VOld until APos is passed
      before = r.pos();
      r.step();
    }
    CHECK(before < 2000.0);
    CHECK(r.velo() == Approx(1000.0).margin(1e-9));  // the cycle in which SetPos passes APos
    r.step();
    CHECK(r.velo() > 1000.0 + 1e-6);  // the next cycle accelerates towards VNew
    CHECK(r.finish(4000.0).fastest_forward == Approx(2000.0).margin(1e-9));
  }
}

TEST_CASE("case 2, APos <= Pos <= EPos: VNew at once", "[new_pos_and_velo]") {
  for (double s : {1.0, -1.0}) {
    INFO(name(s));
    Run r(s);
    r.ask(4000.0, 2000.0, 1000.0);  // APos 1000 < Pos 1150 < EPos 4000
    CHECK(r.velo() > 1000.0 + 1e-6);
    CHECK(r.h.x->NcToPlc.TargetVelo == s * 2000.0);
    CHECK(r.finish(4000.0).fastest_forward == Approx(2000.0).margin(1e-9));
  }
}

TEST_CASE("case 3, APos <= EPos <= Pos: stop and return with VOld", "[new_pos_and_velo]") {
  for (double s : {1.0, -1.0}) {
    INFO(name(s));
    Run r(s);
    r.ask(600.0, 2000.0, 300.0);  // APos 300 < EPos 600 < Pos 1150
    const Run::Trace t = r.finish(600.0);
    CHECK(t.furthest > 1150.0);                                 // could not stop at once
    CHECK(t.fastest_backward == Approx(-1000.0).margin(1e-9));  // returns with VOld, not VNew
  }
}

TEST_CASE("case 4, Pos <= EPos <= APos: only the new end position, VOld", "[new_pos_and_velo]") {
  for (double s : {1.0, -1.0}) {
    INFO(name(s));
    Run r(s);
    r.ask(3000.0, 2000.0, 4000.0);  // Pos 1150 < EPos 3000 < APos 4000
    CHECK(r.finish(3000.0).fastest_forward == Approx(1000.0).margin(1e-9));
  }
}

TEST_CASE(
    "case 5, EPos <= APos <= Pos: stop, return with VOld, VNew once APos is passed on the way "
    "back",
    "[new_pos_and_velo]") {
  for (double s : {1.0, -1.0}) {
    INFO(name(s));
    Run r(s);
    r.ask(-1000.0, 2000.0, 800.0);  // EPos -1000 < APos 800 < Pos 1150
    // Out to the turning point and back with VOld down to APos.
    bool turned = false;
    while (!(turned && r.pos() <= 800.0)) {
      if (r.velo() < 0.0) turned = true;
      REQUIRE(r.velo() >= -1000.0 - 1e-9);
      r.step();
    }
    CHECK(r.velo() == Approx(-1000.0).margin(1e-9));  // the cycle in which SetPos passes APos
    r.step();
    CHECK(r.velo() < -1000.0 - 1e-6);  // then VNew
    CHECK(r.finish(-1000.0).fastest_backward == Approx(-2000.0).margin(1e-9));
  }
}

TEST_CASE("case 6, EPos <= Pos <= APos: stop and return with VOld", "[new_pos_and_velo]") {
  for (double s : {1.0, -1.0}) {
    INFO(name(s));
    Run r(s);
    r.ask(600.0, 2000.0, 2000.0);  // EPos 600 < Pos 1150 < APos 2000
    CHECK(r.finish(600.0).fastest_backward == Approx(-1000.0).margin(1e-9));
  }
}
