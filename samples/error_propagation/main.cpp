// Error propagation sample (seed 000 §3.1, SPEC C7): a master with two slaves; the faulty slave's
// drive cannot follow, its following error (DELAYED, 0.5 s) stops only itself, and the PLC
// decouples the healthy slave before the delay runs out so that it keeps running when the group
// reaction stops the master; recorded with the scope and written as CSV + one SVG.
//
// Usage: error_propagation [output folder, default out/]
// Exit code 0 when the run showed what the seed describes (ErrorPropagationSample::ok()), 1
// otherwise, 2 on a set-up or file error.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "error_propagation_program.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "out";
    error_propagation::ErrorPropagationSample sample;
    return sample_common::run_and_show(sample, out) ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error_propagation: %s\n", e.what());
    return 2;
  }
}
