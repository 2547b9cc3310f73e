// Keys absent from a JSON document keep the defaults of axis_config.hpp (seed 000 §2.1 values).
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "nc_core/config.hpp"

using nlohmann::json;

TEST_CASE("an axis given only its name has every default", "[config]") {
  const nc::KernelSetup setup = nc::parse_kernel_setup(json::parse(R"({"axes": [{"name": "X"}]})"));
  REQUIRE(setup.axes.size() == 1);
  nc::AxisConfig expected;
  expected.name = "X";
  CHECK(setup.axes[0] == expected);

  // The defaults themselves, as axis_config.hpp and docs/configuration.md state them.
  const nc::AxisConfig& a = setup.axes[0];
  CHECK(a.id == 0);
  CHECK(a.kind == nc::AxisKind::kContinuous);
  CHECK(a.max_velocity == 2200.0);
  CHECK(a.ref_velocity == 2200.0);
  CHECK(a.acceleration == 5000.0);
  CHECK(a.deceleration == 5000.0);
  CHECK(a.jerk == 50000.0);
  CHECK(a.modulo_factor == 360.0);
  CHECK(a.override_type == 3);
  CHECK(a.drive_model == nc::DriveModel::kIdeal);
  CHECK_FALSE(a.sw_limit_min_enabled);
  CHECK_FALSE(a.sw_limit_max_enabled);
  CHECK(a.following_error_enabled);
}

TEST_CASE("the kernel object is optional and its keys too", "[config]") {
  CHECK(nc::parse_kernel_setup(json::parse(R"({"axes": []})")).kernel.cycle_time == 0.001);
  CHECK(nc::parse_kernel_setup(json::parse(R"({"kernel": {}, "axes": []})")).kernel ==
        nc::KernelConfig{});
}

TEST_CASE("an empty axes array is a kernel without axes", "[config]") {
  CHECK(nc::parse_kernel_setup(json::parse(R"({"axes": []})")).axes.empty());
}

TEST_CASE("a key present overrides only its own field", "[config]") {
  const nc::KernelSetup setup =
      nc::parse_kernel_setup(json::parse(R"({"axes": [{"name": "X", "deceleration": 3000}]})"));
  nc::AxisConfig expected;
  expected.name = "X";
  expected.deceleration = 3000.0;
  CHECK(setup.axes[0] == expected);
}
