// The set-value source of a coupled linear slave (SPEC C1, seed 000 §3.2.2): its master's
// index, the coupling factor and the offset taken from the coupling positions.
//
// Each cycle the slave reads its master's AxisSnapshot of the SAME cycle (the kernel computes
// masters first, CouplingGraph::order()) and takes
//   p = factor · master p + offset,  v = factor · master v,  a = factor · master a.
// Plain data; cycle functions only (noexcept, no allocation).
#pragma once

#include <cstdint>

#include "nc_core/axis_snapshot.hpp"
#include "nc_core/profile.hpp"

namespace nc::detail {

struct SlaveLink {
  bool coupled = false;
  bool retake_offset = false;  // the offset is taken again from the positions in the next sample
  // SPEC C7 DELAYED: the slave left this coupling on its own error (coupled is false); the link
  // stays in the coupling graph, so the group is still known, until MC_GearOut.
  bool detached = false;
  uint32_t master = 0;   // kernel index of the master
  uint16_t command = 0;  // the MC_GearIn command number in force (CmdNo while coupled)
  double factor = 1.0;
  double offset = 0.0;

  // Couples at the slave position `slave_p` to a master standing at `master_p`.
  void couple(uint32_t master_index, uint16_t number, double ratio, double slave_p,
              double master_p) noexcept {
    coupled = true;
    retake_offset = false;
    detached = false;
    master = master_index;
    command = number;
    factor = ratio;
    offset = slave_p - ratio * master_p;
  }

  // The slave's set values from its master's set values of this cycle. `slave_p` is the slave's
  // set position, used only when the offset is to be taken again.
  KinematicState sample(const AxisSnapshot& m, double slave_p) noexcept {
    if (retake_offset) {
      offset = slave_p - factor * m.set_position;
      retake_offset = false;
    }
    return KinematicState{factor * m.set_position + offset, factor * m.set_velocity,
                          factor * m.set_acceleration};
  }
};

}  // namespace nc::detail
