// AxisCore's transitions (axis_core.hpp): the basic source and path of a cycle, a new job taking
// over the running one, the axis error.
#include "axis/axis_core.hpp"

#include "axis/group_errors.hpp"

namespace nc::detail {

using plc::CommandState;

void AxisCore::accept(JobKind kind, uint16_t number, const Profile& profile, double target,
                      double target_velocity, const Limits& limits) noexcept {
  note_event();
  // A running homing is replaced as a job would be (MC_Stop aborts it; Homed stays as it is).
  const uint16_t running =
      job_.active() ? job_.number() : (homing_.active() ? homing_.number() : 0);
  homing_.clear();
  // A new job in place of the running one: a command waiting behind that one is dropped (when
  // the waiting command itself starts here, the buffer is already empty).
  buffer_.drop(buffer_waiting_, channel_, CommandState::kAborted);
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
    channel_.warnings.clear_except(Warning::kOverrideNotAllowed);
  }
}

void AxisCore::raise_error(ErrorCode code, bool own) noexcept {
  if (!channel_.raise(code)) return;  // the first error stays until reset
  note_event();
  // The motion the error ramp takes over: a homing's stays readable after homing_.clear().
  const MasterJob& running = running_motion();
  error_event_ = true;
  ++errors_raised_;
  has_been_stopped_ = true;
  if (job_.active() && channel_.runs(job_.number())) {
    channel_.answer_current(CommandState::kError, plc::to_id(code));
  }
  if (homing_.active()) {
    if (channel_.runs(homing_.number())) {
      channel_.answer_current(CommandState::kError, plc::to_id(code));
    }
    homing_.clear();
  }
  // A slave's MC_GearIn / MC_GearInDyn fails with the axis (it is no longer InGear); the link
  // itself stays until MC_GearOut (SPEC C7).
  if (channel_.runs(slave_link_.command)) {
    channel_.answer_current(CommandState::kError, plc::to_id(code));
  }
  buffer_.drop(buffer_waiting_, channel_, CommandState::kError,
               plc::to_id(code));  // a waiting command fails with the axis
  // The compensation fails with the axis; external generation is switched off (seed 000 §2.6).
  fold_superpositions(CommandState::kError, code);
  if (own) {
    GroupErrors(*this).begin_error_propagation();  // C7: DELAYED, a slave leaves its master here
  }
  // A coupled slave's motion is its master's: it goes on following (group reactions: SPEC C7).
  if (slave_link_.coupled) return;
  start_error_ramp(running);
}

void AxisCore::start_error_ramp(const MasterJob& running) noexcept {
  if (!channel_.controller_enabled()) {
    job_.clear();
    return;
  }
  // SPEC A6: the axis stops on its own emergency ramp, from the set state it has now; with the
  // running job's larger jerk where the emergency jerk would pass the max velocity (K5).
  const Limits limits = with_running_jerk({config_.max_velocity, config_.acceleration,
                                           config_.emergency_deceleration, config_.emergency_jerk},
                                          set_, running, config_.max_velocity);
  scratch_ = plan_stop(set_, limits.deceleration, limits.jerk);
  if (!scratch_.ok()) {
    job_.clear();
    return;
  }
  job_.start(JobKind::kEmergencyStop, 0, scratch_, scratch_.final_state().p, 0.0, limits);
  target_ = scratch_.final_state().p;
  monitors_.reset_windows();
}

}  // namespace nc::detail
