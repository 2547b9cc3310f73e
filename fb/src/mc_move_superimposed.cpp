#include "fb/mc_move_superimposed.hpp"

namespace fb {

namespace {

bool runs(plc::CommandState state) noexcept {
  return state == plc::CommandState::kActive || state == plc::CommandState::kReached;
}

}  // namespace

void MC_MoveSuperImposed::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    // Seed 000 §2.5 start parameters, passed unchecked: the NC validates them (0x4244, 0x4270…).
    detail::Start start;
    start.command.type = plc::CommandType::kMoveSuperImposed;
    start.command.position = Distance;
    start.command.velocity = VelocityDiff;
    start.command.acceleration = Acceleration;
    start.command.deceleration = Deceleration;
    start.command.process_velocity = VelocityProcess;
    start.command.length = Length;
    return start;
  });
  const uint16_t number = block_.command_number();
  const plc::CommandState state = axis.Mailbox.answer(number).state;
  const bool result = out.done || out.error || out.aborted;
  // The compensation beside the basic motion does not take CmdNo: Active follows its answer.
  const bool running = out.busy && runs(state);
  // The NC's published compensation values belong to this block while its compensation runs and
  // in the call that sees how it ended (the NC publishes the final values in that cycle).
  const bool fresh_result = result && seen_number_ == number && number != 0 && !out.error;
  if (number != seen_number_ && out.busy) {
    seen_number_ = number;
    ActualDistance = 0.0;
    ActualLength = 0.0;
    ActualVelocityDiff = 0.0;
    Warning = false;
    WarningID = 0;
  }
  if (running || (fresh_result && Busy)) {
    ActualDistance = axis.NcToPlc.CompensationDistance;
    ActualLength = axis.NcToPlc.CompensationLength;
    ActualVelocityDiff = axis.NcToPlc.CompensationVelocityDiff;
    if (axis.NcToPlc.Warning == plc::to_id(plc::ErrorCode::kCompensationIncomplete)) {
      Warning = true;
      WarningID = axis.NcToPlc.Warning;
    }
  }
  if (!out.busy && !result) {
    Warning = false;
    WarningID = 0;
  }
  Done = out.done;
  Busy = out.busy;
  Active = running;
  CommandAborted = out.aborted;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
