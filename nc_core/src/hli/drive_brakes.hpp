// A stopped HLI target's drive (SPEC D3, D4): its list goes off and the drive brakes from its
// velocity at the emergency deceleration, then follows its own program from where it stands;
// and the 70195 check of a FRACT target on a referenced axis against its software limits.
//
// A view on the stage's HliState for one call (it owns nothing); defined in hli_stage.cpp next to
// the cycle that calls it. Cycle functions: noexcept, no allocation.
#pragma once

#include <cstddef>

#include "hli/hli_state.hpp"

namespace nc::hli {

class DriveBrakes : public HliPart {
 public:
  using HliPart::HliPart;

  // HliStage::stop: the axis's list goes off and its drive brakes.
  void brake(std::size_t axis) noexcept;
  // brake(), and `code` is the axis error the kernel raises (Outputs::stop) and error_r.
  void halt(std::size_t axis, plc::ErrorCode code, const Outputs& out) noexcept;
  // One cycle of a braking axis's drive (kept in c).
  void advance_brake(std::size_t axis) noexcept;
  // A FRACT target can no longer stop before its software limit (v²/2a from next cycle's state).
  bool cannot_stop_before_limit(std::size_t axis) const noexcept;
};

}  // namespace nc::hli
