// The ConfigError a set-up gives, if any, for configuration tests that check the pointer and rule
// of a refusal: of a JSON kernel set-up, or of any set-up call (a callable, e.g. validate()).
#pragma once

#include <concepts>
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

template <class F>
requires std::invocable<F&> std::optional<nc::ConfigError> error_of(F&& f) {
  try {
    f();
  } catch (const nc::ConfigError& e) {
    return e;
  }
  return std::nullopt;
}

}  // namespace cfgtest
