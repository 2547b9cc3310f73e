// docs/configuration.md lists every field exactly as the visitor describes it: key, type, unit,
// default and range. When a field or rule changes, this test prints the row the doc needs.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "nc_core/config.hpp"
#include "text_file.hpp"

namespace {

std::string read_doc() {
  const auto path =
      std::filesystem::path(__FILE__).parent_path() / ".." / ".." / "docs" / "configuration.md";
  return ncsdk_test::read_text(path);
}

std::string row(const nc::FieldDoc& f) {
  return "| `" + f.key + "` | " + f.type + " | " + (f.unit.empty() ? "–" : f.unit) + " | " +
         f.default_value + " | " + f.range + " | " + f.meaning + " |";
}

void check_rows(const std::string& doc, const std::vector<nc::FieldDoc>& fields) {
  for (const nc::FieldDoc& f : fields) {
    const std::string expected = row(f);
    INFO("docs/configuration.md needs the row:\n" << expected);
    CHECK(doc.find(expected + "\n") != std::string::npos);
  }
}

}  // namespace

TEST_CASE("docs/configuration.md documents every kernel and axis field", "[config]") {
  const std::string doc = read_doc();
  REQUIRE_FALSE(doc.empty());
  check_rows(doc, nc::describe_kernel_fields());
  check_rows(doc, nc::describe_axis_fields());
}

TEST_CASE("the field reference states the defaults of axis_config.hpp", "[config]") {
  for (const nc::FieldDoc& f : nc::describe_axis_fields()) {
    if (f.key == "max_velocity") CHECK(f.default_value == "2200.0");
    if (f.key == "jerk") CHECK(f.default_value == "50000.0");
    if (f.key == "override_type") CHECK(f.range == "[1, 4]");
    if (f.key == "kind") CHECK(f.default_value == "\"continuous\"");
    if (f.key == "acceleration") CHECK(f.unit == "mm/s²");
  }
  REQUIRE(nc::describe_kernel_fields().size() == 1);
  CHECK(nc::describe_kernel_fields()[0].range == "[5e-05, 0.01]");
}
