// The "cnc" object of an axis: CNC parameters in native units mapped onto AxisConfig (SPEC D6).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "config_text.hpp"
#include "nc_core/cnc_parameters.hpp"
#include "nc_core/config.hpp"

namespace nc::cnc {

namespace {

using config_text::child;
using config_text::shown;
using nlohmann::json;

constexpr std::string_view kEmergencyDeceleration = "P-AXIS-00003";
constexpr std::string_view kSwLimitNeg = "P-AXIS-00177";
constexpr std::string_view kSwLimitPos = "P-AXIS-00178";
constexpr std::string_view kForwardMapping = "P-AXIS-00436";
constexpr std::string_view kForwardMappingAbsolute = "P-AXIS-00460";

// An integer parameter in [lo, hi]; `rule` is the text of the range for the error.
int64_t integer(const json& cnc, std::string_view key, std::string_view pointer, int64_t lo,
                int64_t hi, const std::string& rule) {
  const json& value = cnc.at(std::string(key));
  const std::string where = child(pointer, key);
  if (!value.is_number_integer()) throw ConfigError(where, "must be an integer", shown(value));
  if (value.is_number_unsigned() && value.get<uint64_t>() > static_cast<uint64_t>(hi)) {
    throw ConfigError(where, rule, shown(value));
  }
  const int64_t v = value.get<int64_t>();
  if (v < lo || v > hi) throw ConfigError(where, rule, shown(value));
  return v;
}

// The same setting may come as a field or as a CNC parameter, not both.
void refuse_both(const json& axis, std::string_view field, std::string_view key,
                 std::string_view pointer) {
  if (axis.contains(std::string(field))) {
    throw ConfigError(child(pointer, key), std::string("conflicts with \"") + std::string(field) +
                                               "\" given in the same axis; give the setting once");
  }
}

}  // namespace

int32_t length_to_native(double length) noexcept {
  const double units = std::round(length / kLengthUnit);
  if (!(units < static_cast<double>(std::numeric_limits<int32_t>::max()))) {
    return std::numeric_limits<int32_t>::max();
  }
  if (!(units > static_cast<double>(std::numeric_limits<int32_t>::min()))) {
    return std::numeric_limits<int32_t>::min();
  }
  return static_cast<int32_t>(units);
}

void apply_cnc_parameters(const json& cnc, const json& axis, std::string_view pointer,
                          AxisConfig& config) {
  const std::string at = child(pointer, "cnc");
  if (!cnc.is_object()) throw ConfigError(at, "must be an object", shown(cnc));
  for (const auto& item : cnc.items()) {
    const std::string& key = item.key();
    if (key != kEmergencyDeceleration && key != kSwLimitNeg && key != kSwLimitPos &&
        key != kForwardMapping && key != kForwardMappingAbsolute) {
      throw ConfigError(child(at, key),
                        "unknown CNC parameter (known: P-AXIS-00003, P-AXIS-00177, P-AXIS-00178, "
                        "P-AXIS-00436, P-AXIS-00460)");
    }
  }
  // SGN32, exclusive of its extremes (seed: MIN(SGN32) < swe_neg < swe_pos < MAX(SGN32)).
  constexpr int64_t kMin = std::numeric_limits<int32_t>::min();
  constexpr int64_t kMax = std::numeric_limits<int32_t>::max();
  const std::string limit_rule = "must be an integer in (" + std::to_string(kMin) + ", " +
                                 std::to_string(kMax) + ") in 0.1 µm (0.0001°)";
  const bool has_neg = cnc.contains(std::string(kSwLimitNeg));
  const bool has_pos = cnc.contains(std::string(kSwLimitPos));
  const int64_t neg = has_neg ? integer(cnc, kSwLimitNeg, at, kMin + 1, kMax - 1, limit_rule) : 0;
  const int64_t pos = has_pos ? integer(cnc, kSwLimitPos, at, kMin + 1, kMax - 1, limit_rule) : 0;
  if (has_neg && has_pos && !(neg < pos)) {
    throw ConfigError(child(at, kSwLimitNeg),
                      "must be < P-AXIS-00178 (" + std::to_string(pos) + ")", std::to_string(neg));
  }
  if (has_neg) {
    refuse_both(axis, "sw_limit_min", kSwLimitNeg, at);
    refuse_both(axis, "sw_limit_min_enabled", kSwLimitNeg, at);
    config.sw_limit_min = length_from_native(static_cast<int32_t>(neg));
    config.sw_limit_min_enabled = true;  // the CNC always checks its limits (once referenced)
  }
  if (has_pos) {
    refuse_both(axis, "sw_limit_max", kSwLimitPos, at);
    refuse_both(axis, "sw_limit_max_enabled", kSwLimitPos, at);
    config.sw_limit_max = length_from_native(static_cast<int32_t>(pos));
    config.sw_limit_max_enabled = true;
  }
  if (cnc.contains(std::string(kEmergencyDeceleration))) {
    refuse_both(axis, "emergency_deceleration", kEmergencyDeceleration, at);
    // Seed: 1 <= a_emergency <= 2 * P-AXIS-00008, default 0 = P-AXIS-00008.
    const auto top =
        static_cast<int64_t>(std::min(std::floor(2.0 * config.acceleration),
                                      static_cast<double>(std::numeric_limits<uint32_t>::max())));
    const int64_t a =
        integer(cnc, kEmergencyDeceleration, at, 0, top,
                "must be 0 (= acceleration) or an integer in [1, 2 × acceleration = " +
                    std::to_string(top) + "] mm/s²");
    config.emergency_deceleration =
        emergency_deceleration_from_native(static_cast<uint32_t>(a), config.acceleration);
  }
  if (cnc.contains(std::string(kForwardMapping))) {
    refuse_both(axis, "recalc_link_main_input_position", kForwardMapping, at);
    config.recalc_link_main_input_position =
        integer(cnc, kForwardMapping, at, 0, 1, "must be 0 or 1") == 1;
  }
  if (cnc.contains(std::string(kForwardMappingAbsolute))) {
    refuse_both(axis, "recalc_input_position_absolute", kForwardMappingAbsolute, at);
    config.recalc_input_position_absolute =
        integer(cnc, kForwardMappingAbsolute, at, 0, 1, "must be 0 or 1") == 1;
  }
  try {
    validate(config);
  } catch (const ConfigError& e) {
    throw e.prefixed(pointer);
  }
}

}  // namespace nc::cnc
