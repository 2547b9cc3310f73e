// Reflection of the configuration structs: one field visitor per struct.
//
// visit_fields() lists every field of KernelConfig / AxisConfig exactly once, with its JSON key,
// unit, meaning and the rule its value must keep. Reading JSON, writing JSON, validation and the
// field reference in docs/configuration.md are all driven by these two lists, so a field added
// here is read, written, checked and documented everywhere at once (STYLE.md: one reflection
// visitor per configuration struct). Pure compile-time data: no allocation, no exceptions.
#pragma once

#include <climits>
#include <concepts>
#include <limits>
#include <span>
#include <string_view>
#include <type_traits>

#include "nc_core/axis_config.hpp"

namespace nc {

// What the visitor learns about a field besides its value.
struct FieldInfo {
  std::string_view key;      // JSON key = C++ field name
  std::string_view unit;     // "" when dimensionless
  std::string_view meaning;  // one line for the docs
};

// A floating-point field is always finite; it may also be bounded on either side.
struct RealRule {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;  // true: value > min; false: value >= min
  bool max_exclusive = false;  // true: value < max; false: value <= max

  constexpr bool allows(double v) const {
    // Written so that NaN fails every comparison and is refused.
    const bool above = min_exclusive ? v > min : v >= min;
    const bool below = max_exclusive ? v < max : v <= max;
    return above && below && v - v == 0.0;  // v - v is NaN for ±inf and NaN
  }
};

inline constexpr RealRule kAnyFinite{};
inline constexpr RealRule kPositive{0.0, std::numeric_limits<double>::infinity(), true, false};
inline constexpr RealRule kNonNegative{0.0, std::numeric_limits<double>::infinity(), false, false};
constexpr RealRule closed_range(double lo, double hi) {
  return RealRule{lo, hi, false, false};
}

struct IntRule {
  int min = INT_MIN;
  int max = INT_MAX;
  constexpr bool allows(long long v) const { return v >= min && v <= max; }
};

struct TextRule {
  bool non_empty = false;
};

struct FlagRule {};

template <class E>
struct EnumName {
  E value;
  std::string_view name;  // spelling in JSON
};

template <class E>
struct EnumRule {
  std::span<const EnumName<E>> names;

