// The blend velocity is limited to what the path allows, and online functions act on the running
// command with the blend kept (issue 14; docs/behaviour.md "BufferMode"), on the seed axis
// (A+ = A- = 5000 mm/s², J = 50000 mm/s³):
// - the next positioning must still stop at its own target: 0 → 1000 (V 1000), then → 1100
//   (V 2000, BlendingHigh) passes 1000 at the v whose stop v/2·(v/A + A/J) is 100 mm (780.8 mm/s)
//   and never passes 1100;
// - a first leg too short to reach the wanted speed (0 → 100, then BlendingHigh at 2000) passes at
//   what it can reach, never moving backwards;
// - override 50 % halves the pass (BlendingLow: 500 mm/s); MC_NewPos 1500 moves the pass there;
// - a blend posted while the first already brakes never moves backwards;
// - a MoveVelocity (current direction, 1500 mm/s, BlendingNext) passes the target at 1500 mm/s.
// Every run ends exactly at its last target with |a| <= A and |Δa| <= J·T every cycle.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

#include "kernel_harness.hpp"

using plc::CommandState;

namespace {

constexpr double kT = 0.001;
constexpr double kA = 5000.0;
constexpr double kJ = 50000.0;

struct Pass {
  double velocity = -1.0;  // set velocity in the cycle the set position reaches `at`
  double max_position = 0.0;
  double min_velocity = 0.0;
  double final_position = 0.0;
  int cycles = -1;
};

plc::Command with_mode(plc::Command c, plc::MC_BufferMode mode) {
  c.buffer_mode = mode;
  return c;
}

// Runs the first command, posts `second` after `post_after` cycles, calls `during(h, cycle)` each
// cycle, until the second is Done; records the pass of `at`.
Pass run(const plc::Command& first, const plc::Command& second, double at, int post_after = 1,
         const std::function<void(kt::Harness&, int)>& during = {}) {
  kt::Harness h;
  h.post(first);
  h.cycles(post_after);
  const uint16_t number = h.post(second);
  Pass r;
  kt::Sample prev = kt::sample(*h.x);
  for (int i = 1; i < 20000; ++i) {
    if (during) during(h, i);
    h.cycles(1);
    const kt::Sample s = kt::sample(*h.x);
    INFO("cycle " << i << " p " << s.set_pos << " v " << s.set_velo << " a " << s.set_acc);
    REQUIRE(std::abs(s.set_acc) <= kA * (1.0 + 1e-9));
    REQUIRE(std::abs(s.set_acc - prev.set_acc) <= kJ * kT * (1.0 + 1e-9));
    if (r.velocity < 0.0 && prev.set_pos < at && s.set_pos >= at) r.velocity = s.set_velo;
    r.max_position = std::max(r.max_position, s.set_pos);
    r.min_velocity = std::min(r.min_velocity, s.set_velo);
    prev = s;
    if (h.state_of(number) == CommandState::kDone) {
      r.cycles = i;
      break;
    }
  }
  REQUIRE(h.x->NcToPlc.ErrorCode == 0);
  r.final_position = h.x->NcToPlc.SetPos;
  return r;
}

}  // namespace

TEST_CASE("the blend is not faster than the next positioning can stop from", "[kernel][buffer]") {
  const Pass r = run(kt::move_absolute(1000.0, 1000.0),
                     with_mode(kt::move_absolute(1100.0, 2000.0), plc::MC_BlendingHigh), 1000.0);
  // v/2·(v/A + A/J) = 100 mm: v² / 10000 + 0.05 v - 100 = 0.
  const double v = (-0.05 + std::sqrt(0.05 * 0.05 + 4.0 * 100.0 / 10000.0)) / (2.0 / 10000.0);
  CHECK(v == Approx(780.776).epsilon(1e-5));
  CHECK(r.velocity == Approx(v).margin(0.1));
  CHECK(r.max_position == 1100.0);
  CHECK(r.final_position == 1100.0);
  CHECK(r.min_velocity >= 0.0);
}

TEST_CASE("a first leg too short for the wanted speed passes at what it reaches",
          "[kernel][buffer]") {
  const Pass buffered = run(kt::move_absolute(100.0, 1000.0),
                            with_mode(kt::move_absolute(2000.0, 2000.0), plc::MC_Buffered), 100.0);
  const Pass r = run(kt::move_absolute(100.0, 1000.0),
                     with_mode(kt::move_absolute(2000.0, 2000.0), plc::MC_BlendingHigh), 100.0);
  CHECK(r.velocity > 500.0);
  CHECK(r.velocity < 2000.0);
  CHECK(r.min_velocity >= 0.0);  // no run-up backwards
  CHECK(r.final_position == 2000.0);
  CHECK(r.cycles < buffered.cycles);
}

TEST_CASE("override and MC_NewPos act on the running command; the blend follows",
          "[kernel][buffer]") {
  const plc::Command first = kt::move_absolute(1000.0, 1000.0);
  const plc::Command next = with_mode(kt::move_absolute(2000.0, 2000.0), plc::MC_BlendingLow);
  SECTION("override 50 % before the pass: BlendingLow passes at 500 mm/s") {
    const Pass r = run(first, next, 1000.0, 1, [](kt::Harness& h, int cycle) {
      if (cycle == 100) kt::set_override(*h.x, 50.0);
    });
    CHECK(r.velocity == Approx(500.0).margin(0.1));
    CHECK(r.final_position == 2000.0);
  }
  SECTION("MC_NewPos 1500 while the blend waits: passes 1500 at 1000 mm/s") {
    const Pass r = run(first, next, 1500.0, 1, [](kt::Harness& h, int cycle) {
      if (cycle == 300) h.post(kt::new_pos(1500.0));
    });
    CHECK(r.velocity == Approx(1000.0).margin(0.1));
    CHECK(r.final_position == 2000.0);
    CHECK(r.min_velocity >= 0.0);
  }
}

TEST_CASE("a blend posted while the first already brakes never moves backwards",
          "[kernel][buffer]") {
  // 0 → 1000 at V 1000 brakes from about 1.1 s on (1000 cycles of the run); posted at 1.2 s.
  for (int post_after : {1150, 1200, 1250, 1290}) {
    INFO("posted after " << post_after << " cycles");
    const Pass r =
        run(kt::move_absolute(1000.0, 1000.0),
            with_mode(kt::move_absolute(2000.0, 2000.0), plc::MC_BlendingNext), 1000.0, post_after);
    CHECK(r.min_velocity >= 0.0);
    CHECK(r.max_position == 2000.0);
    CHECK(r.final_position == 2000.0);
  }
}

TEST_CASE("MoveVelocity blended behind a positioning passes its target at its velocity",
          "[kernel][buffer]") {
  kt::Harness h;
  h.post(kt::move_absolute(1000.0, 1000.0));
  h.cycles(1);
  const uint16_t jog =
      h.post(with_mode(kt::move_velocity(1500.0, plc::MC_Current_Direction), plc::MC_BlendingNext));
  double pass = -1.0;
  const int n = h.cycles_until(
      [&] {
        if (pass < 0.0 && h.x->NcToPlc.SetPos >= 1000.0) pass = h.x->NcToPlc.SetVelo;
        return h.state_of(jog) == CommandState::kReached;
      },
      5000);
  REQUIRE(n > 0);
  CHECK(pass == Approx(1500.0).margin(0.1));
  CHECK(h.x->NcToPlc.SetVelo == 1500.0);
}
