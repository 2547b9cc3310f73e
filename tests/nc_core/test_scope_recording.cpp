// The scope samples the chosen signals every call, into storage sized at set-up, and writes the
// recording as CSV and JSON.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "nc_core/scope.hpp"
#include "plc_interface/axis_ref.hpp"

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');)
    cells.push_back(cell);
  return cells;
}

}  // namespace

TEST_CASE("the scope records each channel's value at the time of each record call") {
  plc::AXIS_REF axis;
  nc::Scope scope(10);
  scope.add_motion_signals(axis, "Axis1");
  REQUIRE(scope.channel_count() == 7);

  for (int k = 0; k < 3; ++k) {
    axis.NcToPlc.SetPos = 100.0 * k;
    axis.NcToPlc.ActPos = 100.0 * k - 0.5;
    axis.NcToPlc.SetVelo = 2000.0;
    axis.NcToPlc.ActVelo = 1999.0;
    axis.NcToPlc.SetAcc = 5000.0;
    axis.NcToPlc.ActAcc = 4990.0;
    axis.NcToPlc.PosDiff = 0.5;
    REQUIRE(scope.record(0.001 * k));
  }
  REQUIRE(scope.size() == 3);
  const auto set_pos = scope.values(scope.find("Axis1", nc::Signal::kSetPos));
  const auto act_pos = scope.values(scope.find("Axis1.ActPos"));
  CHECK(set_pos[0] == 0.0);
  CHECK(set_pos[2] == 200.0);
  CHECK(act_pos[1] == 99.5);
  CHECK(scope.time()[2] == 0.002);
  CHECK(scope.values(scope.find("Axis1.PosDiff"))[1] == 0.5);
}

TEST_CASE("a full scope drops further samples and counts them") {
  plc::AXIS_REF axis;
  nc::Scope scope(2);
  scope.add_signal(axis, "X", nc::Signal::kSetPos);
  CHECK(scope.record(0.0));
  CHECK(scope.record(0.001));
  CHECK_FALSE(scope.record(0.002));
  CHECK_FALSE(scope.record(0.003));
  CHECK(scope.size() == 2);
  CHECK(scope.dropped() == 2);
  scope.clear();
  CHECK(scope.size() == 0);
  CHECK(scope.dropped() == 0);
  CHECK(scope.record(0.004));
}

