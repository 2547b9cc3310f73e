// External setpoint generator sample (seed 000 §4.1): a PLC-side 3-phase generator with a
// rectangular acceleration profile moves an axis through MC_ExtSetPointGenEnable /
// MC_ExtSetPointGenFeed / MC_ExtSetPointGenDisable; the scope trace (CSV) and plot (SVG) are
// written.
//
// Usage: ext_setpoint_generator [output folder, default out/]
// Exit code 0 when the axis followed every taken packet exactly and ended in the target window
// of the last leg with external generation disabled, 1 otherwise, 2 on a set-up or file error.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "ext_setpoint_generator_program.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "out";
    ext_setpoint_generator::ExtSetpointGeneratorSample sample;
    const ext_setpoint_generator::Report& report = sample.run();
    const auto [csv, svg] = sample.write(out);
    std::fputs(sample.summary().c_str(), stdout);
    std::printf("  trace: %s\n  plot:  %s\n", csv.string().c_str(), svg.string().c_str());
    return report.ok() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ext_setpoint_generator: %s\n", e.what());
    return 2;
  }
}
