// Enumerations of the PLCopen / Tc2_MC2 block inputs, with Tc2_MC2's names and values.
//
// They are the values a PLC programmer types (MC_Positive_Direction, MC_Aborting); blocks pass
// them to the NC unchanged in plc::Command (direction, mode, buffer_mode). They are defined once
// in the contract (plc_interface/command.hpp) and re-exported here under their fb names.
#pragma once

#include "plc_interface/command.hpp"

namespace fb {

using plc::MC_Current_Direction;
using plc::MC_Direction;
using plc::MC_Negative_Direction;
using plc::MC_Positive_Direction;
using plc::MC_Shortest_Way;
using plc::MC_Undefined_Direction;

using plc::E_PositionType;
using plc::POSITIONTYPE_ABSOLUTE;
using plc::POSITIONTYPE_RELATIVE;

using plc::MC_Aborting;
using plc::MC_BlendingHigh;
using plc::MC_BlendingLow;
using plc::MC_BlendingNext;
using plc::MC_BlendingPrevious;
using plc::MC_Buffered;
using plc::MC_BufferMode;

using plc::DEFAULT_HOME_POSITION;
using plc::MC_AbsSwitch;
using plc::MC_DefaultHoming;
using plc::MC_Direct;
using plc::MC_ForceCalibration;
using plc::MC_HomingMode;
using plc::MC_LimitSwitch;
using plc::MC_RefPulse;
using plc::MC_ResetCalibration;

}  // namespace fb
