// MC_GearIn / MC_GearOut on the slave (SPEC C1, C3, C4; seed 000 §3.2.2-3.2.3): the
// checks, the graph update in the commands phase, and what a coupled slave refuses. The codes
// and the order of the checks are in docs/behaviour.md "Slave axes".
#include <cmath>

#include "axis/slave_coupling.hpp"

#include "axis/servo_axis.hpp"

namespace nc::detail {

// The largest |ratio| of a linear coupling (docs/behaviour.md, "Slave axes").
inline constexpr double kMaxGearRatio = 1e6;

using plc::CommandState;
using plc::CommandType;

bool SlaveCoupling::at_rest_for_coupling() const noexcept {
  return !s_.job_.active() && !s_.homing_.active() && s_.set_.v == 0.0 && s_.set_.a == 0.0 &&
         !s_.stack_.compensation.running() && !s_.stack_.external.enabled();
}

bool SlaveCoupling::refused_while_coupled(CommandType type) noexcept {
  switch (type) {
    case CommandType::kMoveAbsolute:
    case CommandType::kMoveRelative:
    case CommandType::kMoveModulo:
    case CommandType::kMoveVelocity:
    case CommandType::kHalt:
    case CommandType::kStop:
    case CommandType::kNewPos:
    case CommandType::kNewPosAndVelo:
    case CommandType::kExtSetPointGenEnable:
    case CommandType::kGearInDyn:
    case CommandType::kHome:
      return true;
    default:
      return false;
  }
}

ErrorCode SlaveCoupling::check_gear_ratio(double ratio) noexcept {
  if (!std::isfinite(ratio)) return ErrorCode::kParameterNotFinite;
  if (ratio == 0.0) return ErrorCode::kCouplingFactorZero;
  // Fuzz finding K6: a ratio of 8.4e301 made the slave's set values overflow (SetAcc inf). With
  // |ratio| <= 1e6 a cascade of three (4 axes) scales the master's values by at most 1e18.
  if (std::abs(ratio) > kMaxGearRatio) return ErrorCode::kGearRatioOutOfRange;
  return ErrorCode::kNone;
}

ErrorCode SlaveCoupling::check_gear_master(const plc::Command& command,
                                           CouplingPort& port) const noexcept {
  if (s_.slave_link_.detached) return ErrorCode::kFunctionNotAllowed;  // C7: MC_GearOut first
  if (s_.config_.kind == AxisKind::kEncoder) return ErrorCode::kAxisKindNotAllowed;
  if (command.other_axis < 0 || static_cast<std::size_t>(command.other_axis) >= port.axes.size()) {
    return ErrorCode::kInvalidAxisReference;
  }
  // A two-speed axis has no set position to follow or to be followed by (seed 004).
  if (port.axes[static_cast<std::size_t>(command.other_axis)]->core().two_speed_) {
    return ErrorCode::kAxisKindNotAllowed;
  }
  return ErrorCode::kNone;
}

ErrorCode SlaveCoupling::check_new_coupling(uint32_t master_index,
                                            CouplingPort& port) const noexcept {
  if (port.graph.would_loop(s_.index_, master_index)) return ErrorCode::kCouplingLoop;
  if (s_.channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (s_.locked_) return ErrorCode::kMotionCommandsLocked;
  if (!s_.channel_.controller_enabled()) return ErrorCode::kSlaveNoControllerOrFeedEnable;
  if (!at_rest_for_coupling() ||
      !SlaveCoupling(port.axes[master_index]->core()).at_rest_for_coupling()) {
    return ErrorCode::kBusyWhileCoupling;
  }
  return ErrorCode::kNone;
}

bool SlaveCoupling::couple_new(const plc::Command& command, uint32_t master_index,
                               CouplingPort& port) noexcept {
  if (!port.graph.couple(s_.index_, master_index)) return false;  // not reached
  AxisCore& master = port.axes[master_index]->core();
  ++master.slave_count_;
  master.note_event();  // its CoupleState
  const uint16_t running = s_.job_.active() ? s_.job_.number() : 0;
  s_.slave_link_.couple(master_index, command.number, command.ratio, s_.set_.p, master.set_.p);
  // A held offset of a compensation that ended in the last cycle is in s_.set_.p, so in the offset.
  s_.stack_.drop_held();
  s_.channel_.take_over(command.number, running);
  s_.monitors_.reset_windows();
  return true;
}

ErrorCode SlaveCoupling::gear_in(const plc::Command& command, CouplingPort& port) noexcept {
  if (const ErrorCode code = check_gear_ratio(command.ratio); code != ErrorCode::kNone) {
    return code;
  }
  if (const ErrorCode code = check_gear_master(command, port); code != ErrorCode::kNone) {
    return code;
  }
  const auto master_index = static_cast<uint32_t>(command.other_axis);
  AxisCore& master = port.axes[master_index]->core();
  if (s_.slave_link_.coupled) {
    // A new rising edge for the same slave and master: the factor changes at once with the
    // slave's position continuous (SPEC C2). Another master needs MC_GearOut first.
    if (master_index != s_.slave_link_.master) return ErrorCode::kFunctionNotAllowed;
    s_.channel_.take_over(command.number, s_.slave_link_.command);  // the former instance: kAborted
    // From the basic set position: a compensation of the slave (C5) goes on on top of it.
    s_.slave_link_.couple(master_index, command.number, command.ratio, s_.base_.p, master.set_.p);
    s_.channel_.answer_current(CommandState::kReached);
    return ErrorCode::kNone;
  }
  if (const ErrorCode code = check_new_coupling(master_index, port); code != ErrorCode::kNone) {
    return code;
  }
  if (!couple_new(command, master_index, port)) return ErrorCode::kCouplingLoop;
  s_.channel_.answer_current(CommandState::kReached);  // InGear at once: the coupling is logical
  return ErrorCode::kNone;
}

bool SlaveCoupling::decoupling_chain(CouplingPort& port, DecouplingChain& chain,
                                     const AxisCore*& head) const noexcept {
  // From this slave up to the head of its cascade: each slave link, and each master's own
  // superposition (a held offset, a compensation) as the level set = (1 + c)·base + e, c the
  // compensation's share of the velocity at decoupling (seed 000 §3.2.4 note 5: its velocity is
  // kept, it never completes). Collected slave first, applied head first.
  DecouplingChain up;
  const AxisCore* axis = &s_;
  while (true) {
    const KinematicState& base = axis->base_;
    const KinematicState& set = axis->set_;
    if (set.p != base.p || set.v != base.v) {
      const double c = base.v != 0.0 ? (set.v - base.v) / base.v : 0.0;
      if (!up.push(1.0 + c, (set.p - base.p) - c * base.p)) return false;
    }
    if (!axis->slave_link_.coupled) break;
    if (!up.push(axis->slave_link_.factor, axis->slave_link_.offset)) return false;
    axis = &port.axes[axis->slave_link_.master]->core();
  }
  // The head's plan is what goes on: without a PTP job there is none to copy (an absolute
  // external generator, a compensation moving a held axis).
  if (!axis->job_.active() || axis->source() != SetValueSource::kPtpJob) return false;
  if (axis->job_.table.chain_depth() + up.count > DecouplingChain::kMaxLevels) return false;
  chain.count = 0;
  for (std::size_t i = up.count; i-- > 0;)
    (void)chain.push(up.levels[i].factor, up.levels[i].offset);
  head = axis;
  return true;
}

ErrorCode SlaveCoupling::gear_out(const plc::Command& command, CouplingPort& port) noexcept {
  if (s_.slave_link_.detached) return release_detached(command, port);  // C7 DELAYED
  if (!s_.slave_link_.coupled) return ErrorCode::kDecouplingNotAllowed;
  // Online when the slave moves (its master's velocity is not 0); at override 0 or at rest it
  // decouples offline (seed 000 §3.2.3).
  const bool online = s_.set_.v != 0.0 || s_.set_.a != 0.0;
  DecouplingChain chain;
  const AxisCore* head = nullptr;
  if (online && !decoupling_chain(port, chain, head)) return ErrorCode::kDecouplingNotAllowed;
  port.graph.decouple(s_.index_);
  AxisCore& master = port.axes[s_.slave_link_.master]->core();
  --master.slave_count_;
  master.note_event();  // its CoupleState
  s_.slave_link_.coupled = false;
  // The coupling command has ended.
  if (s_.channel_.runs(s_.slave_link_.command)) s_.channel_.answer_current(CommandState::kDone);
  s_.monitors_.reset_windows();
  s_.channel_.answer(command.number, CommandState::kDone);
  if (!online) {
    // The slave becomes a PTP master holding its set position.
    s_.base_ = KinematicState{s_.set_.p, 0.0, 0.0};
    s_.target_ = s_.set_.p;
    return ErrorCode::kNone;
  }
  // The slave becomes a master that goes on with the head's plan as it stands now, transformed:
  // override 100 % = |last factor| × the head's target velocity; what comes next (stop, new end
  // position, override) uses the axis's own dynamics. The job has no command number of its own.
  const double scale = std::abs(chain.total_factor());
  const Limits own{scale * head->job_.goal.user_velocity(), s_.config_.acceleration,
                   s_.config_.deceleration, s_.config_.jerk};
  const uint32_t override_value = s_.job_.online.override_value();
  // The slave's own compensation is a level of the chain now: it never completes.
  s_.fold_superpositions(CommandState::kAborted);
  s_.job_ = head->job_;
  s_.job_.follow(chain, 0, own, override_value);
  s_.base_ = s_.set_;
  if (s_.job_.kind() == JobKind::kEmergencyStop) s_.job_.set_kind(JobKind::kHalt);  // no error here
  s_.target_ = s_.job_.kind() == JobKind::kVelocity ? s_.set_.p : s_.job_.goal.target();
  return ErrorCode::kNone;
}

ErrorCode SlaveCoupling::release_detached(const plc::Command& command,
                                          CouplingPort& port) noexcept {
  port.graph.decouple(s_.index_);
  AxisCore& master = port.axes[s_.slave_link_.master]->core();
  --master.slave_count_;
  master.note_event();  // its CoupleState
  s_.slave_link_.detached = false;
  if (s_.channel_.runs(s_.slave_link_.command)) s_.channel_.answer_current(CommandState::kDone);
  s_.channel_.answer(command.number, CommandState::kDone);
  return ErrorCode::kNone;
}

}  // namespace nc::detail
