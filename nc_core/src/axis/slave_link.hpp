// The set-value source of a coupled slave (SPEC C1, C6; seed 000 §3.2.2, §3.3): its master's
// index, the coupling factor in force and the offset taken from the coupling positions.
//
// Each cycle the slave reads its master's AxisSnapshot of the SAME cycle (the kernel computes
// masters first, CouplingGraph::order()) and takes
//   p = factor · master p + offset,  v = factor · master v,  a = factor · master a
// (+ rate · master v for a cyclic slave, rate = d factor / dt). A cyclic slave (MC_GearInDyn)
// moves its factor in force towards the PLC's commanded one with set_factor(); the offset is
// re-set with it so that the slave's position is continuous: offset = slave p(k−1) − factor(k) ·
// master p(k−1), so it moves factor(k) · (master p(k) − master p(k−1)) in that cycle. Plain data;
// cycle functions only (noexcept, no allocation).
#pragma once

#include <cstdint>

#include "nc_core/axis_snapshot.hpp"
#include "nc_core/profile.hpp"

namespace nc::detail {

struct SlaveLink {
  bool coupled = false;
  bool retake_offset = false;  // the offset is taken again from the positions in the next sample
  bool cyclic = false;         // MC_GearInDyn: the factor follows PlcToNc.GearRatio1
  // SPEC C7 DELAYED: the slave left this coupling on its own error (coupled is false); the link
  // stays in the coupling graph, so the group is still known, until MC_GearOut.
  bool detached = false;
  uint32_t master = 0;   // kernel index of the master
  uint16_t command = 0;  // the MC_GearIn / MC_GearInDyn command number in force (CmdNo)
  double factor = 1.0;   // the factor in force
  double offset = 0.0;
  double master_p = 0.0;  // the master's set position of the last sample
  double slave_p = 0.0;   // the slave's basic set position of the last sample
  // Cyclic slave only: d factor / dt of this cycle (1/s), the factor the PLC commands, the
  // acceleration bound (AccBound, mm/s²) and the master's largest acceleration through its
  // cascade as at the coupling (mm/s²).
  double rate = 0.0;
  double commanded = 1.0;
  double acc_bound = 0.0;
  double master_acceleration = 0.0;

  // Couples (linear) at the slave position `slave_position` to a master at `master_position`.
  void couple(uint32_t master_index, uint16_t number, double ratio, double slave_position,
              double master_position) noexcept {
    coupled = true;
    retake_offset = false;
    cyclic = false;
    detached = false;
    master = master_index;
    command = number;
    factor = ratio;
    commanded = ratio;
    rate = 0.0;
    offset = slave_position - ratio * master_position;
    master_p = master_position;
    slave_p = slave_position;
  }

  // Cyclic slave: the factor in force becomes `next` in this cycle, at `next_rate` (1/s); the
  // offset keeps the slave's position continuous from the last sample on.
  void set_factor(double next, double next_rate) noexcept {
    rate = next_rate;
    if (next == factor) return;
    offset = slave_p - next * master_p;
    factor = next;
  }

  // The slave's set values from its master's set values of this cycle. `set_p` is the slave's
  // set position, used only when the offset is to be taken again.
  KinematicState sample(const AxisSnapshot& m, double set_p) noexcept {
    const double mp = m.followed_position();
    const double mv = m.followed_velocity();
    if (retake_offset) {
      offset = set_p - factor * mp;
      retake_offset = false;
    }
    master_p = mp;
    slave_p = factor * mp + offset;
    const double a = factor * m.followed_acceleration();
    return KinematicState{slave_p, factor * mv, cyclic ? a + rate * mv : a};
  }
};

}  // namespace nc::detail
