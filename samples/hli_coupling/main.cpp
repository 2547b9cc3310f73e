// HLI axis coupling sample (seed 002): the seed's examples 1–3 (Y2 = logical axis 8 coupled to
// axis 1: DIRECT; DIRECT + self; self + FRACT −5/9) and the forward-mapping example of
// P-AXIS-00460, each written by a PLC program into the mirrored control unit gpAx[…], recorded
// with the scope and written as CSV + SVG.
//
// Usage: hli_coupling [output folder, default out/]
// Exit code 0 when every example ends at the seed's numbers, 1 otherwise, 2 on a set-up or file
// error.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "hli_coupling_program.hpp"
#include "sample_output.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "out";
    bool all_ok =
        sample_common::run_each<hli_coupling::ExampleSample>(hli_coupling::kExamples, out);
    hli_coupling::MappingSample mapping;
    all_ok = sample_common::run_and_show(mapping, out) && all_ok;
    return all_ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hli_coupling: %s\n", e.what());
    return 2;
  }
}
