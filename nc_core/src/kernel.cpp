#include "nc_core/kernel.hpp"

#include <algorithm>
#include <span>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "axis/group_errors.hpp"
#include "axis/servo_axis.hpp"
#include "homing/axis_homing.hpp"
#include "kernel/hli_phase.hpp"
#include "nc_core/config.hpp"
#include "nc_core/profile.hpp"

namespace nc {

Kernel::Kernel(KernelConfig config) : config_(config) {
  validate(config_);
  hli_ = std::make_unique<detail::HliPhase>(config_.cycle_time);
}

Kernel::~Kernel() = default;
Kernel::Kernel(Kernel&&) noexcept = default;
Kernel& Kernel::operator=(Kernel&&) noexcept = default;

Kernel Kernel::from_json(const nlohmann::json& document) {
  KernelSetup setup = parse_kernel_setup(document);
  Kernel kernel(setup.kernel);
  for (std::size_t i = 0; i < setup.axes.size(); ++i) {
    try {
      kernel.add_axis(setup.axes[i]);
    } catch (const ConfigError& e) {
      throw e.prefixed("/axes/" + std::to_string(i));
    }
  }
  return kernel;
}

plc::AXIS_REF& Kernel::add_axis(const AxisConfig& config) {
  validate(config);
  AxisConfig effective = config;
  if (effective.id == 0) effective.id = static_cast<int>(axes_.size()) + 1;
  for (const auto& other : axes_) {
    if (other->config().name == effective.name) {
      throw ConfigError("/name", "must be unique in the kernel", effective.name);
    }
    if (other->config().id == effective.id) {
      throw ConfigError("/id", "must be unique in the kernel", std::to_string(effective.id));
    }
  }
  axes_.reserve(axes_.size() + 1);
  snapshots_.reserve(axes_.size() + 1);
  auto axis =
      std::make_unique<detail::ServoAxis>(effective, config_.cycle_time, axes_.size(), *scratch_);
  hli_->add_axis(effective);
  couplings_.add_axis();
  snapshots_.emplace_back();
  group_ready_.push_back(0);
  axes_.push_back(std::move(axis));
  return axes_.back()->ref();
}

namespace {

// A coupling command (MC_GearIn, MC_GearInDyn, MC_GearOut) waits in some axis's mailbox: its
// phase (a) reads another axis and may change the coupling graph. Only these commands reach
// another axis; none of them can be buffered (command_buffer.hpp).
bool coupling_command_posted(std::span<const std::unique_ptr<detail::ServoAxis>> axes) noexcept {
  const auto coupling = [](plc::CommandType type) noexcept {
    return type == plc::CommandType::kGearIn || type == plc::CommandType::kGearInDyn ||
           type == plc::CommandType::kGearOut;
  };
  for (const auto& axis : axes) {
    if (axis->ref().Mailbox.holds(coupling)) return true;
  }
  return false;
}

}  // namespace

void Kernel::cycle() noexcept {
  const uint64_t counter = cycles_ + 1;
  const std::size_t n = axes_.size();
  detail::CouplingPort port{axes_, couplings_};
  // Whether phase (c) runs: the PLC's HLI semaphores alone decide it, not phase (a).
  const bool hli = hli_->begin_cycle();
  if (!hli && !couplings_.has_couplings() && !coupling_command_posted(axes_)) {
    // No axis reads another in this cycle, and none will start to: each axis runs all its
    // phases (a) to (f) before the next one, so its data stays in the cache and the kernel
    // loops once (docs/architecture.md "One tick").
    detail::ServoAxis::run_cycles_alone(axes_, snapshots_, port, counter);
  } else {
    // (a) commands of every axis first: a coupling command reads other axes and changes the
    // graph, so the order and the blocks below are those after it.
    for (std::size_t i = 0; i < n; ++i)
      axes_[i]->phase_commands(port);
    // With couplings the phases run over the whole kernel, phase by phase (a slave reads its
    // master's set values, a group reaction needs all its members' errors); so they do while
    // the HLI stage is engaged (phase (c) needs every axis's program position). Without either
    // (the coupling command was refused) each axis runs phases (b) to (f) alone.
    if (couplings_.has_couplings() || hli) {
      run_phases(0, n, counter);
    } else {
      for (std::size_t i = 0; i < n; ++i)
        axes_[i]->run_alone(snapshots_[i], snapshots_, counter);
    }
  }
  mark_ready_groups();
  cycles_ = counter;
}

void Kernel::mark_ready_groups() noexcept {
  // Without couplings every axis heads a group of its own: its phase_monitors() told it already.
  if (!couplings_.has_couplings()) return;
  const std::size_t n = axes_.size();
  for (std::size_t i = 0; i < n; ++i)
    group_ready_[i] = 1;
  for (std::size_t i = 0; i < n; ++i) {
    if (snapshots_[i].error != plc::ErrorCode::kNone || !snapshots_[i].controller_enabled) {
      group_ready_[couplings_.group(i)] = 0;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (couplings_.group(i) == i)
      detail::GroupErrors(axes_[i]->core()).set_group_ready(group_ready_[i] != 0);
  }
}

plc::ErrorCode Kernel::push_by_hand(std::size_t axis, double velocity) noexcept {
  if (axis >= axes_.size()) return plc::ErrorCode::kInvalidAxisReference;
  return detail::GroupErrors(axes_[axis]->core()).push_by_hand(velocity);
}

void Kernel::react_in_groups() noexcept {
  // SPEC C7 (seed 000 §3.1): the group reaction of an axis's own error reaches every axis of its
  // master/slave group as the group is in this cycle, with the faulty axis's code. INSTANTANEOUS:
  // in the cycle the error is raised; DELAYED: when the faulty axis's delay has run out
  // (GroupErrors::group_reaction_due). Errors are rare: the scan over the group's axes runs only
  // for an axis whose reaction is due.
  const std::size_t n = axes_.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!snapshots_[i].group_reaction_due) continue;
    const std::size_t group = couplings_.group(i);
    const plc::ErrorCode code = snapshots_[i].error;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i || couplings_.group(j) != group) continue;
      if (snapshots_[j].error != plc::ErrorCode::kNone) continue;
      detail::GroupErrors(axes_[j]->core()).group_error(code);
      snapshots_[j].error = code;
      snapshots_[j].error_event = true;
    }
  }
}

void Kernel::run_phases(std::size_t first, std::size_t last, uint64_t counter) noexcept {
  const std::span<const uint32_t> order = couplings_.order();
  // (a) commands: mailbox, enables, override and the online functions ran in cycle().
  // (b) set values, every master before its slaves (index order while nothing is coupled).
  for (std::size_t k = first; k < last; ++k) {
    const uint32_t i = order[k];
    axes_[i]->phase_set_values(snapshots_[i], snapshots_);
  }
  // (c) couplings that act on drive positions: the HLI stage, only while engaged (then the
  // block is the whole kernel); otherwise the drive controls to the program's set values.
  if (hli_->engaged()) hli_->run(axes_, snapshots_);
  // (d) position control, drive and encoder.
  for (std::size_t i = first; i < last; ++i)
    axes_[i]->phase_drive(snapshots_[i]);
  // (e) monitors and error handling, then the group reactions (no groups without couplings).
  for (std::size_t i = first; i < last; ++i)
    axes_[i]->phase_monitors(snapshots_[i]);
  if (couplings_.has_couplings()) react_in_groups();
  // (f) publish.
  for (std::size_t i = first; i < last; ++i)
    axes_[i]->phase_publish(counter);
}

}  // namespace nc
