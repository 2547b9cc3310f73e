// External setpoint generation of one axis (seed 000 §2.6, seed 001, SPEC B8): set values fed by
// the PLC every cycle through PlcToNc.ExtSetPos / ExtSetVelo / ExtSetAcc / ExtSetDirection.
//
// A packet is taken only while ExtSetDirection is -1 or +1. Two exceptions, both from the seed:
// in the first NC cycle whose direction is no longer ±1, and in the first cycle after disabling,
// the ExtSetPos then in the interface is still taken ("exactly one further cycle"); from the next
// cycle on the set position is held (velocity and acceleration 0). A non-finite value in a packet
// that would be taken is not taken: take() reports it and the axis raises an error; so is a
// finite packet out of range (carried velocity above the axis's max velocity, |p| or |a| above the
// planner's 1e12), which would overflow the controller and the drive model.
//
// Absolute start type: state() is the axis's set state. Relative: state() is an offset added to
// the internal generator's set values. Value type; cycle functions only (noexcept, no allocation).
#pragma once

#include <cstdint>

#include "nc_core/profile.hpp"
#include "plc_interface/axis_ref.hpp"

namespace nc::detail {

class ExternalSetpoint {
 public:
  // fb::E_PositionType values (seed 000 §2.6 "axis start types absolute (1) or relative (2)").
  enum class Type : int32_t {
    kNone = 0,
    kAbsolute = plc::POSITIONTYPE_ABSOLUTE,
    kRelative = plc::POSITIONTYPE_RELATIVE,
  };

  struct Step {
    KinematicState state;     // the external set state (absolute) or offset (relative)
    bool not_finite = false;  // a packet to be taken held NaN or inf: not taken
    bool too_large = false;   // a packet to be taken was out of range: not taken
    bool finished = false;    // the cycle after the disable has been taken: generation is over
  };

  // Switches on with `start` as the state held until the first packet is taken (absolute: the
  // set state at the enable; relative: a zero offset). Enabling again with the same type keeps
  // the state; only the target changes. `delay` (AxisConfig::ext_setpoint_delay, seed 000 §2.6
  // "Optimization options"): a taken packet (p, v, a) counts as p + v d + a d²/2, v + a d, a —
  // set values carried ahead over the transport dead time. `max_velocity`: the axis's; a packet
  // whose carried velocity is above it is not taken.
  void enable(Type type, const KinematicState& start, double target, double delay,
              double max_velocity) noexcept;
  // Off after one more cycle, which still takes ExtSetPos (seed 000 §2.6 "Disabling").
  void disable() noexcept;
  // Off at once (axis error, reset, controller enable gone, stop): the state is held.
  void abort() noexcept;

  // One NC cycle of `cycle_time`: reads the packet in `in`. A packet with NaN or inf is not
  // taken; the state then goes on for this cycle as its velocity and acceleration say, so that
  // the error ramp the axis starts from there has no jump.
  Step take(const plc::PLCTONC_AXIS_REF& in, double cycle_time) noexcept;

  bool enabled() const noexcept { return enabled_; }
  // Enabled, or in its one more cycle after the disable.
  bool taking() const noexcept { return enabled_ || final_cycle_; }
  // The last packet taken had direction -1 or +1: the fed motion is under way.
  bool moving() const noexcept { return enabled_ && was_moving_; }
  Type type() const noexcept { return type_; }
  double target() const noexcept { return target_; }
  const KinematicState& state() const noexcept { return state_; }

 private:
  // What every cycle reads (enabled(), taking(), moving()) first.
  bool enabled_ = false;
  bool final_cycle_ = false;
  bool was_moving_ = false;  // the previous cycle's direction was ±1
  Type type_ = Type::kNone;
  KinematicState state_{};
  double target_ = 0.0;
  double delay_ = 0.0;
  double max_velocity_ = 0.0;
};

}  // namespace nc::detail
