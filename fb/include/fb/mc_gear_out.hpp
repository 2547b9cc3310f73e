// MC_GearOut: decouples a linear slave from its master (SPEC C4, seed 000 §3.2.3).
//
// Execute-type block (rules in fb/detail/execute_block.hpp). At rest the slave becomes a PTP
// master holding its set position; in motion a master that goes on as it would have as a slave
// (online decoupling). Done in the cycle the NC's answer arrives (the next NC cycle),
// NcToPlc.CoupleState 0 then. An axis that is not a coupled slave: 0x424D.
#pragma once

#include <cstdint>

#include "fb/detail/execute_block.hpp"
#include "plc_interface/axis_ref.hpp"

namespace fb {

class MC_GearOut {
 public:
  // Input.
  bool Execute = false;

  // Outputs.
  bool Done = false;
  bool Busy = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  // Cycle function: runs the block once.
  void operator()(plc::AXIS_REF& slave) noexcept;

  uint16_t command_number() const noexcept { return block_.command_number(); }

 private:
  detail::ExecuteBlock block_;
};

}  // namespace fb
