// Step f of the NC cycle for one axis: the NC→PLC image (SPEC A7; StateDWord bits and AxisState
// values as TwinCAT / Tc2_MC2 number them).
#include <cmath>

#include "axis/rounding.hpp"
#include "axis/servo_axis.hpp"

namespace nc::detail {

namespace {

double modulo(double p, double factor) noexcept {
  // Within the first period the formula gives p itself (floor 0; p + 0.0 as it turns -0.0 into
  // +0.0): no division. `factor` is finite and > 0 (AxisConfig validation).
  if (p >= 0.0 && p < factor) return p + 0.0;
  double m = p - factor * floor_exact(p / factor);
  if (m >= factor || m < 0.0) m = 0.0;  // rounding at the period edge
  return m;
}

}  // namespace

void ServoAxis::phase_publish(uint64_t cycle_counter) noexcept {
  if (two_speed_) return two_speed_->phase_publish(cycle_counter, static_cast<int32_t>(index_));
  using plc::AxisState;
  plc::NCTOPLC_AXIS_REF& out = channel_.ref().NcToPlc;
  const double actual = drive_.measured_position();
  const bool enabled = channel_.controller_enabled();
  const bool error = channel_.has_error();
  const JobKind kind = job_.kind();

  const KinematicState& command = drive_command();  // d: the set values phase (d) controls to
  out.SetPos = command.p;
  out.SetVelo = command.v;
  out.SetAcc = command.a;
  out.SetJerk = set_jerk_;
  out.ActPos = actual;
  out.ActVelo = drive_.velocity();
  out.ActAcc = drive_.acceleration();
  out.PosDiff = command.p - actual;
  out.ModuloActPos = modulo(actual, modulo_factor_);
  out.ModuloSetPos = modulo(command.p, modulo_factor_);
  out.TargetPos = target_;
  out.TargetVelo = target_velocity();
  out.CompensationDistance = stack_.compensation.done();  // travel-relative, as D
  out.CompensationLength = stack_.compensation.length();
  out.CompensationVelocityDiff = stack_.compensation.velocity_diff();
  channel_.publish(static_cast<int32_t>(index_));
  // A gear slave, or an HLI target (a list in force); a gear master, or an HLI source.
  const bool slave = slave_link_.coupled || slave_link_.detached || hli_target();
  const bool master = slave_count_ > 0 || hli_source();
  const plc::CoupleState couple =
      slave ? (master ? plc::CoupleState::kMasterAndSlave : plc::CoupleState::kSlave)
            : (master ? plc::CoupleState::kMaster : plc::CoupleState::kSingle);
  out.CoupleState = static_cast<uint32_t>(couple);
  out.GearRatio = slave_link_.coupled ? slave_link_.factor : 0.0;
  out.CycleCounter = static_cast<uint32_t>(cycle_counter);

  // Constant velocity: a velocity job at its level, or the cruise phase of a positioning.
  const double a_eps = 1e-9 * job_.goal.limits().acceleration + 1e-12;
  const bool constant_velocity = (kind == JobKind::kVelocity && job_.table.velocity_reached()) ||
                                 (kind == JobKind::kPosition && !job_.table.generation_ended() &&
                                  set_.v != 0.0 && std::abs(set_.a) <= a_eps && set_jerk_ == 0.0);

  // Bits or-ed in without branches (every bit starts at 0).
  uint32_t word = 0;
  const auto set_bit = [&word](plc::StateBit bit, bool value) noexcept {
    word |= static_cast<uint32_t>(value) << bit;
  };
  set_bit(plc::kStateOperational, enabled && !error);
  set_bit(plc::kStateHomed, homed_);
  set_bit(plc::kStateNotMoving, std::abs(drive_.velocity()) < standstill_window_);
  set_bit(plc::kStateInPositionArea, monitors_.in_position_area());
  set_bit(plc::kStateInTargetPosition, monitors_.in_target_position());
  set_bit(plc::kStateHasBeenStopped, has_been_stopped_);
  set_bit(plc::kStateHasJob, job_.active() || homing_.active());
  set_bit(plc::kStatePositiveDirection, set_.v > 0.0);
  set_bit(plc::kStateNegativeDirection, set_.v < 0.0);
  set_bit(plc::kStateHomingBusy, homing_.active());
  set_bit(plc::kStateConstantVelocity, constant_velocity);
  set_bit(plc::kStateCompensating, stack_.compensation.running());
  set_bit(plc::kStateExtSetPointGenEnabled, stack_.external.enabled());
  set_bit(plc::kStateCoupled, slave);
  set_bit(plc::kStateContinuousMotion, kind == JobKind::kVelocity);
  set_bit(plc::kStatePtpMode, true);
  set_bit(plc::kStateSoftLimitMinExceeded, monitors_.below_min(actual));
  set_bit(plc::kStateSoftLimitMaxExceeded, monitors_.above_max(actual));
  set_bit(plc::kStateMotionCommandsLocked, locked_);
  set_bit(plc::kStateErrorPropagationDelayed, propagation_.delayed());  // C7 DELAYED
  set_bit(plc::kStateError, error);
  out.StateDWord = word;

  // PLCopen state, in the priority of the PLCopen state diagram.
  AxisState state = AxisState::kStandstill;
  if (error) {
    state = AxisState::kErrorStop;
  } else if (!enabled) {
    state = AxisState::kDisabled;
  } else if (slave_link_.coupled || (hli_target() && kind == JobKind::kNone)) {
    // Also while the master stands still (issue 9); an HLI target's own job shows instead.
    state = AxisState::kSynchronizedMotion;
  } else if (homing_.active()) {
    state = AxisState::kHoming;
  } else if (locked_ || kind == JobKind::kStop || kind == JobKind::kEmergencyStop) {
    state = AxisState::kStopping;
  } else if (kind == JobKind::kPosition || kind == JobKind::kHalt) {
    state = AxisState::kDiscreteMotion;
  } else if (kind == JobKind::kVelocity) {
    state = AxisState::kContinuousMotion;
  }
  out.AxisState = static_cast<uint32_t>(state);
}

}  // namespace nc::detail
