// Malformed JSON configurations: each gives a ConfigError whose pointer is the offending place in
// the document and whose rule says what was expected (SPEC A5, issue 2).
#include <catch2/catch.hpp>

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "config_error_of.hpp"
#include "nc_core/config.hpp"

using cfgtest::error_of;
using nlohmann::json;

namespace {

// Two valid axes; tests break one thing in them.
json two_axes() {
  return json::parse(R"({
    "kernel": {"cycle_time": 0.002},
    "axes": [
      {"name": "X", "max_velocity": 1000.0},
      {"name": "Y", "acceleration": 2000.0}
    ]
  })");
}

}  // namespace

TEST_CASE("the two-axis base document is valid", "[config]") {
  const nc::KernelSetup setup = nc::parse_kernel_setup(two_axes());
  CHECK(setup.kernel.cycle_time == 0.002);
  REQUIRE(setup.axes.size() == 2);
  CHECK(setup.axes[1].acceleration == 2000.0);
}

TEST_CASE("a wrong JSON type names the field and the expected type", "[config]") {
  json d = two_axes();
  d["axes"][0]["max_velocity"] = "fast";
  auto e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/max_velocity");
  CHECK(e->rule() == "must be a number");
  CHECK(std::string(e->what()) == R"(/axes/0/max_velocity: must be a number (got "fast"))");

  d = two_axes();
  d["axes"][1]["sw_limit_min_enabled"] = 1;  // booleans are strict: 1 is not true
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/1/sw_limit_min_enabled");
  CHECK(e->rule() == "must be true or false");

  d = two_axes();
  d["axes"][1]["name"] = 5;
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/1/name");
  CHECK(e->rule() == "must be a string");

  d = two_axes();
  d["kernel"]["cycle_time"] = json::array({0.001});
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/kernel/cycle_time");
  CHECK(e->rule() == "must be a number");

  d = two_axes();
  d["axes"][0]["jerk"] = true;
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/jerk");
  CHECK(e->rule() == "must be a number");
}

TEST_CASE("integer fields refuse fractions and numbers beyond int", "[config]") {
  json d = two_axes();
  d["axes"][0]["override_type"] = 3.5;
  auto e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/override_type");
  CHECK(e->rule() == "must be an integer");

  d = two_axes();
  d["axes"][1]["id"] = 4294967296LL;
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/1/id");
  CHECK(e->rule() == "must be in [0, 2147483647]");

  d = two_axes();
  d["axes"][1]["id"] = "2";
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/1/id");
  CHECK(e->rule() == "must be an integer");
}

TEST_CASE("negative limits in a file name the axis and the field", "[config]") {
  for (const char* key : {"max_velocity", "ref_velocity", "acceleration", "deceleration", "jerk",
                          "emergency_deceleration", "emergency_jerk", "following_error_limit",
                          "target_window", "position_range_window", "modulo_factor"}) {
    INFO(key);
    json d = two_axes();
    d["axes"][1][key] = -10;
    const auto e = error_of(d);
    REQUIRE(e);
    CHECK(e->pointer() == std::string("/axes/1/") + key);
    CHECK(e->rule() == "must be > 0");
    CHECK(std::string(e->what()) == std::string("/axes/1/") + key + ": must be > 0 (got -10)");
  }
}

TEST_CASE("a number too large for a double is refused as not finite", "[config]") {
  const auto e = [] {
    try {
      (void)nc::parse_kernel_setup_text(R"({"axes": [{"name": "X", "jerk": 1e999}]})");
    } catch (const nc::ConfigError& err) {
      return std::optional<nc::ConfigError>(err);
    }
    return std::optional<nc::ConfigError>();
  }();
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/jerk");
  CHECK(e->rule() == "must be finite");
}

TEST_CASE("out-of-range values in a file: override_type, cycle_time, software limits", "[config]") {
  for (const int bad : {0, 5}) {
    json d = two_axes();
    d["axes"][0]["override_type"] = bad;
    const auto e = error_of(d);
    REQUIRE(e);
    CHECK(e->pointer() == "/axes/0/override_type");
    CHECK(e->rule() == "must be in [1, 4]");
  }

  json d = two_axes();
  d["kernel"]["cycle_time"] = 0.02;
  auto e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/kernel/cycle_time");
  CHECK(std::string(e->what()) == "/kernel/cycle_time: must be in [5e-05, 0.01] (got 0.02)");

  d = two_axes();
  d["axes"][1].update(json{{"sw_limit_min_enabled", true},
                           {"sw_limit_max_enabled", true},
                           {"sw_limit_min", 500.0},
                           {"sw_limit_max", -500.0}});
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/1/sw_limit_min");
  CHECK(e->rule() == "must be < sw_limit_max (-500) when both software limits are enabled");
}

