#include "fb/mc_home.hpp"

namespace fb {

void MC_Home::operator()(plc::AXIS_REF& axis) noexcept {
  axis.PlcToNc.ControlDWord =
      plc::with_bit(axis.PlcToNc.ControlDWord, plc::kControlHomingSensor, bCalibrationCam);
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    // The NC buffers moves and halts only (docs/behaviour.md "BufferMode"): homing aborts.
    if (BufferMode != MC_Aborting) return detail::refuse(plc::ErrorCode::kBufferModeNotSupported);
    detail::Start start = detail::motion_start(plc::CommandType::kHome,
                                               {.position = Position, .buffer_mode = BufferMode});
    start.command.mode = HomingMode;
    return start;
  });
  Done = out.done;
  Busy = out.busy;
  Active = out.active;
  CommandAborted = out.aborted;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
