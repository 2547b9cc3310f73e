// Configuration of the NC kernel and of its axes: plain data with defaults.
//
// Every field has a default, a unit and a range (written beside it). A configuration is
// validated once, when an axis is added (Kernel::add_axis) or a JSON document is read
// (Kernel::from_json): set-up functions, which may allocate and throw nc::ConfigError.
// Working state lives in the kernel, never here.
#pragma once

#include <string>

namespace nc {

struct KernelConfig {
  double cycle_time = 0.001;  // s, NC (SAF) cycle, 50e-6 … 10e-3

  bool operator==(const KernelConfig&) const = default;
};

enum class AxisKind {
  kContinuous,  // servo axis: position controller + drive model + encoder
  kEncoder,     // encoder / virtual axis: set = actual, no controller, no compensation
  kTwoSpeed,    // two-speed (rapid/creep) discrete axis (SPEC E, seed 004)
};

enum class DriveModel {
  kIdeal,          // actual velocity = commanded velocity
  kFirstOrderLag,  // first-order lag (drive_time_constant) plus dead time (drive_dead_time)
};

// What an error of a coupled axis does to its master/slave group (SPEC C7, seed 000 §3.1).
enum class ErrorPropagation {
  kInstantaneous,  // the whole group stops at once
  kDelayed,        // only the faulty axis at once; the group after error_propagation_delay
};

// A new field also needs its line in visit_fields() (config_fields.hpp): that one line makes it
// readable from JSON, written to JSON, validated and documented.
struct AxisConfig {
  bool operator==(const AxisConfig&) const = default;  // compares every field, present and future

  std::string name;  // required, unique in a kernel, not empty
  int id = 0;        // logical axis number (HLI ax_nr); 0 = assigned by the kernel (index + 1)
  AxisKind kind = AxisKind::kContinuous;

  // Dynamics (seed 000 §2.1). Units mm, s.
  double max_velocity = 2200.0;  // mm/s, > 0; a start above it is refused (0x4221)
  double ref_velocity = 2200.0;  // mm/s, > 0; reference (100 % drive output); above: refused
  double acceleration = 5000.0;  // A+, mm/s², > 0
  double deceleration = 5000.0;  // A-, mm/s², > 0
  double jerk = 50000.0;         // J, mm/s³, > 0
  double emergency_deceleration = 10000.0;  // mm/s², > 0; axis error ramp
  double emergency_jerk = 100000.0;         // mm/s³, > 0

  // Software limit switches (seed 000 §2.1 notes 4, 5).
  bool sw_limit_min_enabled = false;
  bool sw_limit_max_enabled = false;
  double sw_limit_min = -100000.0;  // mm; < sw_limit_max when both are enabled
  double sw_limit_max = 100000.0;   // mm

  // Homing (SPEC F, MC_Home; docs/behaviour.md "Homing"). true: the axis is referenced from the
  // start (an absolute encoder); false: it must home first, and until it has, its software
  // limits are not monitored.
  bool homed_at_start = true;
  // MC_DefaultHoming, the NC's sequence (docs/behaviour.md "Homing"): towards the cam, off it,
  // then the sync pulse (the encoder's zero pulse) or, with no sync pulse, the cam edge.
  bool homing_cam_search_positive = true;    // direction towards the reference cam
  bool homing_sync_search_positive = false;  // direction off the cam and to the sync pulse
  double homing_velocity_to_cam = 100.0;     // mm/s, > 0; above max/ref velocity: MC_Home refused
  double homing_velocity_off_cam = 10.0;     // mm/s, > 0; likewise
  double homing_sync_pulse_distance = 5.0;   // mm, >= 0: a zero pulse every this many mm of the
                                             // raw encoder (0 = none: the cam edge is used)
  double homing_search_distance = 10000.0;   // mm, > 0: most travel to the cam, and after it
  double homing_reference_position = 0.0;    // mm: MC_Home.Position = DEFAULT_HOME_POSITION
  // The simulated reference cam (a digital input, Kernel::reference_cam): on while the raw
  // encoder position lies in [position, position + width]; width 0 = no cam.
  double homing_cam_position = 100.0;  // mm
  double homing_cam_width = 10.0;      // mm, >= 0

  double modulo_factor = 360.0;  // mm or °, > 0
  int override_type = 3;         // 1 … 4, seed 000 §2.2

