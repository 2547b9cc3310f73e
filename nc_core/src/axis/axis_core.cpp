// AxisCore's transitions (axis_core.hpp): the basic source and path of a cycle, a new job taking
// over the running one.
#include "axis/axis_core.hpp"

namespace nc::detail {

using plc::CommandState;

BasicPath AxisCore::basic_path() const noexcept {
  if (slave_link_.coupled) return slave_path_;
  const JobKind kind = job_.kind();
  BasicPath path;
  path.running = job_.active() && !job_.generation_ended();
  path.stopping =
      kind == JobKind::kHalt || kind == JobKind::kStop || kind == JobKind::kEmergencyStop;
  path.positioning = kind == JobKind::kPosition;
  path.has_target = job_.active() && kind != JobKind::kVelocity;
  path.target = job_.target();
  path.target_velocity = job_.active() ? job_.target_velocity() : 0.0;
  return path;
}

SetValueSource AxisCore::source() const noexcept {
  if (slave_link_.coupled) return SetValueSource::kSlaveLink;  // a coupled slave has no job
  if (homing_.active()) return SetValueSource::kHomingJob;
  if (job_.active()) return SetValueSource::kPtpJob;
  const ExternalSetpoint& external = stack_.external();
  if (external.taking() && external.type() == ExternalSetpoint::Type::kAbsolute) {
    return SetValueSource::kExternalAbsolute;
  }
  return SetValueSource::kHold;
}

void AxisCore::accept(JobKind kind, uint16_t number, const Profile& profile, double target,
                      double target_velocity, const Limits& limits) noexcept {
  // A running homing is replaced as a job would be (MC_Stop aborts it; Homed stays as it is).
  const uint16_t running =
      job_.active() ? job_.number() : (homing_.active() ? homing_.number() : 0);
  homing_.clear();
  // A new job in place of the running one: a command waiting behind that one is dropped (when
  // the waiting command itself starts here, the buffer is already empty).
  buffer_.drop(channel_, CommandState::kAborted);
  job_.start(kind, number, profile, target, target_velocity, limits);
  if (kind == JobKind::kHalt || kind == JobKind::kStop) {
    stack_.on_stop();
  } else {
    fold_superpositions(CommandState::kAborted);
  }
  channel_.take_over(number, running);
  if (kind != JobKind::kVelocity) target_ = target;
  monitors_.reset_windows();
  if (kind == JobKind::kPosition || kind == JobKind::kVelocity) {
    has_been_stopped_ = false;
    // The override's warning stays while PlcToNc.Override is not taken (read_override()).
    channel_.clear_warnings_except(Warning::kOverrideNotAllowed);
  }
}

}  // namespace nc::detail
