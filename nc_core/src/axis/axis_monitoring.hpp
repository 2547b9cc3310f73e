// The watch over one servo axis (SPEC A4, A6; docs/behaviour.md "Axis state and enables"): the
// controller and feed enables in phase a (losing one while a command runs is an axis error), the
// following error, the software limits during motion and the target / position windows in phase
// e, and the end of a job (Done, velocity reached) once its set values and windows allow it.
//
// A view on one axis's AxisCore for one call (it owns nothing); defined in servo_axis.cpp next to
// the phases that call it. Cycle functions: noexcept, no allocation.
#pragma once

#include "axis/axis_core.hpp"

namespace nc::detail {

class AxisMonitoring : public AxisPart {
 public:
  using AxisPart::AxisPart;

  // `kAlone`: called in ServoPhases::cycle_alone(), where nothing is coupled and phase (c) gives no
  // drive command (servo_axis.cpp, ServoPhases).
  template <bool kAlone>
  void check_enables() noexcept;
  // Inlined into the monitor phase (only servo_axis.cpp calls them).
  // `kQuiet`: no homing and no external generation runs (ServoPhases).
  template <bool kAlone, bool kQuiet>
  [[gnu::always_inline]] inline void run_monitors() noexcept;
  template <bool kQuiet>
  [[gnu::always_inline]] inline void finish_job() noexcept;
};

}  // namespace nc::detail