  constexpr const std::string_view* find_name(E v) const {
    for (const auto& n : names) {
      if (n.value == v) return &n.name;
    }
    return nullptr;
  }
};

inline constexpr EnumName<AxisKind> kAxisKindNames[] = {
    {AxisKind::kContinuous, "continuous"},
    {AxisKind::kEncoder, "encoder"},
    {AxisKind::kTwoSpeed, "two_speed"},
};
inline constexpr EnumName<DriveModel> kDriveModelNames[] = {
    {DriveModel::kIdeal, "ideal"},
    {DriveModel::kFirstOrderLag, "first_order_lag"},
};
inline constexpr EnumName<ErrorPropagation> kErrorPropagationNames[] = {
    {ErrorPropagation::kInstantaneous, "instantaneous"},
    {ErrorPropagation::kDelayed, "delayed"},
};

// The visitor is called as visitor(const FieldInfo&, Field& value, const Rule& rule) once per
// field, in declaration order. Config may be const (writing, validating) or not (reading).
template <class Config, class Visitor>
requires std::same_as<std::remove_const_t<Config>, KernelConfig>
void visit_fields(Config& c, Visitor&& v) {
  // A cycle below 50 µs is beyond a PC-based NC; above 10 ms the controller is too slow to be
  // useful (TwinCAT's SAF task default is 2 ms).
  v(FieldInfo{"cycle_time", "s", "NC (SAF) cycle time"}, c.cycle_time, closed_range(50e-6, 10e-3));
}

template <class Config, class Visitor>
requires std::same_as<std::remove_const_t<Config>, AxisConfig>
void visit_fields(Config& c, Visitor&& v) {
  v(FieldInfo{"name", "", "axis name, unique in a kernel; required"}, c.name, TextRule{true});
  v(FieldInfo{"id", "", "logical axis number (HLI ax_nr); 0 = assigned by the kernel"}, c.id,
    IntRule{0, INT_MAX});
  v(FieldInfo{"kind", "", "continuous (servo), encoder (set = actual) or two_speed (rapid/creep)"},
    c.kind, EnumRule<AxisKind>{kAxisKindNames});

  v(FieldInfo{"max_velocity", "mm/s", "maximum velocity; a faster start is refused"},
    c.max_velocity, kPositive);
  v(FieldInfo{"ref_velocity", "mm/s", "reference velocity (100 % drive output)"}, c.ref_velocity,
    kPositive);
  v(FieldInfo{"acceleration", "mm/s²", "default A+ (seed 000 §2.1)"}, c.acceleration, kPositive);
  v(FieldInfo{"deceleration", "mm/s²", "default A- (seed 000 §2.1)"}, c.deceleration, kPositive);
  v(FieldInfo{"jerk", "mm/s³", "default J (seed 000 §2.1)"}, c.jerk, kPositive);
  v(FieldInfo{"emergency_deceleration", "mm/s²", "deceleration of the stop on an axis error"},
    c.emergency_deceleration, kPositive);
  v(FieldInfo{"emergency_jerk", "mm/s³", "jerk of the stop on an axis error"}, c.emergency_jerk,
    kPositive);

  v(FieldInfo{"sw_limit_min_enabled", "", "monitor the minimum software limit"},
    c.sw_limit_min_enabled, FlagRule{});
  v(FieldInfo{"sw_limit_max_enabled", "", "monitor the maximum software limit"},
    c.sw_limit_max_enabled, FlagRule{});
  v(FieldInfo{"sw_limit_min", "mm", "minimum software limit; < sw_limit_max when both enabled"},
    c.sw_limit_min, kAnyFinite);
  v(FieldInfo{"sw_limit_max", "mm", "maximum software limit"}, c.sw_limit_max, kAnyFinite);

  v(FieldInfo{"homed_at_start", "",
              "referenced from the start (absolute encoder); false: must home (MC_Home)"},
    c.homed_at_start, FlagRule{});
  v(FieldInfo{"homing_cam_search_positive", "", "homing: search the cam in the + direction"},
    c.homing_cam_search_positive, FlagRule{});
  v(FieldInfo{"homing_sync_search_positive", "",
              "homing: leave the cam and search the sync pulse in the + direction"},
    c.homing_sync_search_positive, FlagRule{});
  v(FieldInfo{"homing_velocity_to_cam", "mm/s", "homing: velocity towards the cam"},
    c.homing_velocity_to_cam, kPositive);
  v(FieldInfo{"homing_velocity_off_cam", "mm/s", "homing: velocity off the cam"},
    c.homing_velocity_off_cam, kPositive);
  v(FieldInfo{"homing_sync_pulse_distance", "mm",
              "homing: encoder zero pulse every this many mm; 0 = none (cam edge)"},
    c.homing_sync_pulse_distance, kNonNegative);
  v(FieldInfo{"homing_search_distance", "mm",
              "homing: most travel to the cam, and from the cam to the reference"},
    c.homing_search_distance, kPositive);
  v(FieldInfo{"homing_reference_position", "mm",
              "homing: position of the reference when MC_Home.Position is the default"},
    c.homing_reference_position, kAnyFinite);
  v(FieldInfo{"homing_cam_position", "mm", "simulated reference cam: where it begins (raw)"},
    c.homing_cam_position, kAnyFinite);
  v(FieldInfo{"homing_cam_width", "mm", "simulated reference cam: its length; 0 = no cam"},
    c.homing_cam_width, kNonNegative);

  v(FieldInfo{"modulo_factor", "mm", "period of modulo positioning (360 for a rotary axis)"},
    c.modulo_factor, kPositive);
  v(FieldInfo{"override_type", "", "override type of seed 000 §2.2"}, c.override_type,
    IntRule{1, 4});

  // At most 100 1/s: Kv · T <= 1 for every NC cycle T <= 10 ms (Kv · T >= 2 is unstable).
  v(FieldInfo{"position_kv", "1/s", "position controller gain Kv"}, c.position_kv,
    closed_range(0.0, 100.0));
  v(FieldInfo{"velocity_feed_forward", "", "fraction of the set velocity fed forward"},
    c.velocity_feed_forward, closed_range(0.0, 1.0));

  v(FieldInfo{"drive_model", "", "ideal or first_order_lag (with time constant and dead time)"},
    c.drive_model, EnumRule<DriveModel>{kDriveModelNames});
  // At most 100 s: a lag of 100 s already hides the drive for minutes; 1e308 overflowed the
  // drive model's step (fuzz finding C2).
  v(FieldInfo{"drive_time_constant", "s", "first-order lag of the drive; 0 = none"},
    c.drive_time_constant, closed_range(0.0, 100.0));
  v(FieldInfo{"drive_dead_time", "s", "drive dead time, rounded to whole NC cycles"},
    c.drive_dead_time, closed_range(0.0, 1.0));
  v(FieldInfo{"drive_max_velocity", "mm/s", "drive saturation velocity; 0 = no limit"},
    c.drive_max_velocity, kNonNegative);
  v(FieldInfo{"encoder_increment", "mm", "actual-position resolution; 0 = exact"},
    c.encoder_increment, kNonNegative);

  v(FieldInfo{"following_error_enabled", "", "monitor the following error (lag)"},
    c.following_error_enabled, FlagRule{});
  v(FieldInfo{"following_error_limit", "mm", "largest allowed following error"},
    c.following_error_limit, kPositive);
  v(FieldInfo{"following_error_filter_time", "s",
              "error only after the limit is exceeded this long"},
    c.following_error_filter_time, kNonNegative);

  v(FieldInfo{"target_window_enabled", "", "monitor the target window (InTargetPosition)"},
    c.target_window_enabled, FlagRule{});
  v(FieldInfo{"target_window", "mm", "distance actual to target allowed for InTargetPosition"},
    c.target_window, kPositive);
  v(FieldInfo{"target_window_time", "s", "time inside the target window before InTargetPosition"},
    c.target_window_time, kNonNegative);

  v(FieldInfo{"position_range_enabled", "", "monitor the position range (InPositionArea)"},
    c.position_range_enabled, FlagRule{});
  v(FieldInfo{"position_range_window", "mm",
              "distance actual to target allowed for InPositionArea"},
    c.position_range_window, kPositive);

  v(FieldInfo{"standstill_window", "mm/s", "actual speed below this counts as not moving"},
    c.standstill_window, kPositive);

  v(FieldInfo{"ext_setpoint_delay", "s",
              "delay time between velocity and position: external packets carried ahead by it"},
    c.ext_setpoint_delay, closed_range(0.0, 1.0));

  v(FieldInfo{"error_propagation_mode", "",
              "instantaneous: an error stops the whole master/slave group at once; delayed: "
              "only the faulty axis, the group after the delay"},
    c.error_propagation_mode, EnumRule<ErrorPropagation>{kErrorPropagationNames});
  v(FieldInfo{"error_propagation_delay", "s",
              "delayed: time from the error to the group reaction (whole NC cycles)"},
    c.error_propagation_delay, kNonNegative);
  v(FieldInfo{"couple_slave_to_actual_values", "",
              "slaves follow this axis's actual values when it has an error (delayed) or, as "
              "head master, has no controller enable"},
    c.couple_slave_to_actual_values, FlagRule{});
  v(FieldInfo{"actual_value_velocity_window", "mm/s",
              "actual-value coupling: filtered speed below this counts as standstill"},
    c.actual_value_velocity_window, kPositive);
  v(FieldInfo{"actual_value_filter_time", "s",
              "actual-value coupling: time constant of the actual-position filter"},
    c.actual_value_filter_time, kPositive);

  v(FieldInfo{"recalc_link_main_input_position", "",
              "P-AXIS-00436: command-position request maps the drive position forward"},
    c.recalc_link_main_input_position, FlagRule{});
  v(FieldInfo{"recalc_input_position_absolute", "",
              "P-AXIS-00460: forward mapping as if coupled at position 0; needs P-AXIS-00436"},
    c.recalc_input_position_absolute, FlagRule{});

  // Two-speed axis (SPEC E, seed 004); the rules between these fields: validate_two_speed().
  v(FieldInfo{"creep_distance_positive", "mm",
              "two-speed: rapid off this far before the target, +"},
    c.creep_distance_positive, kNonNegative);
  v(FieldInfo{"creep_distance_negative", "mm",
              "two-speed: rapid off this far before the target, -"},
    c.creep_distance_negative, kNonNegative);
  v(FieldInfo{"braking_distance_positive", "mm",
              "two-speed: creep off this far before the target, +"},
    c.braking_distance_positive, kNonNegative);
  v(FieldInfo{"braking_distance_negative", "mm",
              "two-speed: creep off this far before the target, -"},
    c.braking_distance_negative, kNonNegative);
  v(FieldInfo{"brake_incidence_delay_positive", "s", "two-speed: creep off to brake on, +"},
    c.brake_incidence_delay_positive, kNonNegative);
  v(FieldInfo{"brake_incidence_delay_negative", "s", "two-speed: creep off to brake on, -"},
    c.brake_incidence_delay_negative, kNonNegative);
  v(FieldInfo{"rapid_to_creep_delay", "s", "two-speed: rapid off to creep on"},
    c.rapid_to_creep_delay, kNonNegative);
  v(FieldInfo{"creep_distance_stop", "mm", "two-speed: creep travel after a stop is called"},
    c.creep_distance_stop, kNonNegative);
  v(FieldInfo{"brake_release_delay", "s", "two-speed: brake off to travel on at a start"},
    c.brake_release_delay, kNonNegative);
  v(FieldInfo{"looping_distance_enabled", "", "two-speed: approach every target from one side"},
    c.looping_distance_enabled, FlagRule{});
  v(FieldInfo{"looping_distance", "mm", "two-speed: overshoot; > 0 approach from above, < 0 below"},
    c.looping_distance, kAnyFinite);
  v(FieldInfo{"rapid_velocity", "mm/s", "two-speed plant: rapid motor speed"}, c.rapid_velocity,
    kPositive);
  v(FieldInfo{"creep_velocity", "mm/s", "two-speed plant: creep motor speed, <= rapid_velocity"},
    c.creep_velocity, kPositive);
  v(FieldInfo{"two_speed_ramp_time", "s", "two-speed plant: time from 0 to rapid_velocity"},
    c.two_speed_ramp_time, kNonNegative);
}

}  // namespace nc
