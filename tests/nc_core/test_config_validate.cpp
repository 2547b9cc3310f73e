// validate() on configurations built in code: every rule of axis_config.hpp is enforced and the
// error names the field as a pointer relative to the struct (SPEC A5).
#include <catch2/catch.hpp>

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "config_error_of.hpp"
#include "nc_core/config.hpp"

namespace {

using cfgtest::error_of;

nc::AxisConfig named_axis() {
  nc::AxisConfig c;
  c.name = std::string("X");  // move-assigned: GCC 12 warns falsely (-Wrestrict) on = "X" here
  return c;
}

using DoubleField = std::pair<const char*, double nc::AxisConfig::*>;

const std::vector<DoubleField> kPositiveFields = {
    {"max_velocity", &nc::AxisConfig::max_velocity},
    {"ref_velocity", &nc::AxisConfig::ref_velocity},
    {"acceleration", &nc::AxisConfig::acceleration},
    {"deceleration", &nc::AxisConfig::deceleration},
    {"jerk", &nc::AxisConfig::jerk},
    {"emergency_deceleration", &nc::AxisConfig::emergency_deceleration},
    {"emergency_jerk", &nc::AxisConfig::emergency_jerk},
    {"modulo_factor", &nc::AxisConfig::modulo_factor},
    {"following_error_limit", &nc::AxisConfig::following_error_limit},
    {"target_window", &nc::AxisConfig::target_window},
    {"position_range_window", &nc::AxisConfig::position_range_window},
    {"standstill_window", &nc::AxisConfig::standstill_window},
    {"rapid_velocity", &nc::AxisConfig::rapid_velocity},
    {"creep_velocity", &nc::AxisConfig::creep_velocity},
};

const std::vector<DoubleField> kNonNegativeFields = {
    {"drive_max_velocity", &nc::AxisConfig::drive_max_velocity},
    {"encoder_increment", &nc::AxisConfig::encoder_increment},
    {"following_error_filter_time", &nc::AxisConfig::following_error_filter_time},
    {"target_window_time", &nc::AxisConfig::target_window_time},
    // Two-speed distances and delays: checked on every axis kind.
    {"creep_distance_positive", &nc::AxisConfig::creep_distance_positive},
    {"creep_distance_negative", &nc::AxisConfig::creep_distance_negative},
    {"braking_distance_positive", &nc::AxisConfig::braking_distance_positive},
    {"braking_distance_negative", &nc::AxisConfig::braking_distance_negative},
    {"brake_incidence_delay_positive", &nc::AxisConfig::brake_incidence_delay_positive},
    {"brake_incidence_delay_negative", &nc::AxisConfig::brake_incidence_delay_negative},
    {"rapid_to_creep_delay", &nc::AxisConfig::rapid_to_creep_delay},
    {"creep_distance_stop", &nc::AxisConfig::creep_distance_stop},
    {"brake_release_delay", &nc::AxisConfig::brake_release_delay},
    {"two_speed_ramp_time", &nc::AxisConfig::two_speed_ramp_time},
};

const std::vector<DoubleField> kAllDoubleFields = [] {
  std::vector<DoubleField> all = kPositiveFields;
  all.insert(all.end(), kNonNegativeFields.begin(), kNonNegativeFields.end());
  all.push_back({"position_kv", &nc::AxisConfig::position_kv});
  all.push_back({"drive_time_constant", &nc::AxisConfig::drive_time_constant});
  all.push_back({"velocity_feed_forward", &nc::AxisConfig::velocity_feed_forward});
  all.push_back({"drive_dead_time", &nc::AxisConfig::drive_dead_time});
  all.push_back({"sw_limit_min", &nc::AxisConfig::sw_limit_min});
  all.push_back({"sw_limit_max", &nc::AxisConfig::sw_limit_max});
  all.push_back({"looping_distance", &nc::AxisConfig::looping_distance});
  return all;
}();

}  // namespace

TEST_CASE("a default axis with a name and the default kernel are valid", "[config]") {
  CHECK_NOTHROW(nc::validate(named_axis()));
  CHECK_NOTHROW(nc::validate(nc::KernelConfig{}));
}

