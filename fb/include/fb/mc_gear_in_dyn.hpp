// MC_GearInDyn: couples the slave to the master as a cyclic slave (SPEC C6, seed 000 §3.3): the
// factor comes from the PLC every cycle and the NC smooths it so that the slave's acceleration
// stays within AccBound (the Acceleration input).
//
// Enable-type block. Every call writes GearRatio into the slave's PlcToNc.GearRatio1 (the NC
// reads it every cycle; 0, NaN, inf or above 1e6 in size are not taken there: warning 0x4F81).
// Enable rising: the coupling command goes to the slave's mailbox with the master's
// NcToPlc.AxisIndex, GearRatio as the first factor and Acceleration as AccBound (latched then);
// the NC refuses a bad one with its code and changes nothing (docs/behaviour.md "Cyclic slave").
// Busy and Active while coupled; InGear while the factor in force (the slave's NcToPlc.GearRatio)
// equals GearRatio. Enable falling while coupled: the slave decouples as with MC_GearOut (in
// motion it goes on as a master, SPEC C4); Busy until the NC has done it, Error with its code if
// the NC refuses the decoupling. The coupling ending otherwise (MC_GearOut, another MC_GearIn:
// CommandAborted; an error) shows as an Execute-type block's result while Enable stays high.
// BufferMode other than MC_Aborting is refused here (0x4F03); Deceleration and Jerk are not used
// (kept for the Tc2_MC2 interface). Cycle function: no allocation, no exceptions.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "fb/types.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_GearInDyn {
 public:
  // Inputs. GearRatio is written every call; the others are latched when Enable rises.
  bool Enable = false;
  double GearRatio = 1.0;
  double Acceleration = 0.0;  // AccBound (mm/s²), > 0
  double Deceleration = 0.0;
  double Jerk = 0.0;
  MC_BufferMode BufferMode = MC_Aborting;

  // Outputs.
  bool InGear = false;
  bool Busy = false;
  bool Active = false;
  bool CommandAborted = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(const plc::AXIS_REF& master, plc::AXIS_REF& slave) noexcept;

  uint16_t command_number() const noexcept { return couple_.command_number(); }

 private:
  detail::ExecuteBlock couple_{};
  detail::ExecuteBlock decouple_{};
  bool previous_enable_ = false;
  bool decoupling_ = false;  // Enable fell while coupled: the decoupling's Execute
};

}  // namespace fb
