// The rules an HLI control unit (plc::hli::HLI_AX, docs/behaviour.md "HLI axis coupling") keeps
// after every NC cycle, checked by fuzz_blocks' HLI programs:
//  - the semaphore is reset: a list is evaluated in the first NC cycle that sees semaphor_rw;
//  - state_r.error_r is 0 or one of the documented IDs (the kernel's refusals 0x4F06, 0x4223,
//    0x424E; 0x4040 for a two-speed axis; the list's checks 0x4B06, 0x4F08, 70396, 70397, 70410;
//    70200 and 70195, which stop the target);
//  - state_r.desc shows the entries in force (a known ax_nr and a mode ZERO … FRACT) up to the
//    first empty one and nothing after it, and nothing at all while active_r is FALSE.
// Fixed-size, no allocation: nullptr when the unit holds, else what broke.
#pragma once

#include <cstdint>
#include <span>

#include "fail.hpp"
#include "plc_interface/error_code.hpp"
#include "plc_interface/hli.hpp"

namespace fuzz {

// An ID the kernel documents for state_r.error_r (and so for HLI_AxisCoupling's ErrorID, which
// may also be 0x4F08 for a null unit).
FUZZ_CHECKER inline bool documented_hli_id(uint32_t id) noexcept {
  using plc::ErrorCode;
  for (const ErrorCode code :
       {ErrorCode::kNone, ErrorCode::kAxisInErrorState, ErrorCode::kNoControllerOrFeedEnable,
        ErrorCode::kFunctionNotAllowed, ErrorCode::kAxisKindNotAllowed,
        ErrorCode::kBlockInputOutOfRange, ErrorCode::kInvalidAxisReference,
        ErrorCode::kHliDenominatorZero, ErrorCode::kHliFactorTooLarge, ErrorCode::kHliCouplingLoop,
        ErrorCode::kHliChangeWhileMoving, ErrorCode::kHliFractOnReferencedAxis}) {
    if (id == plc::to_id(code)) return true;
  }
  return false;
}

// `ids`: the kernel's logical axis numbers (AxisConfig::id, in axis order).
FUZZ_CHECKER inline const char* broken_hli_unit(const plc::hli::HLI_AX& unit,
                                                std::span<const int> ids) noexcept {
  namespace h = plc::hli;
  const h::HLI_AX_COUPLING& c = unit.lr_mc_control.axis_coupling;
  if (c.command_w.semaphor_rw) return "an HLI list is not evaluated in the NC cycle that sees it";
  if (!documented_hli_id(c.state_r.error_r)) return "HLI error_r is not a documented ID";
  bool ended = !c.state_r.active_r;
  for (const h::HLI_AX_COUPLING_STATE_DESC& d : c.state_r.desc) {
    if (ended) {
      if (d.ax_nr != 0 || d.mode != h::HLI_AXIS_COUPLING_INACTIVE) {
        return "HLI state shows an entry after the list's end or without a list in force";
      }
      continue;
    }
    if (d.mode == h::HLI_AXIS_COUPLING_INACTIVE) {
      if (d.ax_nr != 0) return "HLI state shows an empty entry with an axis number";
      ended = true;
      continue;
    }
    if (d.mode > h::HLI_AXIS_COUPLING_FRACT) return "HLI state shows an unknown mode";
    bool known = false;
    for (const int id : ids)
      known = known || id == d.ax_nr;
    if (!known) return "HLI state shows an unknown axis number";
  }
  return nullptr;
}

}  // namespace fuzz
