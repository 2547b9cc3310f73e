// The two-speed configuration fields (SPEC E, API.md "Two-speed axis"): the rules between them
// on a two-speed axis, JSON round trip and errors with the JSON pointer, and Kernel::add_axis /
// from_json taking a valid two-speed axis and refusing a broken one.
#include <catch2/catch.hpp>

#include <string>

#include <nlohmann/json.hpp>

#include "config_error_of.hpp"
#include "nc_core/config.hpp"
#include "nc_core/kernel.hpp"
#include "two_speed_loop.hpp"

using nlohmann::json;

namespace {

using cfgtest::error_of;

nc::AxisConfig named_axis(nc::AxisKind kind = nc::AxisKind::kContinuous) {
  nc::AxisConfig c;
  c.name = std::string("T");
  c.kind = kind;
  return c;
}

}  // namespace

TEST_CASE("the two-speed defaults are valid and keep the braking inside the creep distance",
          "[config][two_speed]") {
  const nc::AxisConfig c = named_axis();
  CHECK_NOTHROW(nc::validate(c));
  CHECK_NOTHROW(nc::validate_two_speed(c));
  CHECK(c.braking_distance_positive <= c.creep_distance_positive);
  CHECK(c.braking_distance_negative <= c.creep_distance_negative);
  CHECK(c.creep_velocity <= c.rapid_velocity);
  CHECK_FALSE(c.looping_distance_enabled);
}

// The single-field ranges (>= 0, > 0, finite) of the two-speed fields are checked with every other
// field's in test_config_validate.cpp.
TEST_CASE("the looping distance is signed", "[config][two_speed]") {
  nc::AxisConfig c = named_axis();
  c.looping_distance = -30.0;
  CHECK_NOTHROW(nc::validate(c));
}

TEST_CASE("on a two-speed axis the braking distance lies within the creep distance",
          "[config][two_speed]") {
  nc::AxisConfig c = named_axis(nc::AxisKind::kTwoSpeed);
  c.creep_distance_positive = 100.0;
  c.braking_distance_positive = 100.5;
  auto e = error_of([&] { nc::validate(c); });
  REQUIRE(e);
  CHECK(e->what() == std::string("/braking_distance_positive: must be <= creep_distance_positive "
                                 "(100) on a two-speed axis (got 100.5)"));
  c.braking_distance_positive = 100.0;  // equal: no creep phase, allowed
  CHECK_NOTHROW(nc::validate_two_speed(c));

  c.creep_distance_negative = 120.0;
  c.braking_distance_negative = 121.0;
  e = error_of([&] { nc::validate_two_speed(c); });
  REQUIRE(e);
  CHECK(e->pointer() == "/braking_distance_negative");

  // The rule is a two-speed rule only: a servo axis ignores these fields.
  c.kind = nc::AxisKind::kContinuous;
  CHECK_NOTHROW(nc::validate(c));
}

TEST_CASE("on a two-speed axis the creep speed is not above the rapid speed",
          "[config][two_speed]") {
  nc::AxisConfig c = named_axis(nc::AxisKind::kTwoSpeed);
  c.rapid_velocity = 500.0;
  c.creep_velocity = 500.0;
  CHECK_NOTHROW(nc::validate_two_speed(c));
  c.creep_velocity = 600.0;
  const auto e = error_of([&] { nc::validate(c); });
  REQUIRE(e);
  CHECK(e->what() ==
        std::string(
            "/creep_velocity: must be <= rapid_velocity (500) on a two-speed axis (got 600)"));
}

// Fuzz finding K11: a rapid speed of 2.5e306 mm/s was taken, and its first step (ramp time 0)
// published an infinite ActAcc. The bound is the planner's numeric range, which bounds every
// velocity a servo axis can be commanded.
TEST_CASE("on a two-speed axis the rapid speed lies within the NC's numeric range, 1e12 mm/s",
          "[config][two_speed]") {
  nc::AxisConfig c = named_axis(nc::AxisKind::kTwoSpeed);
  c.rapid_velocity = 1e12;
  CHECK_NOTHROW(nc::validate(c));
  for (const double bad : {1.0000000000000002e12, 2.5319621617779095e306}) {
    c.rapid_velocity = bad;
    const auto e = error_of([&] { nc::validate(c); });
    REQUIRE(e);
    CHECK(e->pointer() == "/rapid_velocity");
    CHECK(e->rule() == "must be <= 1e+12 (the NC's numeric range) on a two-speed axis");
  }
  c.rapid_velocity = 2.5319621617779095e306;
  CHECK(error_of([&] { nc::validate(c); })->what() ==
        std::string("/rapid_velocity: must be <= 1e+12 (the NC's numeric range) on a two-speed "
                    "axis (got 2.5319621617779095e+306)"));
  // A servo axis does not use the field.
  c.kind = nc::AxisKind::kContinuous;
  c.creep_velocity = 50.0;
  CHECK_NOTHROW(nc::validate(c));
}

