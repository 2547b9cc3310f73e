#include "fb/mc_ext_set_point_gen_disable.hpp"

namespace fb {

void MC_ExtSetPointGenDisable::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, []() noexcept {
    detail::Start start;
    start.command.type = plc::CommandType::kExtSetPointGenDisable;
    return start;
  });
  Done = out.done;
  Busy = out.busy;
  Error = out.error;
  ErrorID = out.error_id;
  Enabled = plc::test_bit(axis.NcToPlc.StateDWord, plc::kStateExtSetPointGenEnabled);
}

}  // namespace fb
