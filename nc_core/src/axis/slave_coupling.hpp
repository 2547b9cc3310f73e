// A linear or cyclic slave's coupling (SPEC C1-C4, C6; seed 000 §3.2.2-3.2.3, §3.3): MC_GearIn,
// MC_GearInDyn and MC_GearOut on the slave, their checks in the order of docs/behaviour.md "Slave
// axes", the online decoupling chain, and phase b's smoothing of a cyclic slave's factor.
//
// A view on one axis's AxisCore for one call (it owns nothing); the commands reach the master
// through the kernel's CouplingPort. Cycle functions: noexcept, no allocation; a refused command
// changes nothing (every check runs before the graph or the link is written).
#pragma once

#include <cstdint>

#include "axis/axis_core.hpp"
#include "nc_core/axis_snapshot.hpp"
#include "plc_interface/command.hpp"

namespace nc::detail {

struct CouplingPort;

class SlaveCoupling : public AxisPart {
 public:
  using AxisPart::AxisPart;

  ErrorCode gear_in(const plc::Command& command, CouplingPort& port) noexcept;
  ErrorCode gear_in_dyn(const plc::Command& command, CouplingPort& port) noexcept;
  // MC_GearOut; a slave that left its master on its own error (C7 DELAYED) leaves the graph.
  ErrorCode gear_out(const plc::Command& command, CouplingPort& port) noexcept;
  // A coupled slave refuses this command (0x424E): starts, stops, new positions and external
  // setpoint generation (compensation is allowed: C5).
  static bool refused_while_coupled(plc::CommandType type) noexcept;
  // Phase b of a cyclic slave, before its sample: PlcToNc.GearRatio1 read (not taken when 0,
  // NaN, inf or above 1e6: warning 0x4F81) and the factor in force moved towards it within
  // AccBound (the smoothing law of docs/behaviour.md "Cyclic slave").
  void step_cyclic_factor(const AxisSnapshot& master) noexcept;

 private:
  // The checks shared by MC_GearIn and MC_GearInDyn: the factor (finite, not 0, |factor| <=
  // 1e6); the slave's kind and the master index; for a new coupling: loop, error, lock, enable,
  // both at rest.
  static ErrorCode check_gear_ratio(double ratio) noexcept;
  ErrorCode check_gear_master(const plc::Command& command, CouplingPort& port) const noexcept;
  ErrorCode check_new_coupling(uint32_t master_index, CouplingPort& port) const noexcept;
  // A checked new coupling: graph, counts, slave link (linear, factor command.ratio), answered
  // kActive. False only when the graph refuses (a loop; checked before).
  bool couple_new(const plc::Command& command, uint32_t master_index, CouplingPort& port) noexcept;
  // The largest acceleration the axis's set values can have (mm/s²): max(A+, A-) of a master,
  // through its cascade for a slave (|factor| × its master's; a cyclic slave at least AccBound).
  double max_acceleration(const CouplingPort& port) const noexcept;
  // Online decoupling: the levels from the head of this slave's cascade down to it, and the
  // head. False (0x424D) when the head runs no PTP job or the cascade is too deep.
  bool decoupling_chain(CouplingPort& port, DecouplingChain& chain,
                        const AxisCore*& head) const noexcept;
  // At rest for a coupling: no job, set velocity and acceleration 0, no compensation running,
  // no external generation enabled (seed 000 §3.2.2 "both axes are stationary").
  bool at_rest_for_coupling() const noexcept;
  // MC_GearOut of a slave that left its master on its own error: the link leaves the graph.
  ErrorCode release_detached(const plc::Command& command, CouplingPort& port) noexcept;
};

}  // namespace nc::detail
