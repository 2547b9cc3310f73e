#include "fb/mc_ext_set_point_gen_enable.hpp"

namespace fb {

void MC_ExtSetPointGenEnable::operator()(plc::AXIS_REF& axis) noexcept {
  const detail::ExecuteOutputs out = block_(Execute, axis, [this]() noexcept {
    // The NC cannot tell a bad enum value from a meant one: checked here.
    if (PositionType != POSITIONTYPE_ABSOLUTE && PositionType != POSITIONTYPE_RELATIVE) {
      return detail::refuse(plc::ErrorCode::kStartTypeNotAllowed);
    }
    detail::Start start;
    start.command.type = plc::CommandType::kExtSetPointGenEnable;
    start.command.position = Position;
    start.command.mode = PositionType;
    return start;
  });
  Done = out.done;
  Busy = out.busy;
  Error = out.error;
  ErrorID = out.error_id;
  Enabled = plc::test_bit(axis.NcToPlc.StateDWord, plc::kStateExtSetPointGenEnabled);
}

}  // namespace fb
