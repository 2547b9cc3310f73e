// MoveAxis sample (seed 000 §4.3): enable an axis, move it to 2000 mm and back to 0 mm, record
// it with the scope and write the trace (CSV) and the plot (SVG).
//
// Usage: move_axis [output folder, default out/]
// Exit code 0 when the axis reached 2000 mm and returned to 0 mm, 1 otherwise, 2 on a set-up or
// file error.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "move_axis_program.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "out";
    move_axis::MoveAxisSample sample;
    const move_axis::Report& report = sample.run();
    const auto [csv, svg] = sample.write(out);
    std::fputs(sample.summary().c_str(), stdout);
    std::printf("  trace: %s\n  plot:  %s\n", csv.string().c_str(), svg.string().c_str());
    return report.ok() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "move_axis: %s\n", e.what());
    return 2;
  }
}
