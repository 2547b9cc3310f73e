// Cyclic slave sample (seed 000 §3.3): a master at 1000 mm/s and a slave whose factor follows a
// PLC signal through MC_GearInDyn (a step, then a sine), smoothed by AccBound; then the slave is
// decoupled in motion and both are stopped. Recorded with the scope, written as CSV + SVG.
//
// Usage: cyclic_gear [output folder, default out/]
// Exit code 0 when the run showed what the seed describes (CyclicGearSample::ok()), 1 otherwise,
// 2 on a set-up or file error.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "cyclic_gear_program.hpp"
#include "sample_output.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "out";
    cyclic_gear::CyclicGearSample sample;
    return sample_common::run_and_show(sample, out) ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclic_gear: %s\n", e.what());
    return 2;
  }
}
