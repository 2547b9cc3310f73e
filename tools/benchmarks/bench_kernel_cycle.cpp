// One NC cycle with 1, 64, 1024 and 4096 moving axes (issue 2's benchmark). Reported as the counter
// per_axis_cycle: the time of one Kernel::cycle (and, in the *WithBlocks variant, of the axes'
// MC_Power and MC_MoveAbsolute calls) divided by the number of axes, in seconds, printed with an
// SI prefix ("45n" = 45 ns).
//
// Every axis moves back and forth between 0 and 300 + i mm at 1500 mm/s, so the cycle contains
// the whole path: mailbox, planning (about every 0.5 s of simulated time per axis), profile
// sampling, controller, drive, monitors and the NcToPlc image. Half the axes run the first-order
// lag drive with a dead time.
//
// Run: cmake -DNCSDK_BUILD_BENCHMARKS=ON … && ./build/tools/benchmarks/bench_kernel_cycle
#include <benchmark/benchmark.h>

#include <cstddef>
#include <string>
#include <vector>

#include "axis_cycle_counters.hpp"
#include "back_and_forth.hpp"
#include "fb/fb.hpp"
#include "nc_core/kernel.hpp"

namespace {

void enable(plc::AXIS_REF& axis) {
  axis.PlcToNc.ControlDWord = (1U << plc::kControlEnable) | (1U << plc::kControlFeedEnablePlus) |
                              (1U << plc::kControlFeedEnableMinus);
}

// The kernel alone; a minimal PLC posts the next move when the last one is done.
void BM_KernelCycle(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  nc::Kernel kernel;
  std::vector<plc::AXIS_REF*> axes;
  bench::BackAndForth moves(n);
  for (std::size_t i = 0; i < n; ++i) {
    axes.push_back(&kernel.add_axis(bench::kernel_axis(i)));
    enable(*axes.back());
  }
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i)
      moves.step(*axes[i], i);
    kernel.cycle();
  }
  bench::count_axis_cycles(state, n);
}

// The kernel plus each axis's MC_Power and MC_MoveAbsolute, called every cycle as a PLC would.
void BM_KernelCycleWithBlocks(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  nc::Kernel kernel;
  std::vector<plc::AXIS_REF*> axes;
  for (std::size_t i = 0; i < n; ++i)
    axes.push_back(&kernel.add_axis(bench::kernel_axis(i)));
  std::vector<fb::MC_Power> power(n);
  std::vector<fb::MC_MoveAbsolute> move(n);
  std::vector<bool> forward(n, true);
  for (auto _ : state) {
    for (std::size_t i = 0; i < n; ++i) {
      plc::AXIS_REF& a = *axes[i];
      power[i].Enable = true;
      power[i].Enable_Positive = true;
      power[i].Enable_Negative = true;
      power[i](a);
      fb::MC_MoveAbsolute& m = move[i];
      if (m.Done) {
        m.Execute = false;
        forward[i] = !forward[i];
      } else if (power[i].Status && !m.Busy) {
        m.Execute = true;
        m.Position = forward[i] ? 300.0 + static_cast<double>(i) : 0.0;
        m.Velocity = 1500.0;
      }
      m(a);
    }
    kernel.cycle();
  }
  bench::count_axis_cycles(state, n);
}

}  // namespace

BENCHMARK(BM_KernelCycle)->Arg(1)->Arg(64)->Arg(1024)->Arg(4096);
BENCHMARK(BM_KernelCycleWithBlocks)->Arg(1)->Arg(64)->Arg(1024)->Arg(4096);

BENCHMARK_MAIN();