TEST_CASE("scope channels over several axes and application variables stay apart") {
  plc::AXIS_REF x;
  plc::AXIS_REF y;
  double plant_force = 12.5;
  nc::Scope scope(4);
  scope.add_signal(x, "X", nc::Signal::kActVelo);
  scope.add_signal(y, "Y", nc::Signal::kActVelo);
  scope.add_signal(y, "Y", nc::Signal::kOverride);
  scope.add_variable(&plant_force, "Plant.Force", "N");
  x.NcToPlc.ActVelo = 10.0;
  y.NcToPlc.ActVelo = -20.0;
  y.PlcToNc.Override = 500'000;
  scope.record(0.0);
  CHECK(scope.values(scope.find("X.ActVelo"))[0] == 10.0);
  CHECK(scope.values(scope.find("Y.ActVelo"))[0] == -20.0);
  CHECK(scope.values(scope.find("Y.Override"))[0] == 500'000.0);
  CHECK(scope.values(scope.find("Plant.Force"))[0] == 12.5);
  CHECK(scope.channel(scope.find("Plant.Force")).unit == "N");
  CHECK(scope.find("Z.ActVelo") == scope.channel_count());
}

TEST_CASE("scope set-up refuses bad names, duplicates, capacity 0 and late channels") {
  plc::AXIS_REF axis;
  CHECK_THROWS_AS(nc::Scope(0), std::invalid_argument);
  nc::Scope scope(4);
  CHECK_THROWS_AS(scope.add_signal(axis, "", nc::Signal::kSetPos), std::invalid_argument);
  CHECK_THROWS_AS(scope.add_signal(axis, "A,B", nc::Signal::kSetPos), std::invalid_argument);
  CHECK_THROWS_AS(scope.add_variable(nullptr, "v", ""), std::invalid_argument);
  scope.add_signal(axis, "A", nc::Signal::kSetPos);
  CHECK_THROWS_AS(scope.add_signal(axis, "A", nc::Signal::kSetPos), std::invalid_argument);
  scope.record(0.0);
  CHECK_THROWS_AS(scope.add_signal(axis, "A", nc::Signal::kActPos), std::logic_error);
}

TEST_CASE("scope CSV has a time column, one column per channel with its unit, one row per sample") {
  plc::AXIS_REF axis;
  nc::Scope scope(8);
  scope.add_motion_signals(axis, "Axis1");
  scope.add_signal(axis, "Axis1", nc::Signal::kStateDWord);
  axis.NcToPlc.SetPos = 1234.5;
  axis.NcToPlc.StateDWord = 0x11;
  scope.record(0.0);
  axis.NcToPlc.SetPos = 0.1;  // needs the shortest round-trip form, not 6 digits
  scope.record(0.001);

  std::ostringstream out;
  scope.write_csv(out);
  const auto lines = lines_of(out.str());
  REQUIRE(lines.size() == 3);
  const std::vector<std::string> header = cells_of(lines[0]);
  const std::vector<std::string> expected = {"time [s]",
                                             "Axis1.SetPos [mm]",
                                             "Axis1.ActPos [mm]",
                                             "Axis1.SetVelo [mm/s]",
                                             "Axis1.ActVelo [mm/s]",
                                             "Axis1.SetAcc [mm/s^2]",
                                             "Axis1.ActAcc [mm/s^2]",
                                             "Axis1.PosDiff [mm]",
                                             "Axis1.StateDWord"};
  CHECK(header == expected);
  const auto first = cells_of(lines[1]);
  const auto second = cells_of(lines[2]);
  REQUIRE(first.size() == expected.size());
  REQUIRE(second.size() == expected.size());
  CHECK(first[0] == "0");
  CHECK(first[1] == "1234.5");
  CHECK(first[8] == "17");
  CHECK(second[0] == "0.001");
  CHECK(std::stod(second[1]) == 0.1);
}

TEST_CASE("scope JSON carries time, channel names, axes, signals, units and values") {
  plc::AXIS_REF axis;
  nc::Scope scope(8);
  scope.add_signal(axis, "Axis1", nc::Signal::kPosDiff);
  axis.NcToPlc.PosDiff = 0.25;
  scope.record(0.0);
  scope.record(0.001);
  const nlohmann::json doc = scope.to_json();
  CHECK(doc.at("sample_count") == 2);
  CHECK(doc.at("dropped") == 0);
  CHECK(doc.at("time").size() == 2);
  const auto& channel = doc.at("channels").at(0);
  CHECK(channel.at("name") == "Axis1.PosDiff");
  CHECK(channel.at("axis") == "Axis1");
  CHECK(channel.at("signal") == "PosDiff");
  CHECK(channel.at("unit") == "mm");
  CHECK(channel.at("values") == nlohmann::json::array({0.25, 0.25}));
  // The text written to a file parses back to the same document.
  CHECK(nlohmann::json::parse(doc.dump(1)) == doc);
}

TEST_CASE("scope files are written into a new folder, read back, and a bad path is reported") {
  plc::AXIS_REF axis;
  nc::Scope scope(4);
  scope.add_signal(axis, "Axis1", nc::Signal::kActPos);
  axis.NcToPlc.ActPos = 2000.0;
  scope.record(0.5);
  const auto dir = std::filesystem::temp_directory_path() / "ncsdk_test_scope_files";
  std::filesystem::remove_all(dir);
  scope.write_csv(dir / "a" / "trace.csv");
  scope.write_json(dir / "b" / "trace.json");

  std::ifstream csv(dir / "a" / "trace.csv");
  std::stringstream csv_text;
  csv_text << csv.rdbuf();
  CHECK(csv_text.str() == "time [s],Axis1.ActPos [mm]\n0.5,2000\n");
  std::ifstream json(dir / "b" / "trace.json");
  CHECK(nlohmann::json::parse(json) == scope.to_json());

  // A folder cannot be made below a regular file: the error names the path.
  const auto blocked = dir / "a" / "trace.csv" / "inner.csv";
  try {
    scope.write_csv(blocked);
    FAIL("no error for " << blocked);
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("trace.csv") != std::string::npos);
  }
  std::filesystem::remove_all(dir);
}
