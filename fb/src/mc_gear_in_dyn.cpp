#include "fb/mc_gear_in_dyn.hpp"

#include "gear_command.hpp"

namespace fb {

void MC_GearInDyn::operator()(const plc::AXIS_REF& master, plc::AXIS_REF& slave) noexcept {
  slave.PlcToNc.GearRatio1 = GearRatio;
  const bool falling = previous_enable_ && !Enable;
  previous_enable_ = Enable;
  if (Enable) decoupling_ = false;
  const detail::ExecuteOutputs in = couple_(Enable, slave, [this, &master]() noexcept {
    if (BufferMode != MC_Aborting) return detail::refuse(plc::ErrorCode::kBufferModeNotSupported);
    return detail::gear_start(*this, plc::CommandType::kGearInDyn, GearRatio, master);
  });
  if (falling && in.busy) decoupling_ = true;
  const detail::ExecuteOutputs out = decouple_(decoupling_, slave, []() noexcept {
    detail::Start start;
    start.command.type = plc::CommandType::kGearOut;
    return start;
  });
  if (Enable) {
    Busy = in.busy;
    Active = in.active;
    InGear = in.active && slave.NcToPlc.GearRatio == GearRatio;
    CommandAborted = in.aborted;
    Error = in.error;
    ErrorID = in.error_id;
    return;
  }
  // Enable low: decoupling, or a result reached after Enable fell (shown for one call).
  InGear = false;
  Active = false;
  Error = out.error || in.error;
  ErrorID = out.error ? out.error_id : in.error_id;
  Busy = !Error && (in.busy || out.busy);
  CommandAborted = !Error && !Busy && in.aborted;
}

}  // namespace fb
