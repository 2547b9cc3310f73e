// Two-bar linkage sample (seed 000 §2.6, coordinate transformation): a PLC program plans a
// straight line of the tool point, transforms it into joint setpoints with the inverse
// kinematics (Eigen) and feeds both joint axes through external setpoint generation. Writes the
// scope trace (CSV), the tool path (x–y SVG) and the joint motion (SVG).
//
// Usage: two_bar_linkage [output folder, default out/]
// Exit code 0 when the tool stayed on the line (set 1e-6 mm, actual 0.05 mm) and ended at the
// goal with both joints in their target windows, 1 otherwise, 2 on a set-up or file error.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "two_bar_linkage_program.hpp"

int main(int argc, char** argv) {
  try {
    const std::filesystem::path out = argc > 1 ? argv[1] : "out";
    two_bar_linkage::TwoBarLinkageSample sample;
    const two_bar_linkage::Report& report = sample.run();
    const auto files = sample.write(out);
    std::fputs(sample.summary().c_str(), stdout);
    std::printf("  trace: %s\n  plots: %s\n         %s\n", files[0].string().c_str(),
                files[1].string().c_str(), files[2].string().c_str());
    return report.ok() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "two_bar_linkage: %s\n", e.what());
    return 2;
  }
}
