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
  stop_.reserve(n);
  auto referenced = std::make_unique<bool[]>(n);
  std::fill(referenced.get(), referenced.get() + n, true);
  plc::hli::HLI_AX& unit = stage_.add_axis(hli::axis_setup(effective));  // throws before growing
  for (std::vector<double>* v : {&q_, &qv_, &qa_, &d_, &dv_, &da_})
    v->push_back(0.0);
  stop_.push_back(plc::ErrorCode::kNone);
  referenced_ = std::move(referenced);
  return unit;
}

double HliPhase::command_position_request(int ax_nr) const noexcept {
  const std::size_t axis = stage_.index_of(ax_nr);
  if (axis == hli::HliStage::kNoAxis) return std::numeric_limits<double>::quiet_NaN();
  return stage_.command_position_request(axis);
}

bool HliPhase::begin_cycle() noexcept {
  if (!engaged_) {
    for (const plc::hli::HLI_AX* unit : stage_.gpAx()) {
      if (unit->lr_mc_control.axis_coupling.command_w.semaphor_rw) {
        engaged_ = true;
        break;
      }
    }
  }
  return engaged_;
}

void HliPhase::run(std::span<const std::unique_ptr<ServoAxis>> axes,
                   std::span<const AxisSnapshot> snapshots) noexcept {
  const std::size_t n = axes.size();
  for (std::size_t i = 0; i < n; ++i) {
    q_[i] = snapshots[i].set_position;
    qv_[i] = snapshots[i].set_velocity;
    qa_[i] = snapshots[i].set_acceleration;
    // The homed bit as last published (AxisConfig::homed_at_start, MC_Home).
    referenced_[i] = plc::test_bit(axes[i]->ref().NcToPlc.StateDWord, plc::kStateHomed);
  }
  const hli::Inputs in{q_, qv_, qa_, std::span<const bool>(referenced_.get(), n)};
  const hli::Outputs out{d_, dv_, da_, stop_};
  if (!stage_.cycle(in, out)) return;  // sizes always match: every axis was added here
  bool engaged = false;
  for (std::size_t i = 0; i < n; ++i) {
    axes[i]->phase_drive_command(KinematicState{d_[i], dv_[i], da_[i]}, stop_[i]);
    engaged = engaged || d_[i] != q_[i] || stage_.coupled(i) || stage_.braking(i);
  }
  engaged_ = engaged;
}

}  // namespace nc::detail
