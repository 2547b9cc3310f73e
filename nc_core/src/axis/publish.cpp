// Step f of the NC cycle for one axis: the NC→PLC image (SPEC A7; StateDWord bits and AxisState
// values as TwinCAT / Tc2_MC2 number them). What only events change is kept in AxisCore::image_
// and computed anew only after note_event() (docs/performance.md "Fourth pass").
#include <cmath>
#include <cstdlib>

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

// Bits or-ed in without branches (every bit starts at 0).
constexpr void set_bit(uint32_t& word, plc::StateBit bit, bool value) noexcept {
  word |= static_cast<uint32_t>(value) << bit;
}

// The StateDWord bits event_image() gives; the others are computed every cycle.
constexpr uint32_t kEventBits =
    (1U << plc::kStateHomed) | (1U << plc::kStateErrorPropagationDelayed) |
    (1U << plc::kStateHasBeenStopped) | (1U << plc::kStateHasJob) | (1U << plc::kStateHomingBusy) |
    (1U << plc::kStateCompensating) | (1U << plc::kStateExtSetPointGenEnabled) |
    (1U << plc::kStateCoupled) | (1U << plc::kStateContinuousMotion) | (1U << plc::kStatePtpMode) |
    (1U << plc::kStateMotionCommandsLocked);

}  // namespace

EventImage event_image(const AxisCore& a) noexcept {
  using plc::AxisState;
  const JobKind kind = a.job_.kind();
  // A gear slave, or an HLI target (a list in force); a gear master, or an HLI source.
  const bool slave = a.slave_link_.coupled || a.slave_link_.detached || a.hli_target();
  const bool master = a.slave_count_ > 0 || a.hli_source();
  EventImage image;
  uint32_t& word = image.state_bits;
  set_bit(word, plc::kStateHomed, a.homed_);
  set_bit(word, plc::kStateHasBeenStopped, a.has_been_stopped_);
  set_bit(word, plc::kStateHasJob, a.job_.active() || a.homing_.active());
  set_bit(word, plc::kStateHomingBusy, a.homing_.active());
  set_bit(word, plc::kStateCompensating, a.stack_.compensation.running());
  set_bit(word, plc::kStateExtSetPointGenEnabled, a.stack_.external.enabled());
  set_bit(word, plc::kStateCoupled, slave);
  set_bit(word, plc::kStateContinuousMotion, kind == JobKind::kVelocity);
  set_bit(word, plc::kStatePtpMode, true);
  set_bit(word, plc::kStateMotionCommandsLocked, a.locked_);
  set_bit(word, plc::kStateErrorPropagationDelayed, a.propagation_.delayed());  // C7 DELAYED

  // PLCopen state, in the priority of the PLCopen state diagram (ErrorStop and Disabled come
  // first; phase_publish() decides them every cycle).
  AxisState state = AxisState::kStandstill;
  if (a.slave_link_.coupled || (a.hli_target() && kind == JobKind::kNone)) {
    // Also while the master stands still (issue 9); an HLI target's own job shows instead.
    state = AxisState::kSynchronizedMotion;
  } else if (a.homing_.active()) {
    state = AxisState::kHoming;
  } else if (a.locked_ || kind == JobKind::kStop || kind == JobKind::kEmergencyStop) {
    state = AxisState::kStopping;
  } else if (kind == JobKind::kPosition || kind == JobKind::kHalt) {
    state = AxisState::kDiscreteMotion;
  } else if (kind == JobKind::kVelocity) {
    state = AxisState::kContinuousMotion;
  }
  image.axis_state = static_cast<uint32_t>(state);
  image.couple_state = static_cast<uint32_t>(
      slave ? (master ? plc::CoupleState::kMasterAndSlave : plc::CoupleState::kSlave)
            : (master ? plc::CoupleState::kMaster : plc::CoupleState::kSingle));
  image.job_kind = kind;
  image.constant_acceleration = 1e-9 * a.job_.goal.limits().acceleration + 1e-12;
  return image;
}

