#include "fb/mc_gear_in.hpp"

#include "gear_command.hpp"

namespace fb {

void MC_GearIn::operator()(const plc::AXIS_REF& master, plc::AXIS_REF& slave) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, slave, [this, &master]() noexcept {
    if (RatioDenominator == 0) return detail::refuse(plc::ErrorCode::kBlockInputOutOfRange);
    if (BufferMode != MC_Aborting) return detail::refuse(plc::ErrorCode::kBufferModeNotSupported);
    return detail::gear_start(*this, plc::CommandType::kGearIn,
                              RatioNumerator / static_cast<double>(RatioDenominator), master);
  });
  InGear = out.reached;
  Busy = out.busy;
  Active = out.active;
  CommandAborted = out.aborted;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
