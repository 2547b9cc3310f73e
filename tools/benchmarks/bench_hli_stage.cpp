// The HLI coupling stage (nc_core/src/hli) on its own: one HliStage::cycle() with n axes, each
// the target of 8 sources (itself and the next 7 axes, in DIRECT, MIRROR, FRACT and ZERO modes),
// every program moving — the 64 targets × 8 sources. BM_HliStageTakeList adds one list
// evaluation (parse, checks, row rewrite) to each cycle, at rest; BM_HliStageFewTargets has 1024
// axes of which 64 are targets. Reported per stage cycle.
//
// Run: cmake -DNCSDK_BUILD_BENCHMARKS=ON … && ./build/tools/benchmarks/bench_hli_stage
#include <benchmark/benchmark.h>

#include <cstddef>
#include <vector>

#include "hli_stage_rig.hpp"

namespace {

namespace h = plc::hli;

// The test rig (tests/support/hli_stage_rig.hpp) with every axis the target of a full list.
struct Bench : hlitest::Rig {
  static std::vector<nc::hli::AxisSetup> setups(std::size_t axes) {
    std::vector<nc::hli::AxisSetup> s(axes);
    for (std::size_t i = 0; i < axes; ++i)
      s[i].ax_nr = static_cast<int>(i) + 1;
    return s;
  }

  explicit Bench(std::size_t axes) : Rig(setups(axes)) {
    for (std::size_t i = 0; i < n(); ++i)
      list(i);
    Rig::cycle();
  }

  void list(std::size_t i) {
    static constexpr uint16_t kModes[] = {h::HLI_AXIS_COUPLING_DIRECT, h::HLI_AXIS_COUPLING_MIRROR,
                                          h::HLI_AXIS_COUPLING_FRACT, h::HLI_AXIS_COUPLING_ZERO};
    h::HLI_AX_COUPLING_COMMAND& c = unit(i).command_w;
    for (std::size_t k = 0; k < c.desc.size(); ++k) {
      c.desc[k] = {static_cast<int>((i + k) % n()) + 1, kModes[k % 4], 3, 7};
    }
    c.semaphor_rw = true;
  }
};

void BM_HliStageCycle(benchmark::State& state) {
  Bench b(static_cast<std::size_t>(state.range(0)));
  for (std::size_t i = 0; i < b.n(); ++i)
    b.qv[i] = 1.0 + static_cast<double>(i);
  for (auto _ : state) {
    for (std::size_t i = 0; i < b.n(); ++i)
      b.q[i] += b.qv[i] * 0.001;
    b.cycle();
    benchmark::DoNotOptimize(b.d.data());
  }
}
BENCHMARK(BM_HliStageCycle)->Arg(8)->Arg(64);

// A large kernel with few couplings: 1024 axes, 64 of them targets of 8 sources each.
void BM_HliStageFewTargets(benchmark::State& state) {
  Bench b(1024);
  for (std::size_t i = 64; i < b.n(); ++i)
    b.command(i, {hlitest::inactive()});
  b.cycle();
  for (std::size_t i = 0; i < b.n(); ++i)
    b.qv[i] = 1.0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < b.n(); ++i)
      b.q[i] += b.qv[i] * 0.001;
    b.cycle();
    benchmark::DoNotOptimize(b.d.data());
  }
}
BENCHMARK(BM_HliStageFewTargets);

void BM_HliStageTakeList(benchmark::State& state) {
  Bench b(static_cast<std::size_t>(state.range(0)));
  std::size_t next = 0;
  for (auto _ : state) {
    b.list(next);
    next = (next + 1) % b.n();
    b.cycle();
    benchmark::DoNotOptimize(b.d.data());
  }
}
BENCHMARK(BM_HliStageTakeList)->Arg(64);

}  // namespace

BENCHMARK_MAIN();
