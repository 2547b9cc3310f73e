// ConfigError, validation of KernelConfig / AxisConfig, and the field reference — all driven by
// visit_fields() (config_fields.hpp).
#include "nc_core/config.hpp"

#include <charconv>
#include <cmath>
#include <system_error>
#include <type_traits>

#include "config_text.hpp"

namespace nc {

namespace config_text {

std::string number(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

std::string range(const RealRule& rule) {
  const bool low = std::isfinite(rule.min);
  const bool high = std::isfinite(rule.max);
  if (!low && !high) return "finite";
  if (!high) return std::string(rule.min_exclusive ? "> " : ">= ") + number(rule.min);
  if (!low) return std::string(rule.max_exclusive ? "< " : "<= ") + number(rule.max);
  return std::string(rule.min_exclusive ? "(" : "[") + number(rule.min) + ", " + number(rule.max) +
         (rule.max_exclusive ? ")" : "]");
}

std::string range(const IntRule& rule) {
  const bool low = rule.min != INT_MIN;
  const bool high = rule.max != INT_MAX;
  if (!low && !high) return "any";
  if (!high) return std::string(">= ") + std::to_string(rule.min);
  if (!low) return std::string("<= ") + std::to_string(rule.max);
  return std::string("[") + std::to_string(rule.min) + ", " + std::to_string(rule.max) + "]";
}

std::string must(const RealRule& rule) {
  const std::string r = range(rule);
  return r.front() == '[' || r.front() == '(' ? std::string("must be in ") + r
                                              : std::string("must be ") + r;
}

std::string must(const IntRule& rule) {
  const std::string r = range(rule);
  return r.front() == '[' ? std::string("must be in ") + r : std::string("must be ") + r;
}

std::string shown(const nlohmann::json& value) {
  constexpr std::size_t kMaxShown = 40;
  std::string text = value.dump();
  if (text.size() > kMaxShown) text = text.substr(0, kMaxShown - 3) + "...";
  return text;
}

std::string shown(double value) {
  return number(value);
}

std::string escape_token(std::string_view key) {
  std::string out;
  out.reserve(key.size());
  for (const char ch : key) {
    if (ch == '~') {
      out += "~0";
    } else if (ch == '/') {
      out += "~1";
    } else {
      out += ch;
    }
  }
  return out;
}

std::string child(std::string_view pointer, std::string_view key) {
  std::string out(pointer);
  out += '/';
  out += escape_token(key);
  return out;
}

}  // namespace config_text

namespace {

std::string compose_what(const std::string& pointer, const std::string& rule,
                         const std::string& value) {
  std::string out = pointer.empty() ? std::string("(document)") : pointer;
  out += ": ";
  out += rule;
  if (!value.empty()) {
    out += " (got ";
    out += value;
    out += ')';
  }
  return out;
}

// Checks each field against the rule the visitor gives for it.
struct ValidateVisitor {
  void operator()(const FieldInfo& f, double value, const RealRule& rule) const {
    if (!std::isfinite(value)) {
      throw ConfigError(config_text::child("", f.key), "must be finite", config_text::shown(value));
    }
    if (!rule.allows(value)) {
      throw ConfigError(config_text::child("", f.key), config_text::must(rule),
                        config_text::shown(value));
    }
  }
  void operator()(const FieldInfo& f, int value, const IntRule& rule) const {
    if (!rule.allows(value)) {
      throw ConfigError(config_text::child("", f.key), config_text::must(rule),
                        std::to_string(value));
    }
  }
  void operator()(const FieldInfo& f, const std::string& value, const TextRule& rule) const {
    if (rule.non_empty && value.empty()) {
      throw ConfigError(config_text::child("", f.key), "must not be empty");
    }
  }
  void operator()(const FieldInfo&, bool, const FlagRule&) const {}
  template <class E>
  void operator()(const FieldInfo& f, E value, const EnumRule<E>& rule) const {
    // Only reachable from code, with a value cast from an integer.
    if (rule.find_name(value) == nullptr) {
      throw ConfigError(config_text::child("", f.key), config_text::must(rule),
                        std::to_string(static_cast<std::underlying_type_t<E>>(value)));
    }
  }
};

// Builds the reference rows; the defaults are the values of a default-constructed struct.
struct DescribeVisitor {
  std::vector<FieldDoc>& rows;

