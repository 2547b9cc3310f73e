// ncsdk_gallery: the plots of docs/blocks.md, made by the SDK from the scenario files — a thin loop
// over docs/scenarios/*.json (seed 000 §2.1–§2.4 and issue 4's figures, each with the seed's
// numbers as checks). Each scenario runs against the axes file its "axes" key names, and its
// figure (the timeline's "figure": its one axis or a plot) is written as <out>/<stem>.svg.
//
// Usage: ncsdk_gallery [output folder, default docs/gallery] [scenario folder, default
// docs/scenarios]. Prints one line per figure and every failed check. Exit status 0 when every
// scenario passed its checks, 1 when a check failed, 2 on a bad scenario file or a write error.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "nc_core/svg_plot.hpp"
#include "ncsdk_run/scenario.hpp"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  const fs::path out = argc > 1 ? argv[1] : "docs/gallery";
  const fs::path in = argc > 2 ? argv[2] : "docs/scenarios";
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(in)) {
    if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  int failed = 0;
  try {
    for (const fs::path& file : files) {
      const nlohmann::json timeline = scenario::read_json_file(file);
      if (!timeline.is_object() || !timeline.contains("axes") || !timeline["axes"].is_string()) {
        throw scenario::InputError(file.string(), "/axes",
                                   "a gallery scenario names its axes file");
      }
      const fs::path axes_file = file.parent_path() / timeline["axes"].get<std::string>();
      scenario::Scenario s(scenario::read_json_file(axes_file), timeline, axes_file.string(),
                           file.string());
      s.play();
      const fs::path svg = out / (file.stem().string() + ".svg");
      nc::write_svg(svg, s.svg(s.figure()));
      std::printf("%-4s %s  %s\n", s.passed() ? "ok" : "FAIL", svg.string().c_str(),
                  s.title().c_str());
      for (const scenario::CheckResult& c : s.checks()) {
        if (!c.passed) {
          std::printf("       %s %s (%s)\n", c.pointer.c_str(), c.description.c_str(),
                      c.detail.c_str());
        }
      }
      failed += s.passed() ? 0 : 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ncsdk_gallery: %s\n", e.what());
    return 2;
  }
  std::printf("%zu figures, %d with failed checks\n", files.size(), failed);
  return files.empty() ? 2 : (failed == 0 ? 0 : 1);
}