TEST_CASE("an axis without a name is refused at /name", "[config]") {
  const auto e = error_of([] { nc::validate(nc::AxisConfig{}); });
  REQUIRE(e);
  CHECK(e->pointer() == "/name");
  CHECK(e->rule() == "must not be empty");
  CHECK(std::string(e->what()) == "/name: must not be empty");
}

TEST_CASE("every positive field refuses 0 and a negative value, naming the field", "[config]") {
  for (const auto& [key, member] : kPositiveFields) {
    for (const double bad : {0.0, -1.0, -5000.0}) {
      INFO(key << " = " << bad);
      nc::AxisConfig c = named_axis();
      c.*member = bad;
      const auto e = error_of([&] { nc::validate(c); });
      REQUIRE(e);
      CHECK(e->pointer() == std::string("/") + key);
      CHECK(e->rule() == "must be > 0");
    }
    nc::AxisConfig c = named_axis();
    c.*member = 1e-9;
    CHECK_NOTHROW(nc::validate(c));
  }
}

TEST_CASE("every non-negative field accepts 0 and refuses a negative value", "[config]") {
  for (const auto& [key, member] : kNonNegativeFields) {
    INFO(key);
    nc::AxisConfig c = named_axis();
    c.*member = 0.0;
    CHECK_NOTHROW(nc::validate(c));
    c.*member = -1e-3;
    const auto e = error_of([&] { nc::validate(c); });
    REQUIRE(e);
    CHECK(e->pointer() == std::string("/") + key);
    CHECK(e->rule() == "must be >= 0");
    CHECK(std::string(e->what()) == std::string("/") + key + ": must be >= 0 (got -0.001)");
  }
}

TEST_CASE("NaN and infinities set in code are refused in every number field", "[config]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const auto& [key, member] : kAllDoubleFields) {
    for (const double bad : {nan, inf, -inf}) {
      INFO(key << " = " << bad);
      nc::AxisConfig c = named_axis();
      c.*member = bad;
      const auto e = error_of([&] { nc::validate(c); });
      REQUIRE(e);
      CHECK(e->pointer() == std::string("/") + key);
      CHECK(e->rule() == "must be finite");
    }
  }
  nc::KernelConfig k;
  k.cycle_time = nan;
  const auto e = error_of([&] { nc::validate(k); });
  REQUIRE(e);
  CHECK(std::string(e->what()) == "/cycle_time: must be finite (got nan)");
}

TEST_CASE("override_type is 1 to 4 (seed 000 §2.2)", "[config]") {
  for (const int ok : {1, 2, 3, 4}) {
    nc::AxisConfig c = named_axis();
    c.override_type = ok;
    CHECK_NOTHROW(nc::validate(c));
  }
  for (const int bad : {0, 5, -1}) {
    nc::AxisConfig c = named_axis();
    c.override_type = bad;
    const auto e = error_of([&] { nc::validate(c); });
    REQUIRE(e);
    CHECK(e->pointer() == "/override_type");
    CHECK(e->rule() == "must be in [1, 4]");
  }
}

TEST_CASE("id is 0 (assigned by the kernel) or positive", "[config]") {
  nc::AxisConfig c = named_axis();
  c.id = 7;
  CHECK_NOTHROW(nc::validate(c));
  c.id = -1;
  const auto e = error_of([&] { nc::validate(c); });
  REQUIRE(e);
  CHECK(e->pointer() == "/id");
  CHECK(e->rule() == "must be >= 0");
}

TEST_CASE("velocity_feed_forward is a fraction 0 to 1", "[config]") {
  for (const double ok : {0.0, 0.5, 1.0}) {
    nc::AxisConfig c = named_axis();
    c.velocity_feed_forward = ok;
    CHECK_NOTHROW(nc::validate(c));
  }
  for (const double bad : {-0.1, 1.01}) {
    nc::AxisConfig c = named_axis();
    c.velocity_feed_forward = bad;
    const auto e = error_of([&] { nc::validate(c); });
    REQUIRE(e);
    CHECK(e->pointer() == "/velocity_feed_forward");
    CHECK(e->rule() == "must be in [0, 1]");
  }
}

