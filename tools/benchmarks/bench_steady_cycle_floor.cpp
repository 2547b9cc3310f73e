// A floor for issue 8's aim, not a kernel: the least work a steady NC cycle of n moving axes must
// do, written the way a structure-of-arrays kernel would do it, measured beside
// bench_kernel_cycle (same counter, per_axis_cycle). Per axis and cycle: the mailbox's count
// looked at, one cubic sample of the current profile segment, the position controller, the
// drive model of bench_kernel_cycle's axes (every odd axis a first-order lag with a dead time of
// 2 cycles), the encoder's quantisation, the following-error filter and the target window, and
// the NcToPlc image the contract asks for (the real plc::AXIS_REF, 20 fields and StateDWord).
// Left out, so the floor is below what any faithful kernel can reach: segment changes, commands,
// planning, superposition, override, modulo positions, software limits, AxisState, error paths.
// docs/performance.md ("A floor for the steady cycle") gives the numbers and what they mean.
//
// Run: cmake -DNCSDK_BUILD_BENCHMARKS=ON … && ./build/tools/benchmarks/bench_steady_cycle_floor
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "axis_cycle_counters.hpp"
#include "plc_interface/axis_ref.hpp"

namespace {

constexpr double kCycle = 0.001;
constexpr std::size_t kDeadCycles = 2;

// The hot values of all axes, one array each.
struct SteadyAxes {
  explicit SteadyAxes(std::size_t n)
      : t(n, 0.0),
        p0(n, 0.0),
        v0(n),
        a0(n, 0.0),
        j0(n, 0.0),
        set_p(n, 0.0),
        drive_p(n, 0.0),
        act_p(n, 0.0),
        act_v(n, 0.0),
        decay(n),
        lag(n),
        target(n),
        fe_count(n, 0),
        delay(n, std::array<double, kDeadCycles>{}),
        head(n, 0),
        refs(n) {
    for (std::size_t i = 0; i < n; ++i) {
      v0[i] = 1500.0 - static_cast<double>(i % 7);  // a cruise, as most cycles of the scenario
      lag[i] = i % 2 == 1;
      decay[i] = lag[i] ? std::exp(-kCycle / 0.002) : 0.0;
      target[i] = 300.0 + static_cast<double>(i);
    }
  }
  std::vector<double> t, p0, v0, a0, j0, set_p, drive_p, act_p, act_v, decay;
  std::vector<uint8_t> lag;
  std::vector<double> target;
  std::vector<uint32_t> fe_count;
  std::vector<std::array<double, kDeadCycles>> delay;
  std::vector<uint32_t> head;
  std::vector<plc::AXIS_REF> refs;  // the contract's image, 2.3 kB apart as in the kernel
};

// Not inlined, so that callgrind can count it alone (one call per cycle of all axes).
[[gnu::noinline]] void cycle(SteadyAxes& x, uint32_t counter, uint64_t& events) noexcept {
  constexpr double kTau = 0.002;
  constexpr double kIncrement = 1e-4;
  constexpr double kKv = 1.0;
  constexpr double kFollowingLimit = 5.0;
  constexpr double kWindow = 2.0;
  const std::size_t n = x.t.size();
  for (std::size_t i = 0; i < n; ++i) {
    plc::AXIS_REF& ref = x.refs[i];
    if (ref.Mailbox.pending() != 0) ++events;  // a command: the rare path
    // Set values: one cubic of the current segment.
    const double dt = (x.t[i] += kCycle);
    const double j = x.j0[i];
    const double a = x.a0[i] + j * dt;
    const double v = x.v0[i] + dt * (x.a0[i] + 0.5 * j * dt);
    const double p = x.p0[i] + dt * (x.v0[i] + dt * (0.5 * x.a0[i] + dt * j * (1.0 / 6.0)));
    // Position control (feed-forward of the mean set velocity) and the drive.
    double u = (p - x.set_p[i]) / kCycle + kKv * (x.set_p[i] - x.act_p[i]);
    x.set_p[i] = p;
    if (x.lag[i] != 0) {
      const double delayed = x.delay[i][x.head[i]];
      x.delay[i][x.head[i]] = u;
      x.head[i] = x.head[i] + 1 == kDeadCycles ? 0 : x.head[i] + 1;
      u = delayed;
    }
    const double before = x.act_v[i];
    const double gap = before - u;
    const double d = x.decay[i];
    x.drive_p[i] += u * kCycle + gap * kTau * (1.0 - d);
    const double velocity = u + gap * d;
    x.act_v[i] = velocity;
    const double actual = std::nearbyint(x.drive_p[i] / kIncrement) * kIncrement;
    x.act_p[i] = actual;
    // Monitors.
    const double following = p - actual;
    x.fe_count[i] = std::fabs(following) > kFollowingLimit ? x.fe_count[i] + 1 : 0;
    if (x.fe_count[i] > 3) ++events;  // an error: the rare path
    const bool in_target = std::fabs(actual - x.target[i]) <= kWindow;
    // The image.
    plc::NCTOPLC_AXIS_REF& out = ref.NcToPlc;
    out.SetPos = p;
    out.SetVelo = v;
    out.SetAcc = a;
    out.SetJerk = j;
    out.ActPos = actual;
    out.ActVelo = velocity;
    out.ActAcc = (velocity - before) / kCycle;
    out.PosDiff = following;
    out.ModuloActPos = actual;
    out.ModuloSetPos = p;
    out.TargetPos = x.target[i];
    out.TargetVelo = x.v0[i];
    out.CycleCounter = counter;
    const auto bit = [](bool value, plc::StateBit at) {
      return static_cast<uint32_t>(value) << static_cast<uint32_t>(at);
    };
    constexpr uint32_t kPerCycle =
        (1U << plc::kStateNotMoving) | (1U << plc::kStateInTargetPosition) |
        (1U << plc::kStatePositiveDirection) | (1U << plc::kStateNegativeDirection) |
        (1U << plc::kStateConstantVelocity);
    out.StateDWord =
        (out.StateDWord & ~kPerCycle) | bit(std::fabs(velocity) < 0.001, plc::kStateNotMoving) |
        bit(in_target, plc::kStateInTargetPosition) | bit(v > 0.0, plc::kStatePositiveDirection) |
        bit(v < 0.0, plc::kStateNegativeDirection) |
        bit(a == 0.0 && j == 0.0 && v != 0.0, plc::kStateConstantVelocity);
  }
}

void BM_SteadyCycleFloor(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  SteadyAxes axes(n);
  uint32_t counter = 0;
  uint64_t events = 0;
  for (auto _ : state) {
    cycle(axes, ++counter, events);
    benchmark::ClobberMemory();
  }
  benchmark::DoNotOptimize(events);
  bench::count_axis_cycles(state, n);
}

}  // namespace

BENCHMARK(BM_SteadyCycleFloor)->Arg(1)->Arg(64)->Arg(1024)->Arg(4096);
BENCHMARK_MAIN();
