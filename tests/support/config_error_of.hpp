// The ConfigError a JSON kernel set-up gives, if any, for configuration tests that check the
// pointer and rule of a refusal.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "nc_core/config.hpp"

namespace cfgtest {

inline std::optional<nc::ConfigError> error_of(const nlohmann::json& document) {
  try {
    (void)nc::parse_kernel_setup(document);
  } catch (const nc::ConfigError& e) {
    return e;
  }
  return std::nullopt;
}

}  // namespace cfgtest
