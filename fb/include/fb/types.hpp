// Enumerations of the PLCopen / Tc2_MC2 block inputs, with Tc2_MC2's names and values.
//
// They are the values a PLC programmer types (MC_Positive_Direction, MC_Aborting); blocks pass
// them to the NC unchanged in plc::Command (direction, mode), so the numbers are part of the
// PLC↔NC contract and must not be renumbered.
#pragma once

#include <cstdint>

namespace fb {

enum MC_Direction : int32_t {
  MC_Positive_Direction = 1,
  MC_Shortest_Way = 2,
  MC_Negative_Direction = 3,
  MC_Current_Direction = 4,
  MC_Undefined_Direction = 128,
};

enum E_PositionType : int32_t {
  POSITIONTYPE_ABSOLUTE = 1,
  POSITIONTYPE_RELATIVE = 2,
};

enum MC_BufferMode : int32_t {
  MC_Aborting = 0,
  MC_Buffered = 1,
  MC_BlendingLow = 2,
  MC_BlendingPrevious = 3,
  MC_BlendingNext = 4,
  MC_BlendingHigh = 5,
};

}  // namespace fb
