#include "fb/mc_gear_out.hpp"

#include "fb/detail/plain_command.hpp"

namespace fb {

void MC_GearOut::operator()(plc::AXIS_REF& slave) noexcept {
  detail::run_plain_command(*this, block_, slave, plc::CommandType::kGearOut);
}

}  // namespace fb