  void add(const FieldInfo& f, std::string type, std::string default_value, std::string range) {
    rows.push_back(FieldDoc{std::string(f.key), std::move(type), std::string(f.unit),
                            std::move(default_value), std::move(range), std::string(f.meaning)});
  }
  void operator()(const FieldInfo& f, double value, const RealRule& rule) {
    add(f, "number", nlohmann::json(value).dump(), config_text::range(rule));
  }
  void operator()(const FieldInfo& f, int value, const IntRule& rule) {
    add(f, "integer", std::to_string(value), config_text::range(rule));
  }
  void operator()(const FieldInfo& f, const std::string& value, const TextRule& rule) {
    add(f, "string", nlohmann::json(value).dump(), rule.non_empty ? "not empty" : "any");
  }
  void operator()(const FieldInfo& f, bool value, const FlagRule&) {
    add(f, "boolean", value ? "true" : "false", "true, false");
  }
  template <class E>
  void operator()(const FieldInfo& f, E value, const EnumRule<E>& rule) {
    const std::string_view* name = rule.find_name(value);
    add(f, "string", name != nullptr ? '"' + std::string(*name) + '"' : std::string("?"),
        config_text::range(rule));
  }
};

template <class E>
std::string_view enum_to_string(std::span<const EnumName<E>> names, E value) {
  for (const auto& n : names) {
    if (n.value == value) return n.name;
  }
  return "?";
}

}  // namespace

ConfigError::ConfigError(std::string pointer, std::string rule, std::string value)
    : std::runtime_error(compose_what(pointer, rule, value)),
      pointer_(std::move(pointer)),
      rule_(std::move(rule)),
      value_(std::move(value)) {}

ConfigError ConfigError::prefixed(std::string_view prefix) const {
  return ConfigError(std::string(prefix) + pointer_, rule_, value_);
}

void validate(const KernelConfig& config) {
  visit_fields(config, ValidateVisitor{});
}

void validate(const AxisConfig& config) {
  visit_fields(config, ValidateVisitor{});
  // Seed 000 §2.1 note 5: with both limits active the allowed range must not be empty.
  if (config.sw_limit_min_enabled && config.sw_limit_max_enabled &&
      !(config.sw_limit_min < config.sw_limit_max)) {
    throw ConfigError("/sw_limit_min",
                      std::string("must be < sw_limit_max (") +
                          config_text::number(config.sw_limit_max) +
                          ") when both software limits are enabled",
                      config_text::number(config.sw_limit_min));
  }
  // Seed 002 §4: P-AXIS-00460 changes how the P-AXIS-00436 forward mapping computes.
  if (config.recalc_input_position_absolute && !config.recalc_link_main_input_position) {
    throw ConfigError("/recalc_input_position_absolute",
                      "needs recalc_link_main_input_position (P-AXIS-00436)", "true");
  }
  if (config.kind == AxisKind::kTwoSpeed) {
    validate_two_speed(config);
  }
}

std::string_view to_string(AxisKind kind) {
  return enum_to_string<AxisKind>(kAxisKindNames, kind);
}

std::string_view to_string(DriveModel model) {
  return enum_to_string<DriveModel>(kDriveModelNames, model);
}

std::string_view to_string(ErrorPropagation mode) {
  return enum_to_string<ErrorPropagation>(kErrorPropagationNames, mode);
}

std::vector<FieldDoc> describe_kernel_fields() {
  std::vector<FieldDoc> rows;
  const KernelConfig defaults{};
  visit_fields(defaults, DescribeVisitor{rows});
  return rows;
}

std::vector<FieldDoc> describe_axis_fields() {
  std::vector<FieldDoc> rows;
  const AxisConfig defaults{};
  visit_fields(defaults, DescribeVisitor{rows});
  return rows;
}

}  // namespace nc