bool image_consistent(const AxisCore& a) noexcept {
  if (a.two_speed_) return true;  // it publishes in full every cycle (two_speed_axis.cpp)
  const EventImage fresh = event_image(a);
  const plc::NCTOPLC_AXIS_REF& out = a.channel_.ref().NcToPlc;
  const bool free_state = a.channel_.controller_enabled() && !a.channel_.has_error();
  return a.image_ == fresh && (out.StateDWord & kEventBits) == fresh.state_bits &&
         (!free_state || out.AxisState == fresh.axis_state) &&
         out.CoupleState == fresh.couple_state &&
         out.CompensationDistance == a.stack_.compensation.done() &&
         out.CompensationLength == a.stack_.compensation.length() &&
         out.CompensationVelocityDiff == a.stack_.compensation.velocity_diff();
}

void ServoAxis::phase_publish(uint64_t cycle_counter) noexcept {
  if (two_speed_) return two_speed_->phase_publish(cycle_counter, static_cast<int32_t>(index_));
  plc::NCTOPLC_AXIS_REF& out = channel_.ref().NcToPlc;
  if (events_) {
    // Something the image shows may have changed since the last publish (note_event()).
    events_ = false;
    image_ = event_image(*this);
    out.CoupleState = image_.couple_state;
    out.CompensationDistance = stack_.compensation.done();  // travel-relative, as D
    out.CompensationLength = stack_.compensation.length();
    out.CompensationVelocityDiff = stack_.compensation.velocity_diff();
  }
#ifdef NCSDK_CHECK_EVENT_IMAGE
  // A check build (-DNCSDK_CHECK_EVENT_IMAGE): a missed note_event() stops the program here.
  if (!(image_ == event_image(*this))) std::abort();
#endif
  const double actual = drive_.measured_position();
  const bool enabled = channel_.controller_enabled();
  const bool error = channel_.has_error();

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
  channel_.publish(static_cast<int32_t>(index_));
  out.GearRatio = slave_link_.coupled ? slave_link_.factor : 0.0;
  out.CycleCounter = static_cast<uint32_t>(cycle_counter);

  // Constant velocity: a velocity job at its level, or the cruise phase of a positioning.
  const JobKind kind = image_.job_kind;
  const bool constant_velocity =
      (kind == JobKind::kVelocity && job_.table.velocity_reached()) ||
      (kind == JobKind::kPosition && !job_.table.generation_ended() && set_.v != 0.0 &&
       std::abs(set_.a) <= image_.constant_acceleration && set_jerk_ == 0.0);

  uint32_t word = image_.state_bits;
  set_bit(word, plc::kStateOperational, enabled && !error);
  set_bit(word, plc::kStateNotMoving, std::abs(drive_.velocity()) < standstill_window_);
  set_bit(word, plc::kStateInPositionArea, monitors_.in_position_area());
  set_bit(word, plc::kStateInTargetPosition, monitors_.in_target_position());
  set_bit(word, plc::kStatePositiveDirection, set_.v > 0.0);
  set_bit(word, plc::kStateNegativeDirection, set_.v < 0.0);
  set_bit(word, plc::kStateConstantVelocity, constant_velocity);
  set_bit(word, plc::kStateSoftLimitMinExceeded, monitors_.below_min(actual));
  set_bit(word, plc::kStateSoftLimitMaxExceeded, monitors_.above_max(actual));
  set_bit(word, plc::kStateError, error);
  out.StateDWord = word;

  // PLCopen state: ErrorStop and Disabled before the image's.
  out.AxisState = error      ? static_cast<uint32_t>(plc::AxisState::kErrorStop)
                  : !enabled ? static_cast<uint32_t>(plc::AxisState::kDisabled)
                             : image_.axis_state;
}

}  // namespace nc::detail
