// Phase (c): the HLI coupling stage over the kernel's axes (docs/behaviour.md "HLI axis
// coupling").
#include "kernel/hli_phase.hpp"

#include <algorithm>
#include <limits>

#include "axis/servo_axis.hpp"
#include "plc_interface/axis_ref.hpp"

namespace nc::detail {

plc::hli::HLI_AX& HliPhase::add_axis(const AxisConfig& effective) {
  const std::size_t n = stage_.size() + 1;
  for (std::vector<double>* v : {&q_, &qv_, &qa_, &d_, &dv_, &da_})
    v->reserve(n);
  for (std::vector<plc::ErrorCode>* v : {&stop_, &refusal_, &pending_})
    v->reserve(n);
  errors_seen_.reserve(n);
  auto referenced = std::make_unique<bool[]>(n);
  std::fill(referenced.get(), referenced.get() + n, true);
  plc::hli::HLI_AX& unit = stage_.add_axis(hli::axis_setup(effective));  // throws before growing
  for (std::vector<double>* v : {&q_, &qv_, &qa_, &d_, &dv_, &da_})
    v->push_back(0.0);
  for (std::vector<plc::ErrorCode>* v : {&stop_, &refusal_, &pending_})
    v->push_back(plc::ErrorCode::kNone);
  errors_seen_.push_back(0);
  referenced_ = std::move(referenced);
  return unit;
}

double HliPhase::command_position_request(
    int ax_nr, std::span<const std::unique_ptr<ServoAxis>> axes) const noexcept {
  const std::size_t axis = stage_.index_of(ax_nr);
  if (axis == hli::HliStage::kNoAxis) return std::numeric_limits<double>::quiet_NaN();
  if (!engaged_) return axes[axis]->ref().NcToPlc.SetPos;
  return stage_.command_position_request(axis);
}

namespace {

// K26: the axis's drive went off in this cycle under a program in motion: it has no controller
// enable, and its snapshot still shows the last cycle's set values, which moved (from phase (d)
// on its program position follows its actual one, at velocity 0).
bool drive_went_off(const AxisSnapshot& s) noexcept {
  return !s.controller_enabled && (s.set_velocity != 0.0 || s.set_acceleration != 0.0);
}

// A source of `target`'s list in force (not the target itself) whose drive went off.
bool follows_drive_gone(const hli::HliStage& stage, std::size_t target,
                        std::span<const AxisSnapshot> snapshots) noexcept {
  for (std::size_t j = 0; j < snapshots.size(); ++j) {
    if (j != target && drive_went_off(snapshots[j]) && stage.factor(target, j) != 0.0) return true;
  }
  return false;
}

}  // namespace

bool HliPhase::begin_cycle() noexcept {
  if (!engaged_ && handed_out_) {
    for (const plc::hli::HLI_AX* unit : stage_.gpAx()) {
      if (unit->lr_mc_control.axis_coupling.command_w.semaphor_rw) {
        engaged_ = true;
        break;
      }
    }
  }
  return engaged_;
}

plc::ErrorCode HliPhase::refusal(const ServoAxis& axis) noexcept {
  if (axis.core().channel_.has_error()) return plc::ErrorCode::kAxisInErrorState;
  if (!axis.core().channel_.controller_enabled()) return plc::ErrorCode::kNoControllerOrFeedEnable;
  if (axis.core().stack_.external.enabled()) return plc::ErrorCode::kFunctionNotAllowed;
  return plc::ErrorCode::kNone;
}

plc::CoupleState HliPhase::role(std::size_t axis) const noexcept {
  const bool target = stage_.coupled(axis);
  const bool source = stage_.source_of_other(axis);
  if (target) return source ? plc::CoupleState::kMasterAndSlave : plc::CoupleState::kSlave;
  return source ? plc::CoupleState::kMaster : plc::CoupleState::kSingle;
}

void HliPhase::run(std::span<const std::unique_ptr<ServoAxis>> axes,
                   std::span<const AxisSnapshot> snapshots) noexcept {
  const std::size_t n = axes.size();
  const bool drive_gone = std::any_of(snapshots.begin(), snapshots.end(), drive_went_off);
  for (std::size_t i = 0; i < n; ++i) {
    q_[i] = snapshots[i].set_position;
    qv_[i] = snapshots[i].set_velocity;
    qa_[i] = snapshots[i].set_acceleration;
    // The homed bit as last published (AxisConfig::homed_at_start, MC_Home).
    referenced_[i] = plc::test_bit(axes[i]->ref().NcToPlc.StateDWord, plc::kStateHomed);
    refusal_[i] = refusal(*axes[i]);
    pending_[i] = plc::ErrorCode::kNone;
    // A target in axis error (raised in phases (a), (b) of this cycle or (e) of the last one,
    // also one MC_Reset has cleared since) loses its list: its drive brakes from where it is
    // instead of following its sources. Without its drive (controller enable off) the list goes
    // off too, without a ramp to brake on — also when the lost enable already raised an error
    // (0x4260 of a job of its own) — and a brake still running ends: otherwise the stage would
    // brake a drive that is off and hand its far position over when the enable returns (fuzz
    // finding K22). Losing the enable while the drive moves is an axis error, as during a job.
    // (A target was coupled at the last phase (c): errors_seen_ is that phase's count.)
    const uint32_t raised = axes[i]->core().errors_raised_;
    const bool new_error = raised != errors_seen_[i];
    errors_seen_[i] = raised;
    if (!stage_.coupled(i) && !stage_.braking(i)) continue;
    if (!axes[i]->core().channel_.controller_enabled()) {
      if (stage_.coupled(i) && dv_[i] != 0.0) {
        pending_[i] = plc::ErrorCode::kControllerEnableMissing;
      }
      stage_.release(i);
    } else if (stage_.coupled(i) && (axes[i]->core().channel_.has_error() || new_error)) {
      stage_.stop(i);
    } else if (drive_gone && stage_.coupled(i) && follows_drive_gone(stage_, i, snapshots)) {
      // K26: a source's drive went off under its program motion, which from now on follows that
      // drive's actual position; the target does not follow it there (a step of K × the source's
      // velocity and following error) but leaves its list and brakes on its emergency ramp, with
      // the coupled axis's lost enable as its error.
      pending_[i] = plc::ErrorCode::kControllerEnableLost;
      stage_.stop(i);
    }
  }
  const hli::Inputs in{q_, qv_, qa_, std::span<const bool>(referenced_.get(), n), refusal_};
  const hli::Outputs out{d_, dv_, da_, stop_};
  if (!stage_.cycle(in, out)) return;  // sizes always match: every axis was added here
  bool engaged = false;
  for (std::size_t i = 0; i < n; ++i) {
    const plc::ErrorCode stop = stop_[i] != plc::ErrorCode::kNone ? stop_[i] : pending_[i];
    axes[i]->phase_drive_command(KinematicState{d_[i], dv_[i], da_[i]}, stop, role(i));
    engaged = engaged || d_[i] != q_[i] || stage_.coupled(i) || stage_.braking(i);
  }
  engaged_ = engaged;
}

}  // namespace nc::detail
