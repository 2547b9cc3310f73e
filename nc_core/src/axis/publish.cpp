// The part of the NC→PLC image (SPEC A7; StateDWord bits and AxisState values as TwinCAT /
// Tc2_MC2 number them) that only events change: kept in AxisCore::image_, computed here anew
// after note_event(), and the check that compares the two (docs/performance.md "Fourth pass").
// Phase (f) itself, ServoAxis::phase_publish, is in servo_axis.cpp, so that it inlines into
// the steady cycle.
#include "axis/nc_to_plc.hpp"
#include "axis/servo_axis.hpp"

namespace nc::detail {

EventImage event_image(const AxisCore& a) noexcept {
  using plc::AxisState;
  const JobKind kind = a.job_.kind();
  // A gear slave, or an HLI target (a list in force); a gear master, or an HLI source.
  const bool slave = a.slave_link_.coupled || a.slave_link_.detached || a.hli_target();
  const bool master = a.slave_count_ > 0 || a.hli_source();
  EventImage image;
  uint32_t& word = image.state_bits;
  set_state_bit(word, plc::kStateHomed, a.homed_);
  set_state_bit(word, plc::kStateHasBeenStopped, a.has_been_stopped_);
  set_state_bit(word, plc::kStateHasJob, a.job_.active() || a.homing_.active());
  set_state_bit(word, plc::kStateHomingBusy, a.homing_.active());
  set_state_bit(word, plc::kStateCompensating, a.stack_.compensation.running());
  set_state_bit(word, plc::kStateExtSetPointGenEnabled, a.stack_.external.enabled());
  set_state_bit(word, plc::kStateCoupled, slave);
  set_state_bit(word, plc::kStateContinuousMotion, kind == JobKind::kVelocity);
  set_state_bit(word, plc::kStatePtpMode, true);
  set_state_bit(word, plc::kStateMotionCommandsLocked, a.locked_);
  set_state_bit(word, plc::kStateErrorPropagationDelayed, a.propagation_.delayed());  // C7 DELAYED

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
  return a.image_ == fresh && (out.StateDWord & kEventStateBits) == fresh.state_bits &&
         (!free_state || out.AxisState == fresh.axis_state) &&
         out.CoupleState == fresh.couple_state &&
         out.CompensationDistance == a.stack_.compensation.done() &&
         out.CompensationLength == a.stack_.compensation.length() &&
         out.CompensationVelocityDiff == a.stack_.compensation.velocity_diff();
}

}  // namespace nc::detail
