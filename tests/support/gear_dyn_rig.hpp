// Kernel tests of cyclic slaves (SPEC C6, MC_GearInDyn): the coupling command posted straight into
// the slave's mailbox, and one NC cycle with the factor written first, as the block does.
//
// Test code (allocates nothing itself; gr::Rig allocates at construction only).
#pragma once

#include <cstddef>
#include <cstdint>

#include "gear_rig.hpp"

namespace gd {

// MC_GearInDyn's command: the master's kernel index, the first factor and AccBound.
inline plc::Command gear_in_dyn(std::size_t master, double ratio, double acc_bound) {
  plc::Command c;
  c.type = plc::CommandType::kGearInDyn;
  c.other_axis = static_cast<int32_t>(master);
  c.ratio = ratio;
  c.acceleration = acc_bound;
  return c;
}

// Couples `slave` to `master` as a cyclic slave (GearRatio1 written first); the answer.
inline plc::CommandAnswer couple(gr::Rig& rig, std::size_t slave, std::size_t master, double ratio,
                                 double acc_bound) {
  rig.at(slave).PlcToNc.GearRatio1 = ratio;
  const uint16_t n = rig.post(slave, gear_in_dyn(master, ratio, acc_bound));
  rig.kernel.cycle();
  return rig.answer(slave, n);
}

}  // namespace gd
