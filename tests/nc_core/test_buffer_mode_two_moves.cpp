// BufferMode on the kernel (issue 14): MoveAbsolute 0 → 1000 at V 1000, then → 2000 at V 2000
// posted behind it. MC_Buffered stops at 1000 (v = 0) and goes on; BlendingLow and
// BlendingPrevious pass 1000 at 1000 mm/s, BlendingNext and BlendingHigh at 2000 mm/s; each
// ends exactly at 2000 with the axis's limits held every cycle (|v| <= 2000, |a| <= 5000,
// |Δa| <= J·T), the first command Done in the cycle the second becomes the executed one, and
// every blend faster than Buffered. A reversal (1000, then back to 0) passes 1000 at v = 0.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "kernel_harness.hpp"

using plc::CommandState;

namespace {

constexpr double kT = 0.001;
constexpr double kA = 5000.0;   // seed axis A+ = A-
constexpr double kJ = 50000.0;  // seed axis J

struct Run {
  int cycles = -1;              // until the second command is Done (-1: never)
  double pass_velocity = -1.0;  // set velocity in the cycle the set position reaches 1000
  bool stopped_at_first = false;
  double max_position = 0.0;
  double final_position = 0.0;
  int takeover_cycle = -1;  // the cycle the second command became CmdNo
  int first_done_cycle = -1;
};

plc::Command buffered(plc::Command c, plc::MC_BufferMode mode) {
  c.buffer_mode = mode;
  return c;
}

Run run_two(plc::MC_BufferMode mode, double second_target, double second_velocity) {
  kt::Harness h;
  const uint16_t first = h.post(kt::move_absolute(1000.0, 1000.0));
  h.cycles(1);
  REQUIRE(h.state_of(first) == CommandState::kActive);
  const uint16_t second = h.post(buffered(kt::move_absolute(second_target, second_velocity), mode));
  h.cycles(1);
  REQUIRE(h.state_of(second) == CommandState::kBuffered);
  REQUIRE(h.x->NcToPlc.CmdNo == first);

  Run r;
  kt::Sample prev = kt::sample(*h.x);
  const double vmax = std::max(1000.0, second_velocity);
  for (int i = 1; i < 20000; ++i) {
    h.cycles(1);
    const kt::Sample s = kt::sample(*h.x);
    INFO("cycle " << i << " p " << s.set_pos << " v " << s.set_velo << " a " << s.set_acc);
    REQUIRE(std::abs(s.set_velo) <= vmax * (1.0 + 1e-12));
    REQUIRE(std::abs(s.set_acc) <= kA * (1.0 + 1e-9));
    REQUIRE(std::abs(s.set_acc - prev.set_acc) <= kJ * kT * (1.0 + 1e-9));
    if (r.pass_velocity < 0.0 && prev.set_pos < 1000.0 && s.set_pos >= 1000.0) {
      r.pass_velocity = s.set_velo;
    }
    if (s.set_pos == 1000.0 && s.set_velo == 0.0) r.stopped_at_first = true;
    r.max_position = std::max(r.max_position, s.set_pos);
    if (r.first_done_cycle < 0 && h.state_of(first) == CommandState::kDone) r.first_done_cycle = i;
    if (r.takeover_cycle < 0 && s.cmd_no == second) {
      r.takeover_cycle = i;
      REQUIRE(h.state_of(second) == CommandState::kActive);
    }
    if (r.takeover_cycle < 0) REQUIRE(h.state_of(second) == CommandState::kBuffered);
    prev = s;
    if (h.state_of(second) == CommandState::kDone) {
      r.cycles = i;
      break;
    }
  }
  r.final_position = h.x->NcToPlc.SetPos;
  REQUIRE(h.x->NcToPlc.ErrorCode == 0);
  return r;
}

}  // namespace

TEST_CASE("two MoveAbsolute 0 -> 1000 (V 1000) -> 2000 (V 2000) in each BufferMode",
          "[kernel][buffer]") {
  const Run buffered_run = run_two(plc::MC_Buffered, 2000.0, 2000.0);
  CHECK(buffered_run.stopped_at_first);
  CHECK(buffered_run.pass_velocity == 0.0);
  CHECK(buffered_run.final_position == 2000.0);
  CHECK(buffered_run.first_done_cycle == buffered_run.takeover_cycle);
  REQUIRE(buffered_run.cycles > 0);

  struct Blend {
    plc::MC_BufferMode mode;
    const char* name;
    double pass;
  };
  for (const Blend& b : {Blend{plc::MC_BlendingLow, "BlendingLow", 1000.0},
                         Blend{plc::MC_BlendingPrevious, "BlendingPrevious", 1000.0},
                         Blend{plc::MC_BlendingNext, "BlendingNext", 2000.0},
                         Blend{plc::MC_BlendingHigh, "BlendingHigh", 2000.0}}) {
    SECTION(b.name) {
      const Run r = run_two(b.mode, 2000.0, 2000.0);
      // Within one cycle of the pass the acceleration is near 0: J·T² = 0.05 mm/s at most.
      CHECK(r.pass_velocity == Approx(b.pass).margin(0.1));
      CHECK_FALSE(r.stopped_at_first);
      CHECK(r.final_position == 2000.0);
      CHECK(r.first_done_cycle == r.takeover_cycle);
      REQUIRE(r.cycles > 0);
      CHECK(r.cycles < buffered_run.cycles);
    }
  }
}

TEST_CASE("a blend into a reversal (1000, then back to 0) passes 1000 at v = 0",
          "[kernel][buffer]") {
  for (plc::MC_BufferMode mode : {plc::MC_BlendingLow, plc::MC_BlendingPrevious,
                                  plc::MC_BlendingNext, plc::MC_BlendingHigh}) {
    INFO("mode " << static_cast<int>(mode));
    const Run r = run_two(mode, 0.0, 2000.0);
    CHECK(r.stopped_at_first);
    CHECK(r.max_position == 1000.0);
    CHECK(r.final_position == 0.0);
    CHECK(r.first_done_cycle == r.takeover_cycle);
  }
}
