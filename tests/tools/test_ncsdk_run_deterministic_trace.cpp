// The same files give a byte-identical trace.csv (and trace.json): the run is deterministic.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include "scenario_files.hpp"

using scenario_test::contents;

TEST_CASE("two runs of a shipped scenario write byte-identical traces") {
  const std::filesystem::path dir = NCSDK_SCENARIO_DIR;
  for (const char* name : {"override_100_75_100", "npv_case5", "override_types"}) {
    const std::string timeline = (dir / (std::string(name) + ".json")).string();
    const auto first = scenario_test::out_dir(std::string(name) + "_1");
    const auto second = scenario_test::out_dir(std::string(name) + "_2");
    REQUIRE(scenario_test::run({timeline, "--out", first.string()}).status == 0);
    REQUIRE(scenario_test::run({timeline, "--out", second.string()}).status == 0);
    const std::string a = contents(first / "trace.csv");
    INFO(name);
    CHECK(a.size() > 100'000);
    CHECK(a == contents(second / "trace.csv"));
    CHECK(contents(first / "trace.json") == contents(second / "trace.json"));
  }
}
