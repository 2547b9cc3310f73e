// Gear coupling sample (seed 000 §3.2): a master and two slaves, first as a star (gear in at
// rest, master start at override 30 % then 100 %), then re-coupled at rest as a cascade (factor
// change, online decoupling, slave stop, master stop); recorded with the scope and written as
// CSV + one SVG with all axes.
//
// Usage: gear_coupling [output folder, default out/]
// Exit code 0 when the run showed what the seed describes (GearCouplingSample::ok()), 1
// otherwise, 2 on a set-up or file error.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "gear_coupling_program.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "out";
    gear_coupling::GearCouplingSample sample;
    sample.run();
    const auto [csv, svg] = sample.write(out);
    std::fputs(sample.summary().c_str(), stdout);
    std::printf("  trace: %s\n  plot:  %s\n", csv.string().c_str(), svg.string().c_str());
    return sample.ok() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gear_coupling: %s\n", e.what());
    return 2;
  }
}
