// Random online changes (SPEC B1, B3-B6): starts, overrides, new end positions, new velocities,
// modulo starts, halts and stops at random cycles. Whatever the mix, the set values keep V, A+,
// A- and J at every cycle and change continuously within them, the axis never goes into error,
// a positioning that reports kDone stands exactly on its target, and after the mix a last
// positioning with a new end position ends exactly there. Fixed seed, printed.
#include <catch2/catch.hpp>

#include <cstdio>
#include <random>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::CommandType;

namespace {

#ifdef NCSDK_SANITIZED
constexpr int kRuns = 4;
constexpr int kCycles = 5000;
#else
constexpr int kRuns = 40;
constexpr int kCycles = 20000;
#endif
constexpr unsigned kSeed = 20240604u;

}  // namespace

TEST_CASE("random online changes keep the limits at every cycle and end exactly",
          "[override][new_pos][new_pos_and_velo][modulo][random]") {
  std::printf("test_new_pos_random_online_changes: seed %u, %d runs of %d cycles\n", kSeed, kRuns,
              kCycles);
  std::mt19937 rng(kSeed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto pick = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  long online_accepted = 0;
  for (int run = 0; run < kRuns; ++run) {
    INFO("run " << run);
    nc::AxisConfig config = kt::seed_axis();
    config.override_type = 1 + run % 4;
    kt::Harness h(config);
    kt::LimitChecker c = kt::LimitChecker::seed(2000.0);
    uint16_t positioning = 0;  // the last positioning start, to check its end
    uint16_t online = 0;       // the last NewPos / NewPosAndVelo
    for (int k = 0; k < kCycles; ++k) {
      const double r = unit(rng);
      if (r < 0.001) {
        positioning = h.post(kt::move_absolute(pick(-5000.0, 5000.0), pick(100.0, 2000.0)));
      } else if (r < 0.0015) {
        positioning = h.post(kt::move_modulo(pick(-800.0, 800.0), pick(100.0, 2000.0),
                                             1 + static_cast<int32_t>(unit(rng) * 3.0)));
      } else if (r < 0.00175) {
        h.post(kt::move_velocity(pick(100.0, 2000.0), unit(rng) < 0.5 ? 1 : 3));
      } else if (r < 0.003) {
        online = h.post(kt::new_pos(pick(-5000.0, 5000.0)));
      } else if (r < 0.00425) {
        const double end = pick(-5000.0, 5000.0);
        online = h.post(kt::new_pos_and_velo(end, pick(100.0, 2000.0), pick(-5000.0, 5000.0)));
      } else if (r < 0.00575) {
        kt::set_override(*h.x, unit(rng) < 0.15 ? 0.0 : pick(0.0, 100.0));
      } else if (r < 0.0059) {
        h.post(kt::simple(CommandType::kHalt));
      } else if (r < 0.0060) {
        h.post(kt::simple(CommandType::kStop));
      } else if (r < 0.0070) {
        h.post(kt::simple(CommandType::kStopRelease));
      }
      h.kernel.cycle();
      c.check(*h.x);
      REQUIRE(h.x->NcToPlc.ErrorCode == 0);
      if (online != 0 && h.state_of(online) == CommandState::kDone) {
        ++online_accepted;
        online = 0;
      }
      if (positioning != 0 && h.state_of(positioning) == CommandState::kDone) {
        if (h.x->NcToPlc.CmdNo == positioning) {
          REQUIRE(h.x->NcToPlc.SetPos == h.x->NcToPlc.TargetPos);
          REQUIRE(h.x->NcToPlc.SetVelo == 0.0);
        }
        positioning = 0;
      }
      if (!c.ok()) break;
    }
    // Whatever state the mix left: release, 100 %, a last positioning with a new end position
    // on the way, to its exact end.
    h.post(kt::simple(CommandType::kStopRelease));
    kt::set_override(*h.x, 100.0);
    double end = pick(-5000.0, 5000.0);
    const uint16_t last = h.post(kt::move_absolute(end, pick(100.0, 2000.0)));
    kt::checked_cycles(h, c, static_cast<int>(pick(1.0, 1000.0)));
    if (h.state_of(last) == CommandState::kActive) {
      end = pick(-5000.0, 5000.0);
      const uint16_t np = h.post(kt::new_pos(end));
      kt::checked_cycles(h, c, 1);
      REQUIRE(h.state_of(np) == CommandState::kDone);
    }
    REQUIRE(kt::checked_cycles_until(h, c,
                                     [&] { return h.state_of(last) == CommandState::kDone; }) > 0);
    CHECK(h.x->NcToPlc.SetPos == end);
    INFO(c.first);
    REQUIRE(c.ok());
  }
  // The mix did exercise the functions.
  CHECK(online_accepted > kRuns);
}
