#include "axis/superposition_stack.hpp"

namespace nc::detail {

using plc::CommandState;
using Type = ExternalSetpoint::Type;

SuperpositionStack::Result SuperpositionStack::superimpose(const Basic& basic,
                                                           const plc::PLCTONC_AXIS_REF& in,
                                                           AxisChannel& channel,
                                                           double cycle_time) noexcept {
  Result r;
  KinematicState total = basic.state;
  total.p += held_;

  if (compensation.running()) {
    const KinematicState extra = compensation.advance(basic.state.v, basic.state.a, cycle_time);
    total.p += extra.p;
    total.v += extra.v;
    total.a += extra.a;
    // Done when its time T is over; ended early by a compensation stop or when the basic
    // motion's path ends first (seed 000 §2.5 notes 6 and 7).
    if (compensation.time_over()) {
      end_compensation(
          channel, compensation.stop_requested() ? CommandState::kAborted : CommandState::kDone);
    } else if (!basic.path_running) {
      end_compensation(channel, CommandState::kAborted);
    }
  }
  if ((compensation.running() || held_ != 0.0) && basic.has_target && !external.taking()) {
    // The superimposed distance moves the job's end (TargetPos, target window).
    r.target =
        basic.target + held_ + (compensation.running() ? compensation.planned_offset() : 0.0);
    r.target_moved = true;
  }
  if (external.taking() && external.type() == Type::kRelative) {
    const ExternalSetpoint::Step step = external.take(in, cycle_time);
    r.not_finite = step.not_finite;
    r.too_large = step.too_large;
    total.p += step.state.p;
    total.v += step.state.v;
    total.a += step.state.a;
    if (step.finished) held_ += step.state.p;
  }
  r.set = total;
  return r;
}

KinematicState SuperpositionStack::basic_state(const KinematicState& base,
                                               const KinematicState& set) const noexcept {
  if (external.taking() && external.type() == Type::kAbsolute) return set;
  KinematicState state = base;
  state.p += held_;
  return state;
}

KinematicState SuperpositionStack::stop_start_state(const KinematicState& set) const noexcept {
  KinematicState state = set;
  if (compensation.running()) {
    const KinematicState& extra = compensation.state();
    state.p -= extra.p;
    state.v -= extra.v;
    state.a -= extra.a;
  }
  return state;
}

void SuperpositionStack::end_compensation(AxisChannel& channel, CommandState state) noexcept {
  held_ += compensation.finish();
  channel.answer(compensation.number(), state);
  if (compensation.incomplete()) channel.warnings.warn(Warning::kCompensationIncomplete);
}

void SuperpositionStack::fold(AxisChannel& channel, CommandState state, ErrorCode code) noexcept {
  if (compensation.running()) {
    // Its offset so far is in the set state, where the new job starts: nothing to hold.
    compensation.finish();
    channel.answer(compensation.number(), state, plc::to_id(code));
    if (compensation.incomplete()) channel.warnings.warn(Warning::kCompensationIncomplete);
  }
  external.abort();
  held_ = 0.0;
}

void SuperpositionStack::on_stop() noexcept {
  // Planned from stop_start_state(): the held offset and the external offset are in the new
  // job. A stop requests the compensation stop at the same time (seed 000 §2.5).
  external.abort();
  held_ = 0.0;
  if (compensation.running()) (void)compensation.request_stop();  // braking: goes on
}

bool SuperpositionStack::end_external() noexcept {
  if (!external.taking()) return false;
  const bool absolute = external.type() == Type::kAbsolute;
  if (absolute) {
    held_ = 0.0;
  } else {
    held_ += external.state().p;
  }
  external.abort();
  return absolute;
}

}  // namespace nc::detail
