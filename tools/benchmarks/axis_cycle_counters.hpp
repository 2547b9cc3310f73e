// The counters every kernel benchmark reports: the number of axes and the time per axis-cycle
// (the run's time per iteration divided by the axes one iteration cycles).
#pragma once

#include <benchmark/benchmark.h>

#include <cstddef>

namespace bench {

inline void count_axis_cycles(benchmark::State& state, std::size_t axes) {
  state.counters["axes"] = static_cast<double>(axes);
  state.counters["per_axis_cycle"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * static_cast<double>(axes),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace bench
