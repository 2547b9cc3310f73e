// Kernel set-up (SPEC A5, API.md): configurations are validated when the kernel is made and an
// axis is added, names and ids are unique, AXIS_REF references stay valid for the kernel's life,
// and from_json builds the same kernel with errors that name the JSON pointer.
#include <catch2/catch.hpp>

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "kernel_harness.hpp"
#include "nc_core/config.hpp"

TEST_CASE("a bad kernel or axis configuration is refused with a ConfigError naming the field",
          "[kernel][setup]") {
  CHECK_THROWS_AS(nc::Kernel(nc::KernelConfig{0.0}), nc::ConfigError);
  CHECK_THROWS_AS(nc::Kernel(nc::KernelConfig{0.02}), nc::ConfigError);
  nc::Kernel kernel;
  nc::AxisConfig bad = kt::seed_axis();
  bad.jerk = -1.0;
  try {
    kernel.add_axis(bad);
    FAIL("no ConfigError");
  } catch (const nc::ConfigError& e) {
    CHECK(e.pointer() == "/jerk");
  }
  nc::AxisConfig unnamed = kt::seed_axis("");
  CHECK_THROWS_AS(kernel.add_axis(unnamed), nc::ConfigError);
  CHECK(kernel.axis_count() == 0);
}

TEST_CASE("axis names and ids are unique; id 0 becomes index + 1", "[kernel][setup]") {
  nc::Kernel kernel;
  kernel.add_axis(kt::seed_axis("X"));
  nc::AxisConfig y = kt::seed_axis("Y");
  y.id = 7;
  kernel.add_axis(y);
  try {
    kernel.add_axis(kt::seed_axis("X"));
    FAIL("no ConfigError");
  } catch (const nc::ConfigError& e) {
    CHECK(e.pointer() == "/name");
  }
  nc::AxisConfig z = kt::seed_axis("Z");
  z.id = 7;
  try {
    kernel.add_axis(z);
    FAIL("no ConfigError");
  } catch (const nc::ConfigError& e) {
    CHECK(e.pointer() == "/id");
  }
  CHECK(kernel.axis_count() == 2);
  CHECK(kernel.config("X").id == 1);
  CHECK(kernel.config("Y").id == 7);
  CHECK(kernel.axis("Y").NcToPlc.AxisIndex == 1);
  CHECK(&kernel.axis(std::size_t{1}) == &kernel.axis("Y"));
  CHECK_THROWS_AS(kernel.axis("W"), nc::ConfigError);
  CHECK_THROWS_AS(kernel.config("W"), nc::ConfigError);
}

TEST_CASE("AXIS_REF references stay valid while axes are added and the kernel is moved",
          "[kernel][setup]") {
  nc::Kernel kernel;
  std::vector<plc::AXIS_REF*> refs;
  for (int i = 0; i < 300; ++i)
    refs.push_back(&kernel.add_axis(kt::seed_axis(std::to_string(i))));
  for (int i = 0; i < 300; ++i)
    CHECK(refs[static_cast<std::size_t>(i)] == &kernel.axis(std::to_string(i)));

  kt::set_enables(*refs[42], true);
  refs[42]->Mailbox.post(kt::move_absolute(1.0, 100.0));
  nc::Kernel moved = std::move(kernel);
  CHECK(&moved.axis("42") == refs[42]);
  moved.cycle();
  CHECK(refs[42]->NcToPlc.CmdState == static_cast<uint16_t>(plc::CommandState::kActive));
}

TEST_CASE("from_json builds the kernel the document describes", "[kernel][setup][json]") {
  const auto doc = nlohmann::json::parse(R"({
    "kernel": {"cycle_time": 0.002},
    "axes": [
      {"name": "X", "max_velocity": 1500, "ref_velocity": 1500},
      {"name": "Y", "id": 12, "drive_model": "first_order_lag", "drive_time_constant": 0.01}
    ]})");
  nc::Kernel kernel = nc::Kernel::from_json(doc);
  CHECK(kernel.cycle_time() == 0.002);
  CHECK(kernel.axis_count() == 2);
  CHECK(kernel.config("X").max_velocity == 1500.0);
  CHECK(kernel.config("X").id == 1);
  CHECK(kernel.config("Y").id == 12);
  CHECK(kernel.config("Y").drive_model == nc::DriveModel::kFirstOrderLag);

  // The limits of the file apply: 1600 mm/s is above X's maximum.
  plc::AXIS_REF& x = kernel.axis("X");
  kt::set_enables(x, true);
  const uint16_t n = x.Mailbox.post(kt::move_absolute(10.0, 1600.0));
  kernel.cycle();
  CHECK(x.Mailbox.answer(n).error_code == kt::id(plc::ErrorCode::kVelocityNotAllowed));
  CHECK(kernel.time() == 0.002);
}

TEST_CASE("from_json errors name the JSON pointer and nothing is built", "[kernel][setup][json]") {
  struct Case {
    const char* text;
    const char* pointer;
  };
  const Case cases[] = {
      {R"({"axes": [{"name": "X"}, {"name": "Y", "jerk": -5}]})", "/axes/1/jerk"},
      {R"({"axes": [{"name": "X"}, {"name": "X"}]})", "/axes/1/name"},
      {R"({"axes": [{"name": "X", "speed": 5}]})", "/axes/0/speed"},
      {R"({"axes": [{"max_velocity": 5}]})", "/axes/0/name"},
      {R"({"kernel": {"cycle_time": "fast"}, "axes": []})", "/kernel/cycle_time"},
  };
  for (const Case& c : cases) {
    INFO(c.text);
    try {
      (void)nc::Kernel::from_json(nlohmann::json::parse(c.text));
      FAIL("no ConfigError");
    } catch (const nc::ConfigError& e) {
      CHECK(e.pointer() == c.pointer);
    }
  }
}
