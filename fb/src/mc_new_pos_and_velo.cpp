#include "fb/mc_new_pos_and_velo.hpp"

namespace fb {

void MC_NewPosAndVelo::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    detail::Start start;
    start.command.type = plc::CommandType::kNewPosAndVelo;
    start.command.position = NewPos;
    start.command.velocity = NewVelo;
    start.command.activation_position = ActivationPos;
    return start;
  });
  Done = out.done;
  Busy = out.busy;
  CommandAborted = out.aborted;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
