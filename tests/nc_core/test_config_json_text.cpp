// JSON text and files: a syntax error, a key given twice and a missing file become ConfigErrors
// with a clear message instead of a raw parser exception; the example file in docs/ is valid.
#include <catch2/catch.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "config_error_of.hpp"
#include "nc_core/config.hpp"

namespace {

using cfgtest::error_of;

std::optional<nc::ConfigError> text_error(std::string_view text) {
  return error_of([&] { (void)nc::parse_kernel_setup_text(text); });
}

const std::filesystem::path kRepo = std::filesystem::path(__FILE__).parent_path() / ".." / "..";

}  // namespace

TEST_CASE("a syntax error gives the whole document's pointer and the parser's position",
          "[config]") {
  const auto e = text_error("{\n  \"axes\": [\n    {\"name\": \"X\",}\n  ]\n}");
  REQUIRE(e);
  CHECK(e->pointer().empty());
  const std::string what = e->what();
  // Line 3, column 18 is the '}' after the trailing comma.
  CHECK(what.rfind("(document): invalid JSON: parse error at line 3, column 18", 0) == 0);
  CHECK(what.find("unexpected '}'") != std::string::npos);
  CHECK(what.find("[json.exception") == std::string::npos);
}

TEST_CASE("empty and truncated text are syntax errors", "[config]") {
  for (const std::string_view text : {"", "   ", "{\"axes\": [", "{\"axes\": []"}) {
    INFO('"' << text << '"');
    const auto e = text_error(text);
    REQUIRE(e);
    CHECK(e->pointer().empty());
    CHECK(e->rule().rfind("invalid JSON: ", 0) == 0);
  }
}

TEST_CASE("a key given twice in one object is named, not silently dropped", "[config]") {
  auto e = text_error(R"({"axes": [{"name": "X"}, {"name": "Y", "jerk": 10, "jerk": 20}]})");
  REQUIRE(e);
  CHECK(e->pointer() == "/axes/1/jerk");
  CHECK(e->rule() == "key occurs twice in the same object");

  e = text_error(R"({"axes": [], "kernel": {}, "axes": []})");
  REQUIRE(e);
  CHECK(e->pointer() == "/axes");

  // The same key in two different objects is fine.
  CHECK_NOTHROW(nc::parse_kernel_setup_text(
      R"({"axes": [{"name": "X", "jerk": 10}, {"name": "Y", "jerk": 20, "id": 3}]})"));
}

TEST_CASE("value errors in text carry their pointer", "[config]") {
  const auto e = text_error(
      R"({"kernel": {"cycle_time": 0.001}, "axes": [{"name": "X", "acceleration": -1}]})");
  REQUIRE(e);
  CHECK(std::string(e->what()) == "/axes/0/acceleration: must be > 0 (got -1)");
}

TEST_CASE("a missing file is a ConfigError naming the file", "[config]") {
  const auto e =
      error_of([] { (void)nc::parse_kernel_setup_file("/nonexistent/ncsdk/axes.json"); });
  REQUIRE(e);
  CHECK(e->pointer().empty());
  CHECK(e->rule() == "cannot open file /nonexistent/ncsdk/axes.json");
}

TEST_CASE("docs/examples/axes.json is a valid set-up", "[config]") {
  const nc::KernelSetup setup = nc::parse_kernel_setup_file(kRepo / "docs/examples/axes.json");
  CHECK(setup.kernel.cycle_time == 0.002);
  REQUIRE(setup.axes.size() == 3);
  CHECK(setup.axes[0].name == "X");
  CHECK(setup.axes[0].max_velocity == 2200.0);
  CHECK(setup.axes[1].name == "Y");
  CHECK(setup.axes[1].drive_model == nc::DriveModel::kFirstOrderLag);
  CHECK(setup.axes[1].sw_limit_min_enabled);
  CHECK(setup.axes[2].kind == nc::AxisKind::kEncoder);
  for (const auto& axis : setup.axes)
    CHECK_NOTHROW(nc::validate(axis));
}
