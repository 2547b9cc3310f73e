#include "fb/mc_gear_out.hpp"

namespace fb {

void MC_GearOut::operator()(plc::AXIS_REF& slave) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, slave, []() noexcept {
    detail::Start start;
    start.command.type = plc::CommandType::kGearOut;
    return start;
  });
  Done = out.done;
  Busy = out.busy;
  Error = out.error;
  ErrorID = out.error_id;
}

}  // namespace fb
