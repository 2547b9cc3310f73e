// MC_GearIn / MC_GearOut on the slave (SPEC C1, C3, C4 at rest; seed 000 §3.2.2-3.2.3): the
// checks, the graph update in the commands phase, and what a coupled slave refuses. The codes
// and the order of the checks are in docs/behaviour.md "Slave axes".
#include <cmath>

#include "axis/servo_axis.hpp"

namespace nc::detail {

using plc::CommandState;
using plc::CommandType;

bool ServoAxis::at_rest_for_coupling() const noexcept {
  return !job_.active() && !homing_.active() && set_.v == 0.0 && set_.a == 0.0 &&
         !stack_.compensation().running() && !stack_.external().enabled();
}

bool ServoAxis::refused_while_coupled(CommandType type) noexcept {
  switch (type) {
    case CommandType::kMoveAbsolute:
    case CommandType::kMoveRelative:
    case CommandType::kMoveModulo:
    case CommandType::kMoveVelocity:
    case CommandType::kHalt:
    case CommandType::kStop:
    case CommandType::kNewPos:
    case CommandType::kNewPosAndVelo:
    case CommandType::kMoveSuperImposed:
    case CommandType::kExtSetPointGenEnable:
    case CommandType::kGearInDyn:
    case CommandType::kHome:
      return true;
    default:
      return false;
  }
}

ErrorCode ServoAxis::gear_in(const plc::Command& command, CouplingPort& port) noexcept {
  if (!std::isfinite(command.ratio)) return ErrorCode::kParameterNotFinite;
  if (command.ratio == 0.0) return ErrorCode::kCouplingFactorZero;
  if (config_.kind == AxisKind::kEncoder) return ErrorCode::kAxisKindNotAllowed;
  if (command.other_axis < 0 || static_cast<std::size_t>(command.other_axis) >= port.axes.size()) {
    return ErrorCode::kInvalidAxisReference;
  }
  const auto master_index = static_cast<uint32_t>(command.other_axis);
  ServoAxis& master = *port.axes[master_index];
  if (slave_link_.coupled) {
    // A new rising edge for the same slave and master: the factor changes at once with the
    // slave's position continuous (SPEC C2). Another master needs MC_GearOut first.
    if (master_index != slave_link_.master) return ErrorCode::kFunctionNotAllowed;
    channel_.take_over(command.number, slave_link_.command);  // the former instance: kAborted
    slave_link_.couple(master_index, command.number, command.ratio, set_.p, master.set_.p);
    channel_.answer_current(CommandState::kReached);
    return ErrorCode::kNone;
  }
  if (port.graph.would_loop(index_, master_index)) return ErrorCode::kCouplingLoop;
  if (channel_.has_error()) return ErrorCode::kAxisInErrorState;
  if (locked_) return ErrorCode::kMotionCommandsLocked;
  if (!channel_.controller_enabled()) return ErrorCode::kSlaveNoControllerOrFeedEnable;
  if (!at_rest_for_coupling() || !master.at_rest_for_coupling()) {
    return ErrorCode::kBusyWhileCoupling;
  }
  if (!port.graph.couple(index_, master_index)) return ErrorCode::kCouplingLoop;  // not reached
  ++master.slave_count_;
  const uint16_t running = job_.active() ? job_.number() : 0;
  slave_link_.couple(master_index, command.number, command.ratio, set_.p, master.set_.p);
  // A held offset of a compensation that ended in the last cycle is in set_.p, so in the offset.
  stack_.drop_held();
  channel_.take_over(command.number, running);
  channel_.answer_current(CommandState::kReached);  // InGear at once: the coupling is logical
  monitors_.reset_windows();
  return ErrorCode::kNone;
}

ErrorCode ServoAxis::gear_out(const plc::Command& command, CouplingPort& port) noexcept {
  if (!slave_link_.coupled) return ErrorCode::kDecouplingNotAllowed;
  // Online decoupling (SPEC C4 in motion) is not there yet: only a slave at rest decouples.
  if (set_.v != 0.0 || set_.a != 0.0) return ErrorCode::kDecouplingNotAllowed;
  port.graph.decouple(index_);
  ServoAxis& master = *port.axes[slave_link_.master];
  --master.slave_count_;
  slave_link_.coupled = false;
  // The slave becomes a PTP master holding its set position; the coupling command has ended.
  if (channel_.runs(slave_link_.command)) channel_.answer_current(CommandState::kDone);
  base_ = KinematicState{set_.p, 0.0, 0.0};
  target_ = set_.p;
  monitors_.reset_windows();
  channel_.answer(command.number, CommandState::kDone);
  return ErrorCode::kNone;
}

}  // namespace nc::detail
