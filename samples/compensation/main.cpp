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
#include "sample_output.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "out";
    return sample_common::run_each<compensation::CompensationSample>(compensation::kFigures, out)
               ? 0
               : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "compensation: %s\n", e.what());
    return 2;
  }
}
