// Emergency stop parameters (SPEC B4, seed 000 §2.2 "Emergency stop"): MC_Stop's and MC_Halt's
// Deceleration and Jerk replace the running motion's only when BOTH are genuinely larger;
// otherwise the running motion's are used. From 2000 mm/s the running A- = 5000 mm/s²,
// J = 50000 mm/s³ stop in 0.5 s; A- = 10000, J = 100000 stop in 0.3 s.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::CommandType;

namespace {

struct Outcome {
  int cycles = -1;  // from the post to kDone
  kt::LimitChecker checker;
};

// MoveVelocity 2000 mm/s, then the stop command; the limit check uses the expected values.
Outcome stop_from_2000(CommandType type, double deceleration, double jerk,
                       double expected_deceleration, double expected_jerk) {
  kt::Harness h;
  h.post(kt::move_velocity(2000.0, 1));
  h.cycles(600);
  Outcome out;
  out.checker = kt::LimitChecker::seed(2000.0);
  out.checker.deceleration = expected_deceleration;
  out.checker.jerk = expected_jerk;
  const uint16_t stop = h.post(kt::simple(type, deceleration, jerk));
  out.cycles = kt::checked_cycles_until(h, out.checker,
                                        [&] { return h.state_of(stop) == CommandState::kDone; });
  return out;
}

}  // namespace

TEST_CASE("Stop and Halt adopt Deceleration and Jerk only when both are larger than the motion's",
          "[stop][halt]") {
  struct Case {
    double deceleration, jerk;
    bool adopted;
  };
  for (CommandType type : {CommandType::kStop, CommandType::kHalt}) {
    for (const Case& k :
         {Case{10000.0, 100000.0, true}, Case{10000.0, 0.0, false}, Case{10000.0, 50000.0, false},
          Case{5000.0, 100000.0, false}, Case{4000.0, 100000.0, false}, Case{0.0, 0.0, false},
          Case{3000.0, 30000.0, false}}) {
      INFO((type == CommandType::kStop ? "Stop " : "Halt ") << k.deceleration << " / " << k.jerk);
      const Outcome o =
          stop_from_2000(type, k.deceleration, k.jerk, k.adopted ? k.deceleration : 5000.0,
                         k.adopted ? k.jerk : 50000.0);
      CHECK(o.cycles == (k.adopted ? 300 : 500));
      INFO(o.checker.first);
      CHECK(o.checker.ok());
    }
  }
}

TEST_CASE("a second Stop replaces the first; its values count only when both exceed the first's",
          "[stop]") {
  // First stop 6000 / 60000 (adopted). 100 cycles later a second one.
  auto run = [](double deceleration, double jerk, plc::NCTOPLC_AXIS_REF* at_end) {
    kt::Harness h;
    h.post(kt::move_velocity(2000.0, 1));
    h.cycles(600);
    const uint16_t first = h.post(kt::simple(CommandType::kStop, 6000.0, 60000.0));
    h.cycles(100);
    int cycles = 100;
    uint16_t second = 0;
    if (deceleration > 0.0) {
      second = h.post(kt::simple(CommandType::kStop, deceleration, jerk));
      h.cycles(1);
      ++cycles;
      CHECK(h.state_of(first) == CommandState::kAborted);
      CHECK(h.state_of(second) == CommandState::kActive);
    }
    const uint16_t last = second != 0 ? second : first;
    cycles += h.cycles_until([&] { return h.state_of(last) == CommandState::kDone; });
    *at_end = h.x->NcToPlc;
    return cycles;
  };
  plc::NCTOPLC_AXIS_REF alone, sharper, not_both;
  const int n_alone = run(0.0, 0.0, &alone);
  const int n_sharper = run(12000.0, 120000.0, &sharper);
  const int n_not_both = run(12000.0, 60000.0, &not_both);
  // 2000 mm/s with 6000 / 60000: 2000/6000 + 0.1 = 0.4333 s.
  CHECK(n_alone == 434);
  CHECK(n_sharper < n_alone);
  // Not both larger: the first stop's braking goes on (same end, same time).
  CHECK(n_not_both == n_alone);
  CHECK(not_both.SetPos == Approx(alone.SetPos).margin(1e-9));
  CHECK(sharper.SetPos < alone.SetPos);
}
