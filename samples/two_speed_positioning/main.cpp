// Two-speed positioning sample (seed 004 "Positioning examples"): the three examples — A → B
// without loop, A → B with loop movement > 0, stop during an active positioning — each run with
// MC_Power, MC_MoveAbsolute (and MC_Stop) on a two-speed axis and written as CSV + a timing
// diagram SVG.
//
// Usage: two_speed_positioning [output folder, default out/]
// Exit code 0 when every example passes its check (two_speed_positioning_program.hpp), 1
// otherwise, 2 on a set-up or file error.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "sample_output.hpp"
#include "two_speed_positioning_program.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "out";
    return sample_common::run_each<two_speed_positioning::TwoSpeedSample>(
               two_speed_positioning::kExamples, out)
               ? 0
               : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "two_speed_positioning: %s\n", e.what());
    return 2;
  }
}
