// The override (SPEC B3, seed 000 §2.2) with the seed's figures: 0 → 5000 mm at V = 2000 mm/s,
// A+ = A- = 5000 mm/s², J = 50000 mm/s³. Instantaneous, not time-scaled: a new level is reached
// as fast as the limits allow, a lower one from above without undershoot; override 0 waits at
// rest (at the start) or comes to rest on the path (in motion), and the job goes on when it
// rises. The limits hold at every cycle.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "kernel_harness.hpp"

using plc::CommandState;

namespace {

struct Trace {
  std::vector<double> p, v;
  void add(const plc::AXIS_REF& x) {
    p.push_back(x.NcToPlc.SetPos);
    v.push_back(x.NcToPlc.SetVelo);
  }
  // min / max of v over the samples [from, to) (sample i = cycle i + 1 after the post).
  double v_min(std::size_t from, std::size_t to) const {
    return *std::min_element(v.begin() + static_cast<long>(from),
                             v.begin() + static_cast<long>(to));
  }
  double v_max(std::size_t from, std::size_t to) const {
    return *std::max_element(v.begin() + static_cast<long>(from),
                             v.begin() + static_cast<long>(to));
  }
};

// Cycles with the limit check and the trace.
void run(kt::Harness& h, kt::LimitChecker& c, Trace& t, int n) {
  for (int i = 0; i < n; ++i) {
    h.kernel.cycle();
    c.check(*h.x);
    t.add(*h.x);
  }
}

}  // namespace

