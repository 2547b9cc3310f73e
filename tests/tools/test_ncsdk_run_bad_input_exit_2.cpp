// ncsdk_run exits 2 on every class of bad input, naming the file, the JSON pointer and the rule,
// and writes nothing (SPEC H: "no partial output claimed as a result").
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "scenario_files.hpp"

namespace {

using scenario_test::kAxes;
using scenario_test::move_timeline;
using scenario_test::out_dir;
using scenario_test::run;
using scenario_test::write_file;

// Runs `timeline` (and `axes`) and checks exit 2, the pointer and a word of the rule in stderr,
// and that the output folder was not made.
void expect_bad(const std::string& name, const std::string& timeline, const std::string& pointer,
                const std::string& rule, const std::string& axes = kAxes) {
  const auto dir = out_dir(name);
  std::filesystem::remove_all(dir);
  const auto a = write_file(dir.string() + "_in/axes.json", axes);
  const auto t = write_file(dir.string() + "_in/timeline.json", timeline);
  const auto o = run({a.string(), t.string(), "--out", dir.string()});
  INFO(o.err);
  CHECK(o.status == 2);
  CHECK(o.err.find(":" + pointer + ":") != std::string::npos);
  CHECK(o.err.find(rule) != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir));
}

const std::string kPower =
    R"({"t": 0, "block": "pw", "type": "MC_Power", "axis": "X", "set": {"Enable": true}})";

std::string with_actions(const std::string& actions) {
  return R"({"duration": 1.0, "timeline": [)" + kPower + "," + actions + "]}";
}

}  // namespace

TEST_CASE("an unknown block type is refused with its pointer") {
  expect_bad("unknown_type",
             with_actions(R"({"t": 0.1, "block": "mv", "type": "MC_MoveAbsolut", "axis": "X"})"),
             "/timeline/1/type", "unknown block type 'MC_MoveAbsolut'");
}

TEST_CASE("an unknown input is refused with its pointer") {
  expect_bad("unknown_input",
             with_actions(R"({"t": 0.1, "block": "mv", "type": "MC_MoveAbsolute", "axis": "X",
                              "set": {"Positon": 5}})"),
             "/timeline/1/set/Positon", "unknown input 'Positon' of MC_MoveAbsolute");
  // An output is not an input.
  expect_bad("output_as_input",
             with_actions(R"({"t": 0.1, "block": "mv", "type": "MC_MoveAbsolute", "axis": "X",
                              "set": {"Done": true}})"),
             "/timeline/1/set/Done", "unknown input 'Done'");
}

TEST_CASE("a value of the wrong type is refused with its pointer") {
  expect_bad("bool_as_number",
             with_actions(R"({"t": 0.1, "block": "mv", "type": "MC_MoveAbsolute", "axis": "X",
                              "set": {"Execute": 1}})"),
             "/timeline/1/set/Execute", "Execute is a BOOL");
  expect_bad("real_as_string",
             with_actions(R"({"t": 0.1, "block": "mv", "type": "MC_MoveAbsolute", "axis": "X",
                              "set": {"Velocity": "fast"}})"),
             "/timeline/1/set/Velocity", "Velocity is a REAL");
  expect_bad("unknown_enum",
             with_actions(R"({"t": 0.1, "block": "mv", "type": "MC_MoveModulo", "axis": "X",
                              "set": {"Direction": "MC_Sideways"}})"),
             "/timeline/1/set/Direction", "MC_Shortest_Way");
  expect_bad("override_out_of_range",
             with_actions(R"({"t": 0.1, "axis": "X", "write": {"Override": 2000000}})"),
             "/timeline/1/write/Override", "0 … 1000000");
}

TEST_CASE("time going backwards is refused with its pointer") {
  expect_bad("time_backwards", with_actions(R"({"t": 0.5, "block": "pw", "set": {"Enable": false}},
                             {"t": 0.2, "block": "pw", "set": {"Enable": true}})"),
             "/timeline/2/t", "time going backwards");
}

TEST_CASE("a missing axis is refused with its pointer") {
  expect_bad("missing_axis",
             with_actions(R"({"t": 0.1, "block": "mv", "type": "MC_MoveAbsolute", "axis": "Y"})"),
             "/timeline/1/axis", "no axis 'Y'");
  expect_bad("no_axis_given",
             with_actions(R"({"t": 0.1, "block": "mv", "type": "MC_MoveAbsolute"})"),
             "/timeline/1/axis", "MC_MoveAbsolute needs \"axis\"");
  expect_bad("check_missing_axis", move_timeline(R"([{"t": 1, "axis": "Z", "field": "SetPos",
                                                      "value": 0}])"),
             "/expect/0/axis", "no axis 'Z'");
}

TEST_CASE("other bad inputs name their pointer too") {
  expect_bad("block_before_declaration",
             with_actions(R"({"t": 0.1, "block": "mv", "set": {"Execute": true}})"),
             "/timeline/1/block", "no block 'mv' declared before");
  expect_bad("unknown_output_in_when",
             with_actions(R"({"when": {"block": "pw", "output": "Done"}, "block": "pw",
                              "set": {"Enable": false}})"),
             "/timeline/1/when/output", "'Done' is not an output of MC_Power");
  expect_bad("unknown_field_in_check",
             move_timeline(R"([{"t": 1, "axis": "X", "field": "SetPosition", "value": 0}])"),
             "/expect/0/field", "unknown axis field 'SetPosition'");
  expect_bad("unknown_key", move_timeline(R"([{"t": 1, "axis": "X", "field": "SetPos",
                                               "value": 0, "tolerance": 1}])"),
             "/expect/0/tolerance", "unknown key");
  expect_bad("negative_time", with_actions(R"({"t": -1, "block": "pw", "set": {}})"),
             "/timeline/1/t", "a time must be >= 0 s");
  expect_bad("plc_period", R"({"duration": 1, "plc_period": 0.0015, "timeline": []})",
             "/plc_period", "whole multiple of the NC cycle");
  expect_bad("no_duration", R"({"timeline": []})", "/duration", "required");
  expect_bad("malformed_timeline", R"({"duration": 1, "timeline": [)", "(document)",
             "malformed JSON");
  expect_bad("bad_axes", move_timeline("[]"), "/axes/0/jerk", "",
             R"({"axes": [{"name": "X", "jerk": -5}]})");
  expect_bad("malformed_axes", move_timeline("[]"), "(document)", "malformed JSON", "{\"axes\": ");
}

TEST_CASE("a bad command line exits 2 with the usage") {
  const auto o = run({"only_one_file.json"});
  CHECK(o.status == 2);
  CHECK(o.err.find("usage: ncsdk_run") != std::string::npos);
  const auto missing = run({"/nonexistent/axes.json", "/nonexistent/t.json", "--out", "x"});
  CHECK(missing.status == 2);
  CHECK(missing.err.find("cannot be read") != std::string::npos);
}
