// The scope page (ncsdk_run --html) in a real browser, headless Chromium (SPEC H, issue 15 item
// 3): it renders the channels (pixels of each channel's colour read back from the canvas), a
// zoom by mouse drag sets the view, the cursor reads every channel at a time exactly as
// trace.csv has it, a channel switched off leaves the canvas, and a screenshot is taken into the
// test's output folder (scope.png). Without chromium the test exits 77 (CTest: skipped).
// Catch's implementation is linked in (tests/catch_runner.cpp); the main is this file's own.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "ncsdk_run/cli.hpp"
#include "scenario_files.hpp"

namespace ncsdk_test {
int run_catch(int argc, char* argv[]);  // tests/catch_runner.cpp
}

namespace fs = std::filesystem;
using scenario_test::contents;

namespace {

const fs::path kOut = NCSDK_TEST_OUT;

std::string browser() {
  for (const char* name : {"chromium", "chromium-browser"}) {
    if (std::system(("command -v " + std::string(name) + " > /dev/null 2>&1").c_str()) == 0) {
      return name;
    }
  }
  return {};
}

// Runs headless Chromium on the page with `hash`; `mode` is --dump-dom or --screenshot=…
int chromium(const std::string& mode, const std::string& hash, const fs::path& stdout_file) {
  const std::string command =
      "timeout 60 " + browser() +
      " --headless --no-sandbox --disable-gpu --hide-scrollbars --no-first-run"
      " --user-data-dir=" +
      (kOut / "profile").string() + " --window-size=1040,1000 " + mode + " 'file://" +
      (kOut / "run" / "scope.html").string() + "#" + hash + "' > " + stdout_file.string() + " 2> " +
      (kOut / "chromium.log").string();
  return std::system(command.c_str());
}

// The page's state (the JSON it writes into <pre id="state">) after the hash's actions.
nlohmann::json page_state(const std::string& hash) {
  const fs::path dom = kOut / "dom.html";
  REQUIRE(chromium("--dump-dom", hash, dom) == 0);
  const std::string text = contents(dom);
  const std::size_t tag = text.find("<pre id=\"state\"");
  REQUIRE(tag != std::string::npos);
  const std::size_t begin = text.find('>', tag) + 1;
  const std::size_t end = text.find("</pre>", begin);
  return nlohmann::json::parse(text.substr(begin, end - begin));
}

// trace.csv as columns by name (the unit bracket dropped).
std::map<std::string, std::vector<double>> read_csv(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::stringstream header(line);
  for (std::string cell; std::getline(header, cell, ',');)
    names.push_back(cell.substr(0, cell.find(" [")));
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::size_t k = 0;
    for (std::string cell; std::getline(row, cell, ','); ++k)
      columns[names.at(k)].push_back(std::strtod(cell.c_str(), nullptr));
  }
  return columns;
}

}  // namespace

TEST_CASE("the scope page renders, zooms, reads the cursor as trace.csv and hides channels") {
  fs::remove_all(kOut);
  const std::string timeline = std::string(NCSDK_SCENARIO_DIR) + "/override_100_75_100.json";
  std::ostringstream out, err;
  const std::vector<std::string> args = {timeline, "--out", (kOut / "run").string(), "--html"};
  REQUIRE(scenario::run_command(args, out, err) == 0);
  const auto csv = read_csv(kOut / "run" / "trace.csv");
  const std::vector<double>& time = csv.at("time");

  // Zoom by dragging from 0.5 s to 1.0 s, cursor at 0.75 s, actual position switched off.
  const nlohmann::json state = page_state("zoom=0.5,1.0&cursor=0.75&hide=Axis.ActPos");
  CHECK(state["samples"] == time.size());
  // The drag ends on whole pixels: 1 px is 0.5 s / 900 px here.
  const double pixel = 0.5 / 900.0;
  CHECK(std::fabs(state["view"][0].get<double>() - 0.5) < 2.0 * pixel);
  CHECK(std::fabs(state["view"][1].get<double>() - 1.0) < 2.0 * pixel);
  // Every channel that is on has pixels of its colour on the canvas; the hidden one has none.
  for (const char* name : {"Axis.SetPos", "Axis.SetVelo", "Axis.ActVelo", "Axis.SetAcc",
                           "Axis.ActAcc", "Axis.PosDiff"}) {
    INFO(name);
    CHECK(state["pixels"][name].get<int>() > 100);
  }
  CHECK(state["pixels"]["Axis.ActPos"] == 0);
  // The cursor sits on the sample nearest to 0.75 s and reads every channel as trace.csv has it.
  const double t = state["cursor"]["t"].get<double>();
  CHECK(std::fabs(t - 0.75) < 2.0 * pixel);
  const auto index = state["cursor"]["index"].get<std::size_t>();
  REQUIRE(index < time.size());
  CHECK(time[index] == t);
  int compared = 0;
  for (const auto& [name, value] : state["cursor"]["values"].items()) {
    INFO(name);
    CHECK(csv.at(name).at(index) == value.get<double>());
    ++compared;
  }
  CHECK(compared == 7);
  // At 0.75 s the axis cruises at V = 2000 mm/s (override 100 % until 1.0 s, seed 000 §2.2).
  CHECK(state["cursor"]["values"]["Axis.SetVelo"] == 2000.0);
  CHECK(state["cursor"]["values"]["Axis.SetAcc"] == 0.0);

  // Pan by half the view (the Pan buttons move a quarter).
  const nlohmann::json panned = page_state("zoom=0.5,1.0&pan=0.5");
  CHECK(std::fabs(panned["view"][0].get<double>() - 0.75) < 3.0 * pixel);
  CHECK(std::fabs(panned["view"][1].get<double>() - 1.25) < 3.0 * pixel);

  // Reset view: without a hash the page shows the whole run and no cursor.
  const nlohmann::json initial = page_state("");
  CHECK(initial["view"][0] == time.front());
  CHECK(initial["view"][1] == time.back());
  CHECK(initial["pixels"]["Axis.ActPos"].get<int>() > 0);

  // The screenshot (the README's picture is one of these).
  const fs::path png = kOut / "scope.png";
  REQUIRE(chromium("--screenshot=" + png.string(), "zoom=0.5,2.8&cursor=1.5", kOut / "shot.log") ==
          0);
  const std::string image = contents(png);
  CHECK(image.size() > 20'000);
  CHECK(image.substr(1, 3) == "PNG");
}

int main(int argc, char** argv) {
  if (browser().empty()) {
    std::printf("SKIP: chromium is not installed (tools/setup.sh installs it)\n");
    return 77;
  }
  return ncsdk_test::run_catch(argc, argv);
}
