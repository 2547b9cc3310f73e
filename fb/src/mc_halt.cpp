#include "fb/mc_halt.hpp"

namespace fb {

void MC_Halt::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    return detail::motion_start(
        plc::CommandType::kHalt,
        {.deceleration = Deceleration, .jerk = Jerk, .buffer_mode = BufferMode});
  });
  Done = out.done;
  Busy = out.busy;
  Active = out.active;
  CommandAborted = out.aborted;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
