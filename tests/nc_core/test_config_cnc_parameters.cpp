// SPEC D6: CNC parameters load in their native units from an axis's "cnc" object (seed 002 §4):
// P-AXIS-00177/00178 in 0.1 µm, P-AXIS-00003 in mm/s² with 0 = the axis's acceleration,
// P-AXIS-00436/00460 as 0/1; every bad value names its JSON pointer; the result round-trips.
#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "config_error_of.hpp"
#include "nc_core/cnc_parameters.hpp"
#include "nc_core/config.hpp"

using cfgtest::error_of;
using nlohmann::json;

namespace {

json axis_with(const json& cnc) {
  return json{{"axes", json::array({json{
                           {"name", "Y2"}, {"id", 8}, {"acceleration", 4000.0}, {"cnc", cnc}}})}};
}

}  // namespace

TEST_CASE("the seed's parameters load in native units", "[config][cnc]") {
  const nc::KernelSetup setup = nc::parse_kernel_setup(axis_with({{"P-AXIS-00177", -100000000},
                                                                  {"P-AXIS-00178", 12345678},
                                                                  {"P-AXIS-00003", 7000},
                                                                  {"P-AXIS-00436", 1},
                                                                  {"P-AXIS-00460", 1}}));
  const nc::AxisConfig& a = setup.axes.at(0);
  CHECK(a.sw_limit_min == -10000.0);
  CHECK(a.sw_limit_min_enabled);
  CHECK(a.sw_limit_max == Approx(1234.5678).epsilon(1e-15));
  CHECK(a.sw_limit_max_enabled);
  CHECK(a.emergency_deceleration == 7000.0);
  CHECK(a.recalc_link_main_input_position);
  CHECK(a.recalc_input_position_absolute);
  CHECK(a.acceleration == 4000.0);  // untouched
}

TEST_CASE("P-AXIS-00003 = 0 is the axis's acceleration; up to 2 x acceleration is allowed",
          "[config][cnc]") {
  CHECK(nc::parse_kernel_setup(axis_with({{"P-AXIS-00003", 0}})).axes[0].emergency_deceleration ==
        4000.0);
  CHECK(
      nc::parse_kernel_setup(axis_with({{"P-AXIS-00003", 8000}})).axes[0].emergency_deceleration ==
      8000.0);
  CHECK(nc::cnc::emergency_deceleration_from_native(0, 123.0) == 123.0);
  const auto e = error_of(axis_with({{"P-AXIS-00003", 8001}}));
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/cnc/P-AXIS-00003");
  CHECK(e->value() == "8001");
  const auto negative = error_of(axis_with({{"P-AXIS-00003", -1}}));
  REQUIRE(negative);
  CHECK(negative->pointer() == "/axes/0/cnc/P-AXIS-00003");
}

TEST_CASE("bad CNC parameters are refused with their JSON pointer", "[config][cnc]") {
  struct Case {
    json cnc;
    std::string pointer;
  };
  const Case cases[] = {
      {{{"P-AXIS-00177", 5000}, {"P-AXIS-00178", 5000}}, "/axes/0/cnc/P-AXIS-00177"},
      {{{"P-AXIS-00177", std::numeric_limits<int32_t>::min()}}, "/axes/0/cnc/P-AXIS-00177"},
      {{{"P-AXIS-00178", std::numeric_limits<int32_t>::max()}}, "/axes/0/cnc/P-AXIS-00178"},
      {{{"P-AXIS-00178", 3000000000LL}}, "/axes/0/cnc/P-AXIS-00178"},
      {{{"P-AXIS-00178", 1.5}}, "/axes/0/cnc/P-AXIS-00178"},
      {{{"P-AXIS-00178", "100"}}, "/axes/0/cnc/P-AXIS-00178"},
      {{{"P-AXIS-00436", 2}}, "/axes/0/cnc/P-AXIS-00436"},
      {{{"P-AXIS-00436", true}}, "/axes/0/cnc/P-AXIS-00436"},
      {{{"P-AXIS-00460", 1}}, "/axes/0/recalc_input_position_absolute"},  // needs 00436
      {{{"P-AXIS-00008", 1}}, "/axes/0/cnc/P-AXIS-00008"},
      {json::array({1}), "/axes/0/cnc"},
  };
  for (const Case& c : cases) {
    INFO(c.cnc.dump());
    const auto e = error_of(axis_with(c.cnc));
    REQUIRE(e);
    CHECK(e->pointer() == c.pointer);
  }
}

TEST_CASE("a setting given both as a field and as its CNC parameter is refused", "[config][cnc]") {
  json doc = axis_with({{"P-AXIS-00003", 0}});
  doc["axes"][0]["emergency_deceleration"] = 900.0;
  auto e = error_of(doc);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/cnc/P-AXIS-00003");
  CHECK(e->rule().find("emergency_deceleration") != std::string::npos);

  doc = axis_with({{"P-AXIS-00178", 10}});
  doc["axes"][0]["sw_limit_max_enabled"] = false;
  e = error_of(doc);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/cnc/P-AXIS-00178");
}

TEST_CASE("a configuration read from native units round-trips through to_json", "[config][cnc]") {
  const nc::KernelSetup first = nc::parse_kernel_setup(axis_with({{"P-AXIS-00177", -2500001},
                                                                  {"P-AXIS-00178", 999999},
                                                                  {"P-AXIS-00003", 0},
                                                                  {"P-AXIS-00436", 1}}));
  const nc::KernelSetup again = nc::parse_kernel_setup(nc::to_json(first));
  CHECK(again == first);
  CHECK(nc::cnc::length_to_native(first.axes[0].sw_limit_min) == -2500001);
  CHECK(nc::cnc::length_to_native(first.axes[0].sw_limit_max) == 999999);
}

TEST_CASE("native length converters: 0.1 um per unit, exact back and forth, saturating",
          "[config][cnc]") {
  for (const int32_t v :
       {0, 1, -1, 7, 123456789, -100000000, 100000000, std::numeric_limits<int32_t>::max() - 1,
        std::numeric_limits<int32_t>::min() + 1}) {
    CHECK(nc::cnc::length_to_native(nc::cnc::length_from_native(v)) == v);
  }
  CHECK(nc::cnc::length_from_native(10000) == 1.0);  // 1 mm (1°)
  CHECK(nc::cnc::length_to_native(1e9) == std::numeric_limits<int32_t>::max());
  CHECK(nc::cnc::length_to_native(-1e9) == std::numeric_limits<int32_t>::min());
  CHECK(nc::cnc::length_to_native(std::numeric_limits<double>::quiet_NaN()) ==
        std::numeric_limits<int32_t>::max());
}
