#include "ncsdk_run/cli.hpp"

#include <filesystem>
#include <ostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "ncsdk_run/scenario.hpp"

namespace scenario {
namespace {

constexpr const char* kUsage =
    "usage: ncsdk_run [AXES.json] TIMELINE.json --out DIR [--html]\n"
    "  plays TIMELINE.json against the kernel of AXES.json (or of the timeline's \"axes\" file)\n"
    "  exit status: 0 all checks pass, 1 a check failed, 2 bad input\n";

}  // namespace

int run_command(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
  std::vector<std::string> files;
  std::filesystem::path dir;
  bool html = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--out" && i + 1 < args.size()) {
      dir = args[++i];
    } else if (args[i] == "--html") {
      html = true;
    } else if (args[i] == "--help" || args[i] == "-h") {
      out << kUsage;
      return 0;
    } else if (!args[i].empty() && args[i][0] == '-') {
      err << "ncsdk_run: unknown option " << args[i] << "\n" << kUsage;
      return 2;
    } else {
      files.push_back(args[i]);
    }
  }
  if (files.empty() || files.size() > 2 || dir.empty()) {
    err << kUsage;
    return 2;
  }
  try {
    const std::filesystem::path timeline_path = files.back();
    const nlohmann::json timeline = read_json_file(timeline_path);
    std::filesystem::path axes_path;
    if (files.size() == 2) {
      axes_path = files.front();
    } else {
      if (!timeline.is_object() || !timeline.contains("axes") || !timeline["axes"].is_string()) {
        throw InputError(timeline_path.string(), "/axes",
                         "required when no AXES.json is given: the axes file, relative to the "
                         "timeline");
      }
      axes_path = timeline_path.parent_path() / timeline["axes"].get<std::string>();
    }
    const nlohmann::json axes = read_json_file(axes_path);
    Scenario scenario(axes, timeline, axes_path.string(), timeline_path.string());
    scenario.play();
    scenario.write(dir, html);
    out << scenario.summary_text();
    if (scenario.passed()) return 0;
    for (const CheckResult& c : scenario.checks()) {
      if (!c.passed) {
        err << "ncsdk_run: check " << c.pointer << " failed: " << c.description << " (" << c.detail
            << ")\n";
      }
    }
    return 1;
  } catch (const InputError& e) {
    err << "ncsdk_run: bad input: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "ncsdk_run: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace scenario
