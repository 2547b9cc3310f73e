// A fixed-length run of bench_kernel_cycle's scenario for instruction counts, which (unlike the
// times of the benchmark) do not depend on the load of the machine:
//
//   valgrind --tool=callgrind --toggle-collect='nc::Kernel::cycle()'
//     --toggle-collect='(anonymous namespace)::run_blocks*' kernel_cycle_instructions blocks 1024
//     1000
//
// Arguments: "kernel" (the minimal PLC posts into the mailboxes) or "blocks" (each axis's
// MC_Power and MC_MoveAbsolute are called, as in BM_KernelCycleWithBlocks), the number of axes
// and the number of cycles. Instructions per axis-cycle = the collected total / (axes · cycles).
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "back_and_forth.hpp"
#include "fb/fb.hpp"
#include "nc_core/kernel.hpp"

namespace {

struct Blocks {
  std::vector<fb::MC_Power> power;
  std::vector<fb::MC_MoveAbsolute> move;
  std::vector<bool> forward;
};

// The block calls of one cycle (kept out of line so that callgrind can collect them alone).
[[gnu::noinline]] void run_blocks(Blocks& b, const std::vector<plc::AXIS_REF*>& axes) {
  for (std::size_t i = 0; i < axes.size(); ++i) {
    plc::AXIS_REF& a = *axes[i];
    b.power[i].Enable = true;
    b.power[i].Enable_Positive = true;
    b.power[i].Enable_Negative = true;
    b.power[i](a);
    fb::MC_MoveAbsolute& m = b.move[i];
    if (m.Done) {
      m.Execute = false;
      b.forward[i] = !b.forward[i];
    } else if (b.power[i].Status && !m.Busy) {
      m.Execute = true;
      m.Position = b.forward[i] ? 300.0 + static_cast<double>(i) : 0.0;
      m.Velocity = 1500.0;
    }
    m(a);
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 || (std::strcmp(argv[1], "kernel") != 0 && std::strcmp(argv[1], "blocks") != 0)) {
    std::fprintf(stderr, "usage: %s kernel|blocks AXES CYCLES\n", argv[0]);
    return 2;
  }
  const bool blocks = std::strcmp(argv[1], "blocks") == 0;
  const auto n = static_cast<std::size_t>(std::strtoul(argv[2], nullptr, 10));
  const long cycles = std::strtol(argv[3], nullptr, 10);
  nc::Kernel kernel;
  std::vector<plc::AXIS_REF*> axes;
  for (std::size_t i = 0; i < n; ++i)
    axes.push_back(&kernel.add_axis(bench::kernel_axis(i)));
  bench::BackAndForth moves(n);
  Blocks b{std::vector<fb::MC_Power>(n), std::vector<fb::MC_MoveAbsolute>(n),
           std::vector<bool>(n, true)};
  if (!blocks) {
    for (plc::AXIS_REF* a : axes)
      a->PlcToNc.ControlDWord = (1U << plc::kControlEnable) | (1U << plc::kControlFeedEnablePlus) |
                                (1U << plc::kControlFeedEnableMinus);
  }
  double sum = 0.0;
  for (long c = 0; c < cycles; ++c) {
    if (blocks) {
      run_blocks(b, axes);
    } else {
      for (std::size_t i = 0; i < n; ++i)
        moves.step(*axes[i], i);
    }
    kernel.cycle();
  }
  for (const plc::AXIS_REF* a : axes)
    sum += a->NcToPlc.ActPos;
  std::printf("%s %zu axes, %ld cycles, sum of ActPos %.17g\n", argv[1], n, cycles, sum);
  return 0;
}
