// The five SPEC C7 / C8 axis fields (seed 000 §3.1 "Error Propagation Mode", "Error Propagation
// Delay", "Couple slave to actual values if not enabled", "Velocity Window", "Filter Time for
// Velocity Window"): their defaults, JSON spelling and round trip, and the refusals with the JSON
// pointer of the bad value.
#include <catch2/catch.hpp>

#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "config_error_of.hpp"
#include "nc_core/config.hpp"

using cfgtest::error_of;
using nlohmann::json;

namespace {

json one_axis(const json& fields) {
  json axis = {{"name", "X"}};
  axis.update(fields);
  return json{{"axes", json::array({axis})}};
}

}  // namespace

TEST_CASE("error propagation and actual-value coupling have the seed's defaults", "[config]") {
  const nc::AxisConfig c;
  CHECK(c.error_propagation_mode == nc::ErrorPropagation::kInstantaneous);
  CHECK(c.error_propagation_delay == 0.0);
  CHECK_FALSE(c.couple_slave_to_actual_values);
  CHECK(c.actual_value_velocity_window == 1.0);
  CHECK(c.actual_value_filter_time == 0.01);
  CHECK(nc::to_string(nc::ErrorPropagation::kDelayed) == "delayed");
  CHECK(nc::to_string(nc::ErrorPropagation::kInstantaneous) == "instantaneous");
}

TEST_CASE("the C7 / C8 fields are read from JSON and written back", "[config]") {
  const json d = one_axis({{"error_propagation_mode", "delayed"},
                           {"error_propagation_delay", 0.5},
                           {"couple_slave_to_actual_values", true},
                           {"actual_value_velocity_window", 2.5},
                           {"actual_value_filter_time", 0.02}});
  const nc::KernelSetup setup = nc::parse_kernel_setup(d);
  REQUIRE(setup.axes.size() == 1);
  const nc::AxisConfig& a = setup.axes[0];
  CHECK(a.error_propagation_mode == nc::ErrorPropagation::kDelayed);
  CHECK(a.error_propagation_delay == 0.5);
  CHECK(a.couple_slave_to_actual_values);
  CHECK(a.actual_value_velocity_window == 2.5);
  CHECK(a.actual_value_filter_time == 0.02);
  const json written = nc::to_json(a);
  CHECK(written["error_propagation_mode"] == "delayed");
  CHECK(written["error_propagation_delay"] == 0.5);
  CHECK(nc::parse_kernel_setup(json{{"axes", json::array({written})}}).axes[0] == a);
}

TEST_CASE("bad C7 / C8 values are refused with the JSON pointer", "[config]") {
  struct Bad {
    const char* key;
    json value;
    const char* rule;
  };
  const Bad cases[] = {
      {"error_propagation_mode", "later", "must be one of \"instantaneous\", \"delayed\""},
      {"error_propagation_mode", 1, "must be one of \"instantaneous\", \"delayed\""},
      {"error_propagation_delay", -0.001, "must be >= 0"},
      {"error_propagation_delay", "0.5", "must be a number"},
      {"couple_slave_to_actual_values", 1, "must be true or false"},
      {"actual_value_velocity_window", 0.0, "must be > 0"},
      {"actual_value_velocity_window", -1.0, "must be > 0"},
      {"actual_value_filter_time", 0.0, "must be > 0"},
  };
  for (const Bad& b : cases) {
    INFO(b.key << " = " << b.value.dump());
    const auto e = error_of(one_axis({{b.key, b.value}}));
    REQUIRE(e);
    CHECK(e->pointer() == std::string("/axes/0/") + b.key);
    CHECK(e->rule() == b.rule);
  }
}

TEST_CASE("a delay or window that is not finite is refused by validate()", "[config]") {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double bad : {inf, -inf, nan}) {
    nc::AxisConfig c;
    c.name = "X";
    c.error_propagation_delay = bad;
    auto e = error_of([&] { nc::validate(c); });
    REQUIRE(e);
    CHECK(e->pointer() == "/error_propagation_delay");
    c.error_propagation_delay = 0.0;
    c.actual_value_velocity_window = bad;
    e = error_of([&] { nc::validate(c); });
    REQUIRE(e);
    CHECK(e->pointer() == "/actual_value_velocity_window");
    c.actual_value_velocity_window = 1.0;
    c.actual_value_filter_time = bad;
    e = error_of([&] { nc::validate(c); });
    REQUIRE(e);
    CHECK(e->pointer() == "/actual_value_filter_time");
  }
  nc::AxisConfig c;
  c.name = "X";
  c.error_propagation_mode = static_cast<nc::ErrorPropagation>(7);
  const auto e = error_of([&] { nc::validate(c); });
  REQUIRE(e);
  CHECK(e->pointer() == "/error_propagation_mode");
}
