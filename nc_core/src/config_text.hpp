// Internal: the wording shared by validation, the JSON reader and the field reference, so that
// an error message and the documented range of a field always say the same thing.
#pragma once

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "nc_core/config_fields.hpp"

namespace nc::config_text {

// Shortest text that reads back to the same double ("0", "5e-05", "-2.5").
std::string number(double v);

// The allowed range as written in the docs: "> 0", ">= 0", "[5e-05, 0.01]", "finite".
std::string range(const RealRule& rule);
std::string range(const IntRule& rule);
template <class E>
std::string range(const EnumRule<E>& rule) {
  std::string out;
  for (const auto& n : rule.names) {
    if (!out.empty()) out += ", ";
    out += '"';
    out += n.name;
    out += '"';
  }
  return out;
}

// The rule as an error states it: "must be > 0", "must be in [1, 4]", "must be one of ...".
std::string must(const RealRule& rule);
std::string must(const IntRule& rule);
template <class E>
std::string must(const EnumRule<E>& rule) {
  std::string out = "must be one of ";
  bool first = true;
  for (const auto& n : rule.names) {
    if (!first) out += ", ";
    first = false;
    out += '"';
    out += n.name;
    out += '"';
  }
  return out;
}

// A value as shown after "got": JSON text, shortened; NaN and infinities by name.
std::string shown(const nlohmann::json& value);
std::string shown(double value);

// One JSON-pointer reference token: '~' → "~0", '/' → "~1" (RFC 6901).
std::string escape_token(std::string_view key);
std::string child(std::string_view pointer, std::string_view key);

}  // namespace nc::config_text
