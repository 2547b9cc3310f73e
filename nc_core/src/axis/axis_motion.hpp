// The motion of one servo axis in a cycle: phase b, the basic source's set values (the PTP job,
// the absolute external generator, the slave link, the homing job or a hold;
// set_value_source.hpp) with the superposition stack on top; and phase d, position control and
// the drive (the controller enable off: the drive is off or pushed by hand, the set values follow
// the actual position).
//
// A view on one axis's AxisCore for one call (it owns nothing); defined in servo_axis.cpp next to
// the phases that call it. Cycle functions: noexcept, no allocation.
#pragma once

#include <span>

#include "axis/axis_core.hpp"
#include "nc_core/axis_snapshot.hpp"

namespace nc::detail {

class AxisMotion : public AxisPart {
 public:
  using AxisPart::AxisPart;

  // Phase b; `snapshots`: every axis's, a slave samples its master's. `kAlone` and `kQuiet` as in
  // AxisMonitoring (servo_axis.cpp, ServoPhases).
  template <bool kAlone, bool kQuiet>
  void generate_set_values(std::span<const AxisSnapshot> snapshots) noexcept;
  // Phase d.
  template <bool kAlone>
  void control_and_drive() noexcept;
};

}  // namespace nc::detail
