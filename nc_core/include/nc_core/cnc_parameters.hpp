// CNC axis parameters in their native units (SPEC D6, seed 002 §4).
//
// An axis in JSON may carry a "cnc" object keyed by parameter ID, in the CNC's own units:
//   "P-AXIS-00003"  emergency deceleration, mm/s² (°/s²), 0 = the axis's acceleration
//   "P-AXIS-00177"  negative software limit, 0.1 µm (rotary axes 0.0001°)
//   "P-AXIS-00178"  positive software limit, same unit
//   "P-AXIS-00436"  forward mapping of the drive position, 0 / 1
//   "P-AXIS-00460"  forward mapping with absolute coordinates, 0 / 1
// They map onto AxisConfig fields (emergency_deceleration, sw_limit_min/max with their
// *_enabled flags, recalc_link_main_input_position, recalc_input_position_absolute); a value
// given both ways is an error. The converters are plain functions; apply_cnc_parameters is a
// set-up function that throws nc::ConfigError with the JSON pointer of the offending value.
#pragma once

#include <cstdint>
#include <string_view>

#include <nlohmann/json.hpp>

#include "nc_core/axis_config.hpp"

namespace nc::cnc {

// One native length unit: 0.1 µm = 1e-4 mm on a linear axis, 0.0001° on a rotary one.
inline constexpr double kLengthUnit = 1e-4;

constexpr double length_from_native(int32_t value) noexcept {
  return static_cast<double>(value) * kLengthUnit;
}
// The nearest native value (mm → 0.1 µm); saturates at the int32 range (NaN: the maximum).
int32_t length_to_native(double length) noexcept;

// P-AXIS-00003: 0 means the axis's maximum acceleration (seed: P-AXIS-00008, here
// AxisConfig::acceleration).
constexpr double emergency_deceleration_from_native(uint32_t value, double acceleration) noexcept {
  return value == 0 ? acceleration : static_cast<double>(value);
}

// Reads `cnc` (the "cnc" member of the axis object `axis`, which sits at `pointer` in its
// document) into `config`, whose other fields are already read; checks each parameter's native
// range and conflicts with the same setting given as a field, then validates the result. Throws
// nc::ConfigError.
void apply_cnc_parameters(const nlohmann::json& cnc, const nlohmann::json& axis,
                          std::string_view pointer, AxisConfig& config);

}  // namespace nc::cnc
