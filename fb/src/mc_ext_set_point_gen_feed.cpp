#include "fb/mc_ext_set_point_gen_feed.hpp"

#include "plc_interface/error_code.hpp"

namespace fb {

uint32_t MC_ExtSetPointGenFeed(double Position, double Velocity, double Acceleration,
                               int32_t Direction, plc::AXIS_REF& Axis) noexcept {
  if (Direction < -1 || Direction > 1) return plc::to_id(plc::ErrorCode::kDirectionInvalid);
  Axis.PlcToNc.ExtSetPos = Position;
  Axis.PlcToNc.ExtSetVelo = Velocity;
  Axis.PlcToNc.ExtSetAcc = Acceleration;
  Axis.PlcToNc.ExtSetDirection = Direction;
  return 0;
}

}  // namespace fb