  // Position controller: v_cmd = feed_forward · v_set + kv · (p_set - p_act).
  double position_kv = 1.0;            // 1/s (mm/s per mm), 0 … 100
  double velocity_feed_forward = 1.0;  // 0 … 1 (fraction of the set velocity)

  // Drive model and encoder.
  DriveModel drive_model = DriveModel::kIdeal;
  double drive_time_constant = 0.0;  // s, >= 0 (first-order lag; 0 = none)
  double drive_dead_time = 0.0;      // s, >= 0, at most 1 s (rounded to whole NC cycles)
  double drive_max_velocity = 0.0;   // mm/s, >= 0; the drive saturates here (0 = no limit)
  double encoder_increment = 1e-4;   // mm, >= 0; actual position resolution (0 = exact)

  // Following-error (lag) monitoring (A4).
  bool following_error_enabled = true;
  double following_error_limit = 5.0;         // mm, > 0
  double following_error_filter_time = 0.02;  // s, >= 0: error only after this long above

  // Target position window: InTargetPosition once |p_act - target| <= window for the time.
  bool target_window_enabled = true;
  double target_window = 2.0;        // mm, > 0
  double target_window_time = 0.02;  // s, >= 0

  // Position range window: InPositionArea while |p_act - target| <= window.
  bool position_range_enabled = true;
  double position_range_window = 5.0;  // mm, > 0

  double standstill_window = 1e-3;  // mm/s, > 0: |v_act| below it counts as not moving

  // External setpoint generation (seed 000 §2.6 "Optimization options"): "delay time between
  // velocity and position". Each taken packet is carried this far ahead along its velocity and
  // acceleration, compensating the transport dead time of the cyclic interface.
  double ext_setpoint_delay = 0.0;  // s, 0 … 1 (0 = none)

  // Error propagation in a master/slave group and coupling to actual values (SPEC C7, C8; seed
  // 000 §3.1; docs/behaviour.md "Error propagation and actual-value coupling"). Continuous and
  // encoder axes only; the faulty axis's own mode and delay decide.
  ErrorPropagation error_propagation_mode = ErrorPropagation::kInstantaneous;
  double error_propagation_delay = 0.0;  // s, >= 0, finite: DELAYED's wait for the group
  // The axis's slaves follow its filtered actual position while it has an error (DELAYED) or,
  // as head master, while its controller enable is off (pushed by hand).
  bool couple_slave_to_actual_values = false;
  double actual_value_velocity_window = 1.0;  // mm/s, > 0: filtered speed below it = standstill
  double actual_value_filter_time = 0.01;     // s, > 0: first-order filter of the actual value

  // HLI axis coupling, command-position request (SPEC D5, seed 002 §4). The CNC parameters in
  // their native units load from the JSON "cnc" object (docs/configuration.md).
  bool recalc_link_main_input_position = false;  // P-AXIS-00436: forward mapping of d
  bool recalc_input_position_absolute = false;   // P-AXIS-00460: ... as if coupled at 0 (needs 436)

  // Two-speed (rapid/creep) axis, kind kTwoSpeed (SPEC E, seed 004). Units mm, s; every value
  // >= 0 and finite; per direction: braking distance <= creep distance. Ignored by other kinds.
  double creep_distance_positive = 100.0;  // mm: rapid off this far before the target (or loop)
  double creep_distance_negative = 100.0;
  double braking_distance_positive = 5.0;  // mm: creep off this far before the target
  double braking_distance_negative = 5.0;
  double brake_incidence_delay_positive = 0.03;  // s: creep off → brake on
  double brake_incidence_delay_negative = 0.03;
  double rapid_to_creep_delay = 0.02;  // s: rapid off → creep on
  double creep_distance_stop = 20.0;   // mm: creep travel after a stop is called
  double brake_release_delay = 0.05;   // s: brake off → travel on
  bool looping_distance_enabled = false;
  double looping_distance = 30.0;  // mm, signed: > 0 approach from above, < 0 from below
  // The simulated two-speed plant (E6).
  double rapid_velocity = 500.0;     // mm/s, > 0
  double creep_velocity = 50.0;      // mm/s, > 0, <= rapid_velocity
  double two_speed_ramp_time = 0.1;  // s, >= 0: 0 → rapid_velocity (0 = a step)
};

}  // namespace nc