TEST_CASE(
    "override 100 % -> 75 % -> 100 % during 0 -> 5000 mm: a plateau at exactly 1500 mm/s "
    "without undershoot, back to 2000 mm/s, exact end",
    "[override]") {
  kt::Harness h;
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
  Trace t;
  const uint16_t move = h.post(kt::move_absolute(5000.0, 2000.0));
  run(h, c, t, 1000);  // t = 1.0 s: cruising at 2000 since 0.5 s, at 1500 mm
  CHECK(t.v.back() == Approx(2000.0).margin(1e-9));
  CHECK(t.p.back() == Approx(1500.0).margin(1e-9));

  kt::set_override(*h.x, 75.0);
  run(h, c, t, 1000);
  CHECK(h.x->NcToPlc.TargetVelo == 1500.0);
  // 2000 → 1500 is a jerk-limited step of 500 = A²/J: 0.2 s, then the plateau.
  CHECK(t.v_min(1000, 2000) >= 1500.0 - 1e-9);  // no undershoot
  CHECK(t.v_min(1200, 2000) == Approx(1500.0).margin(1e-9));
  CHECK(t.v_max(1200, 2000) == Approx(1500.0).margin(1e-9));
  CHECK(t.v[1100] < 2000.0);
  CHECK(t.v[1100] > 1500.0);

  kt::set_override(*h.x, 100.0);
  run(h, c, t, 200);
  CHECK(h.x->NcToPlc.TargetVelo == 2000.0);
  CHECK(t.v.back() == Approx(2000.0).margin(1e-9));  // back at 2000 after 0.2 s
  REQUIRE(kt::checked_cycles_until(h, c, [&] { return h.state_of(move) == CommandState::kDone; }) >
          0);
  CHECK(h.x->NcToPlc.SetPos == 5000.0);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE("override 20 % at the start gives 400 mm/s; raised to 100 % the axis reaches 2000 mm/s",
          "[override]") {
  kt::Harness h;
  kt::set_override(*h.x, 20.0);
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
  Trace t;
  const uint16_t move = h.post(kt::move_absolute(5000.0, 2000.0));
  run(h, c, t, 1000);
  CHECK(h.state_of(move) == CommandState::kActive);
  CHECK(h.x->NcToPlc.TargetVelo == 400.0);
  // 0 → 400 (< A²/J): 2·sqrt(400 / 50000) = 0.179 s, then 400 until the override changes.
  CHECK(t.v_max(0, 1000) == Approx(400.0).margin(1e-9));
  CHECK(t.v_min(200, 1000) == Approx(400.0).margin(1e-9));
  CHECK(t.v[150] < 400.0);

  kt::set_override(*h.x, 100.0);
  run(h, c, t, 1000);
  CHECK(t.v_max(1000, 2000) == Approx(2000.0).margin(1e-9));
  REQUIRE(kt::checked_cycles_until(h, c, [&] { return h.state_of(move) == CommandState::kDone; }) >
          0);
  CHECK(h.x->NcToPlc.SetPos == 5000.0);
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE(
    "a start at override 0 is accepted and waits at standstill; it moves when the override "
    "rises",
    "[override]") {
  kt::Harness h;
  kt::set_override(*h.x, 0.0);
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
  const uint16_t move = h.post(kt::move_absolute(5000.0, 2000.0));
  kt::checked_cycles(h, c, 500);
  CHECK(h.state_of(move) == CommandState::kActive);
  CHECK(h.x->NcToPlc.CmdNo == move);
  CHECK(h.x->NcToPlc.SetPos == 0.0);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  CHECK(h.x->NcToPlc.TargetPos == 5000.0);
  CHECK(h.x->NcToPlc.TargetVelo == 0.0);
  CHECK(kt::bit(*h.x, plc::kStateHasJob));
  CHECK(kt::axis_state(*h.x) == plc::AxisState::kDiscreteMotion);

  kt::set_override(*h.x, 100.0);
  // From rest the table is the start's: 0.5 s up, 2.0 s at 2000, 0.5 s down = 3000 cycles.
  kt::checked_cycles(h, c, 2999);
  CHECK(h.x->NcToPlc.SetPos < 5000.0);
  kt::checked_cycles(h, c, 1);
  CHECK(h.x->NcToPlc.SetPos == 5000.0);
  REQUIRE(kt::checked_cycles_until(h, c, [&] { return h.state_of(move) == CommandState::kDone; }) >
          0);
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE(
    "override 0 in motion brings the axis to rest on its path, the job stays active, and it "
    "resumes to the exact end when the override rises",
    "[override]") {
  kt::Harness h;
  kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
  const uint16_t move = h.post(kt::move_absolute(5000.0, 2000.0));
  kt::checked_cycles(h, c, 1000);  // 2000 mm/s at 1500 mm
  kt::set_override(*h.x, 0.0);
  // The shortest stop from 2000 mm/s: 0.5 s over 500 mm.
  kt::checked_cycles(h, c, 499);
  CHECK(h.x->NcToPlc.SetVelo > 0.0);
  kt::checked_cycles(h, c, 1);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  CHECK(h.x->NcToPlc.SetPos == Approx(2000.0).margin(1e-9));
  const double rest = h.x->NcToPlc.SetPos;
  kt::checked_cycles(h, c, 300);
  CHECK(h.x->NcToPlc.SetPos == rest);
  CHECK(h.state_of(move) == CommandState::kActive);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK(kt::axis_state(*h.x) == plc::AxisState::kDiscreteMotion);

  kt::set_override(*h.x, 100.0);
  REQUIRE(kt::checked_cycles_until(h, c, [&] { return h.state_of(move) == CommandState::kDone; }) >
          0);
  CHECK(h.x->NcToPlc.SetPos == 5000.0);
  INFO(c.first);
  CHECK(c.ok());
}

TEST_CASE("an override changed during the brake phase has no effect", "[override][brake]") {
  // 0 → 3000 mm: the final deceleration begins at 1.5 s (2500 mm).
  kt::TwinKernels t;
  const uint16_t move = t.probe.post(kt::move_absolute(3000.0, 2000.0));
  t.reference.post(kt::move_absolute(3000.0, 2000.0));
  t.cycles(1550);
  REQUIRE(t.probe.x->NcToPlc.SetAcc < 0.0);
  kt::set_override(*t.probe.x, 50.0);
  t.cycles(100);
  kt::set_override(*t.probe.x, 0.0);
  for (int i = 0; i < 400; ++i) {
    t.cycles(1);
    REQUIRE(t.same());
  }
  CHECK(t.probe.state_of(move) == CommandState::kDone);
  CHECK(t.probe.x->NcToPlc.SetPos == 3000.0);
}

TEST_CASE("an override changed just before the brake phase acts", "[override][brake]") {
  kt::TwinKernels t;
  t.both(kt::move_absolute(3000.0, 2000.0));
  t.cycles(1450);  // 50 ms before the brake phase
  kt::set_override(*t.probe.x, 50.0);
  t.cycles(10);
  CHECK(t.probe.x->NcToPlc.SetVelo < t.reference.x->NcToPlc.SetVelo);
}
