// Position compensation sample (seed 000 §2.5): the seed's three figures — full, partial (the
// largest feasible D) and negative compensation on a 0 → 10000 mm positioning — each run with
// MC_MoveAbsolute + MC_MoveSuperImposed, recorded with the scope and written as CSV + SVG.
//
// Usage: compensation [output folder, default out/]
// Exit code 0 when every figure ends at the seed's end position (with the warning exactly where
// D was not feasible), 1 otherwise, 2 on a set-up or file error.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "compensation_program.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "out";
    bool all_ok = true;
    for (const compensation::Figure& figure : compensation::kFigures) {
      compensation::CompensationSample sample(figure);
      sample.run();
      const auto [csv, svg] = sample.write(out);
      std::fputs(sample.summary().c_str(), stdout);
      std::printf("  trace: %s\n  plot:  %s\n", csv.string().c_str(), svg.string().c_str());
      all_ok = all_ok && sample.ok();
    }
    return all_ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compensation: %s\n", e.what());
    return 2;
  }
}