TEST_CASE("an unknown key is named at the top level, in kernel and in an axis", "[config]") {
  json d = two_axes();
  d["axis"] = json::array();
  auto e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axis");
  CHECK(e->rule() == R"(unknown key (did you mean "axes"?))");

  d = two_axes();
  d["kernel"]["cycle"] = 0.001;
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/kernel/cycle");
  CHECK(e->rule() == "unknown key");

  d = two_axes();
  d["axes"][1]["max_velocty"] = 100.0;
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/1/max_velocty");
  CHECK(e->rule() == R"(unknown key (did you mean "max_velocity"?))");

  d = two_axes();
  d["axes"][0]["a/b~c"] = 1;  // RFC 6901 escapes in the pointer
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/a~1b~0c");
}

TEST_CASE("an axis without a name is refused at its name", "[config]") {
  json d = two_axes();
  d["axes"].push_back(json{{"name", "Z"}});
  d["axes"][2].erase("name");
  d["axes"][2]["jerk"] = 1000.0;
  auto e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/2/name");
  CHECK(e->rule() == "required");
  CHECK(std::string(e->what()) == "/axes/2/name: required");

  d = two_axes();
  d["axes"][0]["name"] = "";
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/name");
  CHECK(e->rule() == "must not be empty");
}

TEST_CASE("a repeated axis name or explicit id is refused at the second axis", "[config]") {
  json d = two_axes();
  d["axes"].push_back(json{{"name", "X"}});
  auto e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/2/name");
  CHECK(e->rule() == "must be unique; axis 0 has it too");

  d = two_axes();
  d["axes"][0]["id"] = 4;
  d["axes"][1]["id"] = 4;
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/1/id");
  CHECK(e->rule() == "must be unique; axis 0 has it too");

  d = two_axes();  // both 0: the kernel assigns them
  d["axes"][0]["id"] = 0;
  d["axes"][1]["id"] = 0;
  CHECK_FALSE(error_of(d));
}

TEST_CASE("an enum is given by its name; another string or type is refused", "[config]") {
  json d = two_axes();
  d["axes"][0]["kind"] = "servo";
  auto e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/kind");
  CHECK(e->rule() == R"(must be one of "continuous", "encoder", "two_speed")");

  d = two_axes();
  d["axes"][1]["drive_model"] = 1;
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/1/drive_model");
  CHECK(e->rule() == R"(must be one of "ideal", "first_order_lag")");

  d = two_axes();
  d["axes"][1]["drive_model"] = "first_order_lag";
  d["axes"][0]["kind"] = "encoder";
  const nc::KernelSetup setup = nc::parse_kernel_setup(d);
  CHECK(setup.axes[0].kind == nc::AxisKind::kEncoder);
  CHECK(setup.axes[1].drive_model == nc::DriveModel::kFirstOrderLag);
}

TEST_CASE("the document shape: an object with an axes array of objects", "[config]") {
  auto e = error_of(json::array());
  REQUIRE(e);
  CHECK(e->pointer().empty());
  CHECK(e->rule() == "must be an object");
  CHECK(std::string(e->what()) == "(document): must be an object (got [])");

  e = error_of(json{{"kernel", json::object()}});
  REQUIRE(e);
  CHECK(e->pointer() == "/axes");
  CHECK(e->rule() == "required");

  e = error_of(json{{"axes", json::object()}});
  REQUIRE(e);
  CHECK(e->pointer() == "/axes");
  CHECK(e->rule() == "must be an array");

  json d = two_axes();
  d["axes"][1] = "Y";
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/1");
  CHECK(e->rule() == "must be an object");

  d = two_axes();
  d["kernel"] = 0.001;
  e = error_of(d);
  REQUIRE(e);
  CHECK(e->pointer() == "/kernel");
  CHECK(e->rule() == "must be an object");
}
