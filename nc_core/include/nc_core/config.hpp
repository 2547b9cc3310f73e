// Checking, reading and writing the kernel and axis configuration (SPEC A5).
//
// A configuration comes from code (KernelConfig / AxisConfig literals) or from a JSON document
//   {"kernel": {KernelConfig fields}, "axes": [{AxisConfig fields}, ...]}
// whose keys are the C++ field names (see config_fields.hpp and docs/configuration.md). Every
// bad value is reported as an nc::ConfigError that names the field by its JSON pointer and the
// rule it broke, so that nothing starts on a bad file.
//
// Everything here is a set-up function: it may allocate and throws nc::ConfigError. None of it
// may be called from the cycle path.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "nc_core/axis_config.hpp"
#include "nc_core/config_fields.hpp"

namespace nc {

// A configuration value that breaks a rule. what() is "<pointer>: <rule>" followed by
// " (got <value>)" when the offending value is known; a pointer of "" (the whole document) is
// shown as "(document)".
class ConfigError : public std::runtime_error {
 public:
  ConfigError(std::string pointer, std::string rule, std::string value = {});

  const std::string& pointer() const noexcept { return pointer_; }  // JSON pointer, "/axes/1/jerk"
  const std::string& rule() const noexcept { return rule_; }        // "must be > 0"
  const std::string& value() const noexcept { return value_; }      // "-5", may be empty

  // The same error with `prefix` put in front of the pointer: validate() reports pointers
  // relative to the struct; the JSON reader places them in the document ("/axes/1" + "/jerk").
  ConfigError prefixed(std::string_view prefix) const;

 private:
  std::string pointer_;
  std::string rule_;
  std::string value_;
};

// Checks every rule of axis_config.hpp; throws ConfigError with a pointer relative to the
// struct ("/cycle_time", "/acceleration").
void validate(const KernelConfig& config);
void validate(const AxisConfig& config);
// The rules between the two-speed fields, which validate() checks for a kTwoSpeed axis: per
// direction braking distance <= creep distance; creep_velocity <= rapid_velocity; with looping
// enabled |looping_distance| > braking_distance_positive + braking_distance_negative (so that the
// return leg is always longer than its braking distance).
void validate_two_speed(const AxisConfig& config);

// A whole kernel set-up as read from JSON.
struct KernelSetup {
  KernelConfig kernel;
  std::vector<AxisConfig> axes;

  bool operator==(const KernelSetup&) const = default;
};

// Reads and validates a document {"kernel": {...}, "axes": [...]}. "kernel" is optional (all
// defaults), "axes" is required (it may be empty), each axis needs a "name", names are unique and
// explicitly given ids (non-zero) are unique. Absent keys keep their defaults; unknown keys,
// wrong JSON types and broken rules throw ConfigError with the pointer into `document`.
KernelSetup parse_kernel_setup(const nlohmann::json& document);
// The same from JSON text or a file; a syntax error (or a key repeated within one object) is a
// ConfigError too, with the parser's position in the rule.
KernelSetup parse_kernel_setup_text(std::string_view text);
KernelSetup parse_kernel_setup_file(const std::filesystem::path& path);

// Reads one struct from a JSON object (absent keys keep their defaults) and validates it.
// `pointer` is where `object` sits in its document; errors are reported below it.
KernelConfig parse_kernel_config(const nlohmann::json& object, std::string_view pointer = "");
AxisConfig parse_axis_config(const nlohmann::json& object, std::string_view pointer = "");

// Every field, with enums as their JSON names; parse(to_json(x)) == x.
nlohmann::json to_json(const KernelConfig& config);
nlohmann::json to_json(const AxisConfig& config);
nlohmann::json to_json(const KernelSetup& setup);

// JSON spelling of the enum values ("continuous", "first_order_lag").
std::string_view to_string(AxisKind kind);
std::string_view to_string(DriveModel model);
std::string_view to_string(ErrorPropagation mode);  // "instantaneous", "delayed"

// One row of the field reference (docs/configuration.md), taken from the visitor.
struct FieldDoc {
  std::string key;            // "max_velocity"
  std::string type;           // "number", "integer", "boolean", "string", "enum"
  std::string unit;           // "mm/s", or "" when dimensionless
  std::string default_value;  // as JSON: 2200, "continuous", true
  std::string range;          // "> 0", "[1, 4]", "\"ideal\", \"first_order_lag\""
  std::string meaning;
};
std::vector<FieldDoc> describe_kernel_fields();
std::vector<FieldDoc> describe_axis_fields();

}  // namespace nc