TEST_CASE("an enabled looping distance must exceed both braking distances together",
          "[config][two_speed]") {
  nc::AxisConfig c = named_axis(nc::AxisKind::kTwoSpeed);
  c.braking_distance_positive = 5.0;
  c.braking_distance_negative = 6.0;
  c.looping_distance_enabled = true;
  for (const double bad : {11.0, -11.0, 0.0, 3.0}) {
    c.looping_distance = bad;
    const auto e = error_of([&] { nc::validate(c); });
    REQUIRE(e);
    CHECK(e->pointer() == "/looping_distance");
    CHECK(e->rule() ==
          "|looping_distance| must be > braking_distance_positive + braking_distance_negative "
          "(11) when looping_distance_enabled");
  }
  for (const double good : {11.5, -30.0}) {
    c.looping_distance = good;
    CHECK_NOTHROW(nc::validate_two_speed(c));
  }
  c.looping_distance_enabled = false;
  c.looping_distance = 0.0;  // disabled: not evaluated
  CHECK_NOTHROW(nc::validate_two_speed(c));
}

TEST_CASE("the kernel takes a valid two-speed axis and refuses a broken one whole",
          "[config][two_speed]") {
  const nc::AxisConfig c = named_axis(nc::AxisKind::kTwoSpeed);
  REQUIRE_NOTHROW(nc::validate(c));

  nc::Kernel kernel;
  nc::AxisConfig servo = named_axis();
  servo.name = std::string("X");  // GCC 12 warns falsely (-Wrestrict) on = "X"
  kernel.add_axis(servo);
  nc::AxisConfig broken = c;
  broken.braking_distance_positive = broken.creep_distance_positive + 1.0;
  auto e = error_of([&] { kernel.add_axis(broken); });
  REQUIRE(e);
  CHECK(e->pointer() == "/braking_distance_positive");
  CHECK(kernel.axis_count() == 1);  // nothing added, the servo axis untouched
  kernel.add_axis(c);
  CHECK(kernel.axis_count() == 2);
  CHECK(kernel.config("T").kind == nc::AxisKind::kTwoSpeed);
  CHECK(kernel.two_speed_output("T").nControlByte != 0);  // brake applied: bBreak set
  e = error_of([&] { (void)kernel.two_speed_output("X"); });
  REQUIRE(e);
  CHECK(e->rule() == "has this axis, but not of kind two_speed");

  json document = {{"axes", {{{"name", "X"}}, {{"name", "T"}, {"kind", "two_speed"}}}}};
  const nc::Kernel from_json = nc::Kernel::from_json(document);
  CHECK(from_json.config("T").kind == nc::AxisKind::kTwoSpeed);
  document["axes"][1]["creep_velocity"] = 600.0;  // above rapid_velocity (500 by default)
  e = error_of([&] { (void)nc::Kernel::from_json(document); });
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/1/creep_velocity");
}

TEST_CASE("the two-speed fields go through JSON unchanged", "[config][two_speed]") {
  nc::AxisConfig c = ts::issue_axis();  // issue 12's parameters, all different from the defaults
  c.kind = nc::AxisKind::kContinuous;
  c.looping_distance_enabled = true;
  c.looping_distance = -1.0 / 3.0;  // all 17 digits needed
  const json j = nc::to_json(c);
  CHECK(j.at("braking_distance_negative") == 6.0);
  CHECK(j.at("looping_distance_enabled") == true);
  CHECK(nc::parse_axis_config(j) == c);
  CHECK(nc::parse_kernel_setup_text(nc::to_json(nc::KernelSetup{{}, {c}}).dump()).axes[0] == c);

  c.kind = nc::AxisKind::kTwoSpeed;
  CHECK(nc::to_json(c).at("kind") == "two_speed");
  CHECK(nc::to_string(nc::AxisKind::kTwoSpeed) == "two_speed");
}

TEST_CASE("bad two-speed values in JSON name their pointer", "[config][two_speed]") {
  const auto error_for = [](const char* key, const json& value) {
    json axis = {{"name", "T"}};
    axis[key] = value;
    const json document = {{"axes", {axis}}};
    return error_of([&] { (void)nc::parse_kernel_setup(document); });
  };
  auto e = error_for("braking_distance_negative", -1);
  REQUIRE(e);
  CHECK(e->what() == std::string("/axes/0/braking_distance_negative: must be >= 0 (got -1)"));
  e = error_for("creep_velocity", "slow");
  REQUIRE(e);
  CHECK(e->what() == std::string(R"(/axes/0/creep_velocity: must be a number (got "slow"))"));
  e = error_for("looping_distance_enabled", 1);
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/looping_distance_enabled");
  e = error_of([] {
    (void)nc::parse_kernel_setup_text(R"({"axes": [{"name": "T", "brake_release_delay": 1e999}]})");
  });
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/0/brake_release_delay");
  e = error_for("kind", "two-speed");
  REQUIRE(e);
  CHECK(e->rule() == R"(must be one of "continuous", "encoder", "two_speed")");
}
