// Issue 9's benchmark: one NC cycle with 512 masters each driving one linear slave (1024 axes),
// against 1024 masters moving alone — "a slave costs no more than a master". Reported as the
// counter per_axis_cycle: the time of one Kernel::cycle divided by the number of axes, in
// seconds, printed with an SI prefix ("45n" = 45 ns).
//
// Every master moves back and forth between 0 and 300 + i mm at 1500 mm/s (back_and_forth.hpp,
// as in bench_kernel_cycle); in the pairs each odd axis follows the even one before it with factor
// 0.75, coupled at rest before the measurement.
//
// Run: cmake -DNCSDK_BUILD_BENCHMARKS=ON … && ./build/tools/benchmarks/bench_gear_cycle
#include <benchmark/benchmark.h>

#include <cstddef>
#include <string>
#include <vector>

#include "axis_cycle_counters.hpp"
#include "back_and_forth.hpp"
#include "nc_core/kernel.hpp"

namespace {

void enable(plc::AXIS_REF& axis) {
  axis.PlcToNc.ControlDWord = (1U << plc::kControlEnable) | (1U << plc::kControlFeedEnablePlus) |
                              (1U << plc::kControlFeedEnableMinus);
}

// `n` axes; with `pairs`, every odd axis is coupled to the even one before it. The masters move.
void run(benchmark::State& state, bool pairs) {
  const auto n = static_cast<std::size_t>(state.range(0));
  nc::Kernel kernel;
  std::vector<plc::AXIS_REF*> axes;
  for (std::size_t i = 0; i < n; ++i) {
    nc::AxisConfig c;
    c.name = "axis" + std::to_string(i);
    axes.push_back(&kernel.add_axis(c));
    enable(*axes.back());
  }
  kernel.cycle();
  std::vector<bool> moves(n, true);
  if (pairs) {
    for (std::size_t i = 1; i < n; i += 2) {
      plc::Command c;
      c.type = plc::CommandType::kGearIn;
      c.other_axis = static_cast<int32_t>(i - 1);
      c.ratio = 0.75;
      axes[i]->Mailbox.post(c);
      moves[i] = false;
    }
    kernel.cycle();
  }
  bench::BackAndForth motion(n);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) {
      if (moves[i]) motion.step(*axes[i], i);
    }
    kernel.cycle();
  }
  bench::count_axis_cycles(state, n);
}

void BM_MastersAlone(benchmark::State& state) {
  run(state, false);
}
void BM_MasterSlavePairs(benchmark::State& state) {
  run(state, true);
}

}  // namespace

BENCHMARK(BM_MastersAlone)->Arg(1024);
BENCHMARK(BM_MasterSlavePairs)->Arg(1024);

BENCHMARK_MAIN();
