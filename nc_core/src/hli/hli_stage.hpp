// The HLI axis-coupling stage (SPEC D2–D5, seed 002): phase (c) of the NC cycle.
//
// Every axis has a program position q (what its own motion commands) and a drive command
// position d. The stage owns each axis's HLI control unit (plc::hli::HLI_AX, what gpAx[i] points
// to) and maps q to d with one coupling matrix over all axes: d = K·q + c (Eigen, dense,
// row-major; only the targets' rows are stored and multiplied, packed at the top, so the cost
// per cycle is (number of targets) × (number of axes)). An axis without a list has the unit row
// (d = q + offset, not stored); a target's row holds its factors, and c is set when the list is
// taken so that d does not jump:
// d = d(activation) + Σ K·(q_source − q_source(activation)). Sources contribute program movement,
// never drive movement, so there are no chains. The stage evaluates a list in the cycle the PLC
// sets semaphor_rw and resets the semaphore in that same cycle; refused lists change nothing
// (error_r says why), 70200 and 70195 stop the target (its list off, its drive braking at the
// emergency deceleration; Outputs::stop tells the kernel to raise the axis error).
// Set-up functions (constructor, reserve, add_axis) may allocate and throw; cycle(), stop() and
// the queries are noexcept and allocate nothing (the matrix is sized in add_axis).
// The stage runs the cycle over its state (HliState, hli_state.hpp); its parts are the matrix
// (CouplingMatrix), the lists (ListEvaluation) and the brakes of stopped targets (DriveBrakes).
#pragma once

#include <cstddef>
#include <span>

#include "hli/hli_state.hpp"
#include "plc_interface/error_code.hpp"
#include "plc_interface/hli.hpp"

namespace nc::hli {

class HliStage : private HliState {
 public:
  using HliState::index_of;
  using HliState::kListSize;
  using HliState::kNoAxis;
  using HliState::size;

  explicit HliStage(double cycle_time);  // s, > 0; throws std::invalid_argument

  // Set-up: room for `axes` axes without reallocating the per-axis storage later.
  void reserve(std::size_t axes);
  // Set-up: adds an axis (index = size() before the call); the control unit's address stays
  // valid for the stage's life. Throws std::invalid_argument for ax_nr 0 or a repeated ax_nr,
  // a deceleration <= 0 or non-finite values.
  plc::hli::HLI_AX& add_axis(const AxisSetup& setup);

  // gpAx[axis_idx] of the seed: pointers to the control units, indexed by axis index.
  std::span<plc::hli::HLI_AX* const> gpAx() const noexcept { return pointers_; }
  plc::hli::HLI_AX& unit(std::size_t axis) noexcept { return *pointers_[axis]; }

  // Cycle: computes d for every axis, evaluates the lists whose semaphore is set, monitors
  // FRACT targets against their software limits. False (and nothing done) when a span's size
  // differs from size().
  bool cycle(const Inputs& in, const Outputs& out) noexcept;

  // Cycle: the axis is stopped (the kernel calls this when it stops a target for its own
  // reasons): its list goes off and its drive brakes from its current velocity at the emergency
  // deceleration, then follows its own program motion from where it stands.
  void stop(std::size_t axis) noexcept;
  // Cycle: the target's drive is off (no controller enable): its list goes off without braking,
  // as a list switched off by the PLC (d stays, then follows the axis's own program); a brake
  // still running ends there too (a drive that is off has no ramp). No-op for a free axis.
  void release(std::size_t axis) noexcept;

  // The program coordinate #CHANNEL INIT [CMDPOS] would give the axis now (D5): the drive
  // position d by default; with P-AXIS-00436 the q for which the target's list gives d, relative
  // to the activation positions, or with P-AXIS-00460 as if coupled at position 0.
  double command_position_request(std::size_t axis) const noexcept;

  bool coupled(std::size_t axis) const noexcept { return targets_[axis].state == State::kCoupled; }
  // The axis is a source of another axis's list in force (its self entry does not count).
  bool source_of_other(std::size_t axis) const noexcept { return source_uses_[axis] > 0; }
  bool braking(std::size_t axis) const noexcept { return targets_[axis].state == State::kBraking; }
  // K(target, source) in force: the unit row for an axis without a list, 0 while braking.
  double factor(std::size_t target, std::size_t source) const noexcept;
};

}  // namespace nc::hli
