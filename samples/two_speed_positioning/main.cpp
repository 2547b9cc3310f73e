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

#include "two_speed_positioning_program.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "out";
    bool all_ok = true;
    for (const two_speed_positioning::Example& example : two_speed_positioning::kExamples) {
      two_speed_positioning::TwoSpeedSample sample(example);
      sample.run();
      const auto [csv, svg] = sample.write(out);
      std::fputs(sample.summary().c_str(), stdout);
      std::printf("  trace: %s\n  plot:  %s\n", csv.string().c_str(), svg.string().c_str());
      all_ok = all_ok && sample.ok();
    }
    return all_ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "two_speed_positioning: %s\n", e.what());
    return 2;
  }
}
