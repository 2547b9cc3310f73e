// MC_ExtSetPointGenFeed: feeds one setpoint packet of a PLC-side setpoint generator into the
// cyclic axis interface (seed 000 §2.6 "Specification of setpoints", SPEC B8).
//
// A FUNCTION, as in Tc2_MC2: call it every PLC cycle while external setpoint generation is
// enabled (MC_ExtSetPointGenEnable). It copies Position, Velocity, Acceleration and Direction into
// PlcToNc.ExtSetPos / ExtSetVelo / ExtSetAcc / ExtSetDirection at once; the NC reads them in its
// next cycle. The NC takes a packet only while Direction is -1 or +1 (0 = standstill: the set
// position is taken for exactly one more cycle, then held), so set the direction one cycle before
// and one cycle after the motion (seed 000 §2.6). Cycle function: no allocation, no exceptions.
//
// Result: Tc2_MC2's result is unused and always FALSE. Here it is an ErrorID, so it still reads
// FALSE (0) whenever the packet is written: 0x4F07 (kDirectionInvalid) when Direction is not -1,
// 0 or +1 — the NC cannot tell a bad direction from a meant one — and then nothing is written
// (the NC keeps what it had). Positions and the other values are passed unchecked: the NC
// validates them.
#pragma once

#include <cstdint>

#include "plc_interface/axis_ref.hpp"

namespace fb {

uint32_t MC_ExtSetPointGenFeed(double Position, double Velocity, double Acceleration,
                               int32_t Direction, plc::AXIS_REF& Axis) noexcept;

}  // namespace fb
