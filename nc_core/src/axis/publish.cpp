// The part of the NC→PLC image (SPEC A7; StateDWord bits and AxisState values as TwinCAT /
// Tc2_MC2 number them) that only events change: kept in AxisCore::image_, computed here anew
// after note_event(), and the check that compares the two (docs/performance.md "Fourth pass").
// Phase (f) itself, ServoAxis::phase_publish, is in servo_axis.cpp, so that it inlines into
// the steady cycle.
#include <cstring>

#include "axis/nc_to_plc.hpp"
#include "axis/servo_axis.hpp"

namespace nc::detail {

EventImage event_image(const AxisCore& a, plc::NCTOPLC_AXIS_REF& out) noexcept {
  using plc::AxisState;
  const JobKind kind = a.job_.kind();
  const bool enabled = a.channel_.controller_enabled();
  const bool error = a.channel_.has_error();
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
  set_state_bit(word, plc::kStateOperational, enabled && !error);
  set_state_bit(word, plc::kStateError, error);

  // PLCopen state, in the priority of the PLCopen state diagram.
  AxisState state = AxisState::kStandstill;
  if (error) {
    state = AxisState::kErrorStop;
  } else if (!enabled) {
    state = AxisState::kDisabled;
  } else if (a.slave_link_.coupled || (a.hli_target() && kind == JobKind::kNone)) {
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
  image.job_kind = kind;
  image.rare = a.homing_.active() || !a.stack_.empty() || a.actual_filter_.active;
  image.constant_acceleration = 1e-9 * a.job_.goal.limits().acceleration + 1e-12;

  out.AxisState = static_cast<uint32_t>(state);
  out.CoupleState = static_cast<uint32_t>(
      slave ? (master ? plc::CoupleState::kMasterAndSlave : plc::CoupleState::kSlave)
            : (master ? plc::CoupleState::kMaster : plc::CoupleState::kSingle));
  out.CompensationDistance = a.stack_.compensation.done();  // travel-relative, as D
  out.CompensationLength = a.stack_.compensation.length();
  out.CompensationVelocityDiff = a.stack_.compensation.velocity_diff();
  // A coupled slave's change in every cycle: phase_publish() writes them again then.
  out.TargetVelo = a.target_velocity();
  out.GearRatio = a.slave_link_.coupled ? a.slave_link_.factor : 0.0;
  a.channel_.publish_to(out, static_cast<int32_t>(a.index_));
  return image;
}

bool image_consistent(const AxisCore& a) noexcept {
  if (a.two_speed_) return true;  // it publishes in full every cycle (two_speed_axis.cpp)
  const plc::NCTOPLC_AXIS_REF& out = a.channel_.ref().NcToPlc;
  // The recomputation writes its fields over a copy of what was published: every byte must stay.
  // Bytes, not values, on purpose: the copy's padding is the published one's, and a -0.0 where
  // 0.0 was published (or another NaN) is a difference the PLC could see.
  plc::NCTOPLC_AXIS_REF fresh_out;
  std::memcpy(&fresh_out, &out, sizeof out);
  const EventImage fresh = event_image(a, fresh_out);
  // NOLINTNEXTLINE(bugprone-suspicious-memory-comparison): bytes on purpose (above)
  const bool same_bytes = std::memcmp(&fresh_out, &out, sizeof out) == 0;
  return a.image_ == fresh && (out.StateDWord & kEventStateBits) == fresh.state_bits && same_bytes;
}

}  // namespace nc::detail
