// A scenario whose expectation is wrong exits 1 and names the failed check by its JSON pointer; a
// right one exits 0. Both runs write their results (the trace is a result either way).
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "scenario_files.hpp"

using scenario_test::kAxes;
using scenario_test::move_timeline;
using scenario_test::out_dir;
using scenario_test::run;
using scenario_test::write_file;

namespace {

scenario_test::Outcome run_checks(const std::string& name, const std::string& expect) {
  const auto dir = out_dir(name);
  std::filesystem::remove_all(dir);
  const auto a = write_file(dir.string() + "_in/axes.json", kAxes);
  const auto t = write_file(dir.string() + "_in/timeline.json", move_timeline(expect));
  return run({a.string(), t.string(), "--out", dir.string()});
}

}  // namespace

TEST_CASE("right expectations exit 0") {
  const auto o = run_checks("right", R"([
      {"no_errors": true},
      {"t": "end", "axis": "X", "field": "SetPos", "value": 1000},
      {"t": "end", "block": "mv", "output": "Done", "value": true},
      {"axis": "X", "field": "SetVelo", "abs": true, "max": 2000, "tol": 1e-9}])");
  INFO(o.out << o.err);
  CHECK(o.status == 0);
  CHECK(o.out.find("checks: 5 passed, 0 failed") != std::string::npos);  // + stop_when
}

TEST_CASE("a wrong expectation exits 1 naming the check") {
  const auto o = run_checks("wrong", R"([
      {"no_errors": true},
      {"t": "end", "axis": "X", "field": "SetPos", "value": 999, "tol": 0.5},
      {"t": "end", "block": "mv", "output": "Done", "value": true}])");
  INFO(o.out << o.err);
  CHECK(o.status == 1);
  CHECK(o.err.find("check /expect/1 failed: X.SetPos at the end = 999") != std::string::npos);
  CHECK(o.err.find("was 1000") != std::string::npos);
  CHECK(o.err.find("/expect/2") == std::string::npos);
  CHECK(o.out.find("FAIL /expect/1") != std::string::npos);
  const auto dir = out_dir("wrong");
  CHECK(std::filesystem::file_size(dir / "trace.csv") > 0);
  std::ifstream summary(dir / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(summary);
  CHECK(j["passed"] == false);
  CHECK(j["checks"][2]["pointer"] == "/expect/1");
  CHECK(j["checks"][2]["passed"] == false);
}

TEST_CASE("each kind of check fails when its expectation is wrong") {
  const std::string kinds[] = {
      R"({"no_errors": true, "from": 0}, {"t": 0.2, "block": "pw", "output": "Error", "value": true})",
      R"({"axis": "X", "field": "SetVelo", "max": 1999})",
      R"({"axis": "X", "field": "SetVelo", "ever": true, "min": 2001})",
      R"({"axis": "X", "field": "SetPos", "from": 0, "to": "end", "change": 900, "tol": 1})",
      R"({"t": 99, "axis": "X", "field": "SetPos", "value": 1000})",
  };
  for (const std::string& k : kinds) {
    const auto o = run_checks("kind", "[" + k + "]");
    INFO(k << "\n" << o.out);
    CHECK(o.status == 1);
  }
}

TEST_CASE("a stop condition never reached fails the run") {
  const auto dir = out_dir("never_stops");
  const auto a = write_file(dir.string() + "_in/axes.json", kAxes);
  const auto t = write_file(dir.string() + "_in/timeline.json", R"({"duration": 0.2,
      "stop_when": {"block": "pw", "output": "Status"},
      "timeline": [{"t": 0, "block": "pw", "type": "MC_Power", "axis": "X"}]})");
  const auto o = run({a.string(), t.string(), "--out", dir.string()});
  CHECK(o.status == 1);
  CHECK(o.err.find("check /stop_when failed") != std::string::npos);
}
