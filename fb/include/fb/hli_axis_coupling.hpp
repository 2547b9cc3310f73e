// HLI_AxisCoupling: writes a coupling list into an axis's HLI control unit and triggers its
// evaluation (SPEC D1, seed 002 §2 "Activation"), as a block with the project's Execute rules.
//
// Not a PLCopen block, hence no MC_ prefix; HLI_ as in the seed's names (HLI_AXIS_COUPLING_*),
// so that a PLC programmer finds it beside the control unit it drives. Called with the unit
// (gpAx[axis_idx], or *gpAx[axis_idx]). On a rising edge of Execute the block latches `desc`
// (entries up to the first HLI_AXIS_COUPLING_INACTIVE are the list, as in command_w.desc) and,
// once command_w.semaphor_rw is free (another writer's list may still be pending), copies it into
// command_w.desc and sets semaphor_rw. When the NC has reset the semaphore it shows Done if
// state_r.error_r is 0, else Error with ErrorID = error_r (70396, 70397, 70410, 70200, …). Busy
// in between. Output rules as fb/detail/execute_block.hpp: Busy, Done and Error exclusive; a
// result stays while Execute is high, or is shown for one call if Execute fell before it; a
// rising edge while Busy starts nothing. A null unit gives Error 0x4F08.
// Cycle function: no allocation, no exceptions.
#pragma once

#include <array>
#include <cstdint>

#include "plc_interface/hli.hpp"

namespace fb {

class HLI_AxisCoupling {
 public:
  // Inputs.
  bool Execute = false;
  std::array<plc::hli::HLI_AX_COUPLING_DESC, plc::hli::HLI_AX_COUPLING_MAXIDX + 1> desc{};

  // Outputs.
  bool Done = false;
  bool Busy = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  void operator()(plc::hli::HLI_AX& unit) noexcept;
  void operator()(plc::hli::HLI_AX* unit) noexcept;

 private:
  enum class Phase : uint8_t { kIdle, kWaiting, kWritten, kResult };

  // Edge detection and the reset of a result already shown; true when a list is to start.
  bool begin_call() noexcept;
  void show() noexcept;

  Phase phase_ = Phase::kIdle;
  bool previous_execute_ = false;
  uint32_t result_id_ = 0;  // 0 = Done
  std::array<plc::hli::HLI_AX_COUPLING_DESC, plc::hli::HLI_AX_COUPLING_MAXIDX + 1> latched_{};
};

}  // namespace fb
