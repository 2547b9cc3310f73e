// Drive-controlled homing sample (seed 000 §4.2): Axis1 homes through its simulated SERCOS drive,
// Axis2 with the NC's sequence on a reference cam.
//
// Usage: drive_homing [fault], fault one of none (default), scaling, aborted, no_reference.
// Exit code 0 when both axes are homed, 1 otherwise (the summary names DriveHoming.nErrorCode),
// 2 on a bad argument or a set-up error.
#include <cstdio>
#include <cstring>
#include <exception>

#include "drive_homing_program.hpp"

int main(int argc, char** argv) {
  using Fault = drive_homing::SercosDrive::Fault;
  try {
    Fault fault = Fault::kNone;
    if (argc > 1) {
      const char* arg = argv[1];
      if (std::strcmp(arg, "scaling") == 0) {
        fault = Fault::kParameterScaling;
      } else if (std::strcmp(arg, "aborted") == 0) {
        fault = Fault::kHomingAborted;
      } else if (std::strcmp(arg, "no_reference") == 0) {
        fault = Fault::kNoReferenceFlag;
      } else if (std::strcmp(arg, "none") != 0) {
        std::fprintf(stderr, "drive_homing: unknown fault '%s'\n", arg);
        return 2;
      }
    }
    drive_homing::DriveHomingSample sample(fault);
    const drive_homing::Report& report = sample.run();
    std::fputs(sample.summary().c_str(), stdout);
    return report.ok() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "drive_homing: %s\n", e.what());
    return 2;
  }
}
