// A coupling list the PLC hands to the HLI stage (SPEC D2, D4): parsed from command_w, refused
// (error_r says why, the list in force stays), refused with a stop (70200: an involved axis
// moves), or taken into the target's row of the coupling matrix so that d does not jump; and the
// list in force shown in state_r.
//
// A view on the stage's HliState for one call (it owns nothing). Cycle functions: noexcept, no
// allocation (the loop check's scratch is reserved in HliStage::add_axis).
#pragma once

#include <cstddef>

#include "hli/hli_state.hpp"

namespace nc::hli {

class ListEvaluation : public HliPart {
 public:
  using HliPart::HliPart;

  // The target's semaphore is set: its list is evaluated now (and the semaphore reset).
  // `refusal`: the kernel's reason to refuse any list on it (kNone: none).
  void evaluate(std::size_t target, plc::ErrorCode refusal, const Outputs& out) noexcept;
  // The target's list in force is replaced by `list` (empty: switched off; d stays).
  void take(std::size_t target, const HliState::Candidate& list) noexcept;
  // state_r shows the target's list in force.
  void publish(std::size_t axis) noexcept;
  // Counts t's sources other than `target` itself in source_uses_ (add) or out of it.
  void count_sources(std::size_t target, const HliState::Target& t, bool add) noexcept;

 private:
  plc::ErrorCode parse(const plc::hli::HLI_AX_COUPLING_COMMAND& command,
                       HliState::Candidate& list) const noexcept;
  bool makes_loop(std::size_t target, const HliState::Candidate& list) noexcept;
  bool involved_axis_moves(std::size_t target, const HliState::Candidate& list) const noexcept;
};

}  // namespace nc::hli
