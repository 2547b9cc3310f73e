#include "fb/mc_gear_in.hpp"

namespace fb {

void MC_GearIn::operator()(const plc::AXIS_REF& master, plc::AXIS_REF& slave) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, slave, [this, &master]() noexcept {
    if (RatioDenominator == 0) return detail::refuse(plc::ErrorCode::kBlockInputOutOfRange);
    if (BufferMode != MC_Aborting) return detail::refuse(plc::ErrorCode::kBufferModeNotSupported);
    detail::Start start;
    start.command.type = plc::CommandType::kGearIn;
    start.command.ratio = RatioNumerator / static_cast<double>(RatioDenominator);
    start.command.other_axis = master.NcToPlc.AxisIndex;
    start.command.acceleration = Acceleration;
    start.command.deceleration = Deceleration;
    start.command.jerk = Jerk;
    start.command.buffer_mode = BufferMode;
    return start;
  });
  InGear = out.reached;
  Busy = out.busy;
  Active = out.active;
  CommandAborted = out.aborted;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