TEST_CASE("position_kv is 0 to 100 1/s (issue 16: 1.3e88 was accepted and overflowed)",
          "[config]") {
  for (const double ok : {0.0, 1.0, 100.0}) {
    nc::AxisConfig c = named_axis();
    c.position_kv = ok;
    CHECK_NOTHROW(nc::validate(c));
  }
  for (const double bad : {-1.0, 100.5, 1.3e88}) {
    nc::AxisConfig c = named_axis();
    c.position_kv = bad;
    const auto e = error_of([&] { nc::validate(c); });
    REQUIRE(e);
    CHECK(e->pointer() == "/position_kv");
    CHECK(e->rule() == "must be in [0, 100]");
  }
}

TEST_CASE("drive_time_constant is 0 to 100 s (fuzz finding C2: 1e308 was accepted and overflowed)",
          "[config]") {
  for (const double ok : {0.0, 0.01, 100.0}) {
    nc::AxisConfig c = named_axis();
    c.drive_time_constant = ok;
    CHECK_NOTHROW(nc::validate(c));
  }
  for (const double bad : {-0.01, 100.5, 1e308}) {
    nc::AxisConfig c = named_axis();
    c.drive_time_constant = bad;
    const auto e = error_of([&] { nc::validate(c); });
    REQUIRE(e);
    CHECK(e->pointer() == "/drive_time_constant");
    CHECK(e->rule() == "must be in [0, 100]");
  }
}

TEST_CASE("drive_dead_time is at most 1 s", "[config]") {
  nc::AxisConfig c = named_axis();
  c.drive_dead_time = 1.0;
  CHECK_NOTHROW(nc::validate(c));
  c.drive_dead_time = 1.001;
  const auto e = error_of([&] { nc::validate(c); });
  REQUIRE(e);
  CHECK(e->pointer() == "/drive_dead_time");
  CHECK(e->rule() == "must be in [0, 1]");
}

TEST_CASE("cycle_time is 50 us to 10 ms", "[config]") {
  for (const double ok : {50e-6, 1e-3, 2e-3, 10e-3}) {
    CHECK_NOTHROW(nc::validate(nc::KernelConfig{ok}));
  }
  for (const double bad : {0.0, 49e-6, 10.001e-3, -1e-3}) {
    INFO(bad);
    const auto e = error_of([&] { nc::validate(nc::KernelConfig{bad}); });
    REQUIRE(e);
    CHECK(e->pointer() == "/cycle_time");
    CHECK(e->rule() == "must be in [5e-05, 0.01]");
  }
}

TEST_CASE("software limits: min below max only when both are enabled", "[config]") {
  nc::AxisConfig c = named_axis();
  c.sw_limit_min = 100.0;
  c.sw_limit_max = 100.0;
  c.sw_limit_min_enabled = true;
  CHECK_NOTHROW(nc::validate(c));  // only one limit active: no range to be empty
  c.sw_limit_min_enabled = false;
  c.sw_limit_max_enabled = true;
  CHECK_NOTHROW(nc::validate(c));

  c.sw_limit_min_enabled = true;
  for (const double min : {100.0, 150.0}) {
    c.sw_limit_min = min;
    const auto e = error_of([&] { nc::validate(c); });
    REQUIRE(e);
    CHECK(e->pointer() == "/sw_limit_min");
    CHECK(e->rule() == "must be < sw_limit_max (100) when both software limits are enabled");
  }
  c.sw_limit_min = 99.999;
  CHECK_NOTHROW(nc::validate(c));
}

TEST_CASE("an enum value outside the named ones is refused", "[config]") {
  nc::AxisConfig c = named_axis();
  c.kind = static_cast<nc::AxisKind>(7);
  auto e = error_of([&] { nc::validate(c); });
  REQUIRE(e);
  CHECK(e->pointer() == "/kind");
  CHECK(e->rule() == R"(must be one of "continuous", "encoder", "two_speed")");

  c = named_axis();
  c.drive_model = static_cast<nc::DriveModel>(-1);
  e = error_of([&] { nc::validate(c); });
  REQUIRE(e);
  CHECK(e->pointer() == "/drive_model");
  CHECK(e->rule() == R"(must be one of "ideal", "first_order_lag")");
}
