// What a timeline means (docs/scenarios/README.md): actions fire in order, each at its first PLC
// cycle at or after its "t", "after" seconds after the previous one and once its "when" holds
// (outputs of the previous PLC call); blocks are called every PLC cycle from their declaration,
// in declaration order; PlcToNc writes stay; the trace holds every axis's NcToPlc and every
// block's outputs each NC cycle. Every fb block is available by its type name.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "ncsdk_run/block_registry.hpp"
#include "ncsdk_run/scenario.hpp"

namespace {

using nlohmann::json;

// "b<k>" (built in two steps: GCC 12 warns falsely about "b" + std::to_string(k)).
std::string block_name(int k) {
  std::string name = std::to_string(k);
  name.insert(name.begin(), 'b');
  return name;
}

double value_at(const nc::Scope& trace, const std::string& column, double t) {
  const std::size_t c = trace.find(column);
  REQUIRE(c < trace.channel_count());
  const auto time = trace.time();
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (std::fabs(time[i] - t) < 1e-9) return trace.values(c)[i];
  }
  FAIL("no sample at " << t);
  return 0.0;
}

// The first time the column is `value`, or -1.
double first_time(const nc::Scope& trace, const std::string& column, double value) {
  const std::size_t c = trace.find(column);
  REQUIRE(c < trace.channel_count());
  const auto time = trace.time();
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (trace.values(c)[i] == value) return time[i];
  }
  return -1.0;
}

const json kAxes = json::parse(R"({"kernel": {"cycle_time": 0.001}, "axes": [{"name": "X"}]})");

}  // namespace

TEST_CASE("a PlcToNc write takes effect at its time and stays") {
  scenario::Scenario s(kAxes, json::parse(R"({"duration": 1.0, "timeline": [
      {"t": 0.5, "axis": "X", "write": {"Override": 300000, "Enable": true, "GearRatio1": 0.5}}]})"));
  s.play();
  CHECK(value_at(s.trace(), "X.Override", 0.499) == 1'000'000.0);
  CHECK(value_at(s.trace(), "X.Override", 0.5) == 300'000.0);
  CHECK(value_at(s.trace(), "X.Override", 1.0) == 300'000.0);
  CHECK(value_at(s.trace(), "X.ControlDWord", 0.5) == 1.0);
  CHECK(value_at(s.trace(), "X.GearRatio1", 0.5) == 0.5);
  CHECK(s.trace().time().back() == Approx(1.0).margin(1e-12));  // t = 0 … duration
}

TEST_CASE("when fires on the PLC cycle after the output shows, after waits from the previous") {
  scenario::Scenario s(kAxes, json::parse(R"({"duration": 2.0, "timeline": [
      {"t": 0, "block": "pw", "type": "MC_Power", "axis": "X",
       "set": {"Enable": true, "Enable_Positive": true, "Enable_Negative": true}},
      {"t": 0, "block": "mv", "type": "MC_MoveRelative", "axis": "X",
       "set": {"Distance": 100, "Velocity": 1000}},
      {"when": {"block": "pw", "output": "Status"}, "block": "mv", "set": {"Execute": true}},
      {"when": {"block": "mv", "output": "Done"}, "block": "mv", "set": {"Execute": false}},
      {"after": 0.25, "block": "mv", "set": {"Execute": true}}]})"));
  s.play();
  const double status = first_time(s.trace(), "pw.Status", 1.0);
  REQUIRE(status >= 0.0);
  CHECK(first_time(s.trace(), "mv.Busy", 1.0) == Approx(status + 0.001).margin(1e-12));
  // The second move starts 0.25 s after the first one's Done was taken (Execute fell).
  const double done = first_time(s.trace(), "mv.Done", 1.0);
  REQUIRE(done > 0.0);
  CHECK(value_at(s.trace(), "X.SetPos", done + 0.25) == 100.0);
  CHECK(value_at(s.trace(), "X.SetPos", 2.0) == Approx(200.0).margin(1e-9));
}

TEST_CASE("a slower PLC task fires actions and calls blocks on its own cycles") {
  scenario::Scenario s(kAxes, json::parse(R"({"duration": 0.05, "plc_period": 0.004,
      "timeline": [{"t": 0.01, "axis": "X", "write": {"Override": 500000}}]})"));
  s.play();
  CHECK(value_at(s.trace(), "X.Override", 0.011) == 1'000'000.0);  // PLC cycles 0.008, 0.012
  CHECK(value_at(s.trace(), "X.Override", 0.012) == 500'000.0);
}

TEST_CASE("every registered block type can be declared, called and traced by its IEC names") {
  const char* const api_blocks[] = {"MC_Power",
                                    "MC_Reset",
                                    "MC_MoveAbsolute",
                                    "MC_MoveRelative",
                                    "MC_MoveModulo",
                                    "MC_MoveVelocity",
                                    "MC_Halt",
                                    "MC_Stop",
                                    "MC_SetOverride",
                                    "MC_NewPos",
                                    "MC_NewPosAndVelo",
                                    "MC_MoveSuperImposed",
                                    "MC_AbortSuperposition",
                                    "MC_ExtSetPointGenEnable",
                                    "MC_ExtSetPointGenDisable",
                                    "MC_ExtSetPointGenFeed",
                                    "MC_ReadStatus",
                                    "MC_ReadActualPosition",
                                    "MC_ReadAxisError"};
  for (const char* name : api_blocks) {
    INFO(name);
    CHECK(scenario::find_block_type(name) != nullptr);
  }
  json timeline = {{"duration", 0.02}, {"timeline", json::array()}};
  int k = 0;
  for (const scenario::BlockType& type : scenario::block_types()) {
    json action = {{"t", 0},
                   {"block", block_name(k++)},
                   {"type", std::string(type.name)},
                   {"set", json::object()}};
    for (const std::string_view axis : type.axes)
      action[std::string(axis)] = "X";
    for (const scenario::Port& port : type.ports) {
      // Each input set once through its setter and read back through its getter below.
      if (port.kind == scenario::PortKind::kInput && port.type == scenario::ValueType::kBool) {
        action["set"][std::string(port.name)] = true;
      }
    }
    timeline["timeline"].push_back(action);
  }
  scenario::Scenario s(kAxes, timeline);
  s.play();
  k = 0;
  for (const scenario::BlockType& type : scenario::block_types()) {
    const std::string block = block_name(k++);
    for (const scenario::Port& port : type.ports) {
      const bool traced =
          s.trace().find(block + "." + std::string(port.name)) < s.trace().channel_count();
      INFO(type.name << "." << port.name);
      CHECK(traced == (port.kind == scenario::PortKind::kOutput));
    }
  }
}

TEST_CASE("a port reads and writes the block's member") {
  const scenario::BlockType* type = scenario::find_block_type("MC_MoveModulo");
  REQUIRE(type != nullptr);
  auto block = type->make();
  const scenario::Port* direction = type->find("Direction");
  const scenario::Port* position = type->find("Position");
  REQUIRE(direction != nullptr);
  REQUIRE(position != nullptr);
  CHECK(direction->type == scenario::ValueType::kDirection);
  direction->set(block->data(), scenario::enum_value(direction->type, "MC_Negative_Direction"));
  position->set(block->data(), 270.0);
  CHECK(direction->get(block->data()) == 3.0);
  CHECK(position->get(block->data()) == 270.0);
  CHECK(type->find("Done")->kind == scenario::PortKind::kOutput);
  CHECK(type->find("Nonsense") == nullptr);
}
