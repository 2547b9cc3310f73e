// Helpers of the ncsdk_run tests: write a scenario's two files and run the command in-process.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ncsdk_run/cli.hpp"

namespace scenario_test {

struct Outcome {
  int status = -1;
  std::string out;
  std::string err;
};

inline std::filesystem::path out_dir(const std::string& name) {
  return std::filesystem::path(NCSDK_TEST_OUT) / name;
}

inline std::filesystem::path write_file(const std::filesystem::path& path,
                                        const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

inline std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

inline Outcome run(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  Outcome o;
  o.status = scenario::run_command(args, out, err);
  o.out = out.str();
  o.err = err.str();
  return o;
}

// One axis "X" on a 1 ms NC cycle.
inline const char* const kAxes = R"({"kernel": {"cycle_time": 0.001}, "axes": [{"name": "X"}]})";

// MC_Power enables X; mv moves it to 1000 mm once the power is on; the run ends 0.1 s after Done.
// `expect` is the checks array's text.
inline std::string move_timeline(const std::string& expect) {
  return R"({"duration": 3.0,
  "stop_when": {"block": "mv", "output": "Done", "after": 0.1},
  "timeline": [
    {"t": 0, "block": "pw", "type": "MC_Power", "axis": "X",
     "set": {"Enable": true, "Enable_Positive": true, "Enable_Negative": true}},
    {"t": 0, "block": "mv", "type": "MC_MoveAbsolute", "axis": "X",
     "set": {"Position": 1000, "Velocity": 2000}},
    {"when": {"block": "pw", "output": "Status"}, "block": "mv", "set": {"Execute": true}}
  ],
  "expect": )" +
         expect + "}";
}

}  // namespace scenario_test
