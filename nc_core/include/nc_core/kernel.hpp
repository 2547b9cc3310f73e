// The NC kernel: the axes of one controller and the fixed NC cycle that moves them (SPEC A1).
//
// The kernel owns its axes. The PLC side sees each axis only through the plc::AXIS_REF returned
// by add_axis()/axis(): it writes PlcToNc, posts commands into the mailbox and reads NcToPlc.
// One call of cycle() is one NC cycle; its phases are drawn in docs/architecture.md, and how an
// axis behaves (starts, override, stops, new positions, compensation, external setpoints,
// errors, with their codes) is written in docs/behaviour.md.
//
// Set-up functions (constructor, from_json, add_axis, axis, config) may allocate and throw
// nc::ConfigError. cycle() is the cycle function: noexcept, no allocation, no locks, no I/O —
// all memory is reserved when an axis is added.
#pragma once

#include <cstddef>
#include <cstdint>

#include <nlohmann/json_fwd.hpp>

#include "nc_core/axis_config.hpp"
#include "nc_core/detail/kernel_axes.hpp"
#include "plc_interface/error_code.hpp"

namespace nc {

// The axis lookups (axis, axis_count, config, reference_cam, two_speed_output, snapshot,
// couplings, gpAx, command_position_request) come from detail::KernelAxes.
class Kernel : public detail::KernelAxes {
 public:
  // Set-up: validates `config` (throws ConfigError).
  explicit Kernel(KernelConfig config = {});
  ~Kernel();
  Kernel(Kernel&&) noexcept;
  Kernel& operator=(Kernel&&) noexcept;
  Kernel(const Kernel&) = delete;
  Kernel& operator=(const Kernel&) = delete;

  // Set-up: {"kernel": {...}, "axes": [...]} (see config.hpp); throws ConfigError naming the
  // JSON pointer and the rule.
  static Kernel from_json(const nlohmann::json& document);

  // Set-up: validates the configuration, rejects a duplicate name or id (ConfigError), reserves
  // all the axis's memory. The reference stays valid for the kernel's life (also across moves
  // of the Kernel object). An id of 0 is replaced by index + 1.
  plc::AXIS_REF& add_axis(const AxisConfig& config);

  const KernelConfig& kernel_config() const noexcept { return config_; }

  // Cycle function: one NC cycle, phase by phase over all axes (docs/architecture.md "One
  // tick"): commands, set values (masters before slaves), couplings on drive positions, position
  // control + drive + encoder, monitors and errors then group reactions, publish.
  void cycle() noexcept;

  // The simulated drive of a continuous axis whose controller enable is off is moved by hand
  // at `velocity` (mm/s, signed) from the next cycle on, until another velocity is given or the
  // controller enable returns (the push ends then). For tests and samples of SPEC C8 (a head
  // master pushed by hand). kNone when taken; refused, nothing changed: an unknown axis index
  // (kInvalidAxisReference), a velocity NaN or infinite (kParameterNotFinite) or above the axis's
  // max_velocity in size (kVelocityNotAllowed), an encoder or two-speed axis
  // (kAxisKindNotAllowed), an axis with its controller enable (kPushByHandControllerEnabled).
  // Between cycles; noexcept, no allocation.
  plc::ErrorCode push_by_hand(std::size_t axis, double velocity) noexcept;

  double cycle_time() const noexcept { return config_.cycle_time; }
  // Completed NC cycles since the kernel was made.
  uint64_t cycle_count() const noexcept { return cycles_; }
  // Seconds since start = cycle_count() · cycle_time() (a product, never a running sum).
  double time() const noexcept { return static_cast<double>(cycles_) * config_.cycle_time; }

 private:
  // Phases (a) … (f) over axes [first, last) of the set-value order.
  void run_phases(std::size_t first, std::size_t last, uint64_t counter) noexcept;
  // Phase (e), with couplings: an axis's new error reaches its whole group (SPEC C7).
  void react_in_groups() noexcept;
  // After all phases, with couplings: tells each group's head whether its group has no error and
  // every axis enabled (the precondition of SPEC C8 case 2, GroupErrors::follows_by_hand()). An
  // uncoupled axis (a group of its own) knows it from its own monitor phase.
  void mark_ready_groups() noexcept;

  KernelConfig config_;
  uint64_t cycles_ = 0;
};

}  // namespace nc
