// One continuous servo (or encoder) axis of the kernel: its cyclic interface, its master job,
// position controller, drive, encoder and monitors (SPEC A3, A4, B1, B2).
//
// Split by concept over several files: commands.cpp (mailbox → validate → act → answer),
// servo_axis.cpp (the cycle: set values, control, drive, monitors, errors), publish.cpp
// (NcToPlc). The constructor is set-up (allocates the dead-time line); everything else runs in
// the cycle: noexcept, no allocation.
#pragma once

#include <cstddef>
#include <cstdint>

#include "axis/drive.hpp"
#include "axis/master_job.hpp"
#include "axis/monitors.hpp"
#include "axis/position_controller.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/profile.hpp"
#include "plc_interface/axis_ref.hpp"

namespace nc::detail {

class ServoAxis {
 public:
  ServoAxis(const AxisConfig& config, double cycle_time, std::size_t index);

  plc::AXIS_REF& ref() noexcept { return ref_; }
  const plc::AXIS_REF& ref() const noexcept { return ref_; }
  const AxisConfig& config() const noexcept { return config_; }

  // One NC cycle of this axis (steps a … f of ARCHITECTURE "One tick").
  void cycle(uint64_t cycle_counter) noexcept;

 private:
  // --- commands.cpp ---
  void handle_commands() noexcept;
  void handle(const plc::Command& command) noexcept;
  ErrorCode start_position(const plc::Command& command) noexcept;
  ErrorCode start_velocity(const plc::Command& command) noexcept;
  ErrorCode start_halt_or_stop(const plc::Command& command) noexcept;
  ErrorCode check_dynamics(const plc::Command& command, Limits& limits) const noexcept;
  // The new job replaces the running one: the replaced command is answered kAborted.
  void accept(JobKind kind, uint16_t number, const Profile& profile, double target,
              double target_velocity, const Limits& limits) noexcept;
  void answer_current(plc::CommandState state, uint32_t code = 0) noexcept;

  // --- servo_axis.cpp ---
  void check_enables() noexcept;
  void generate_set_values() noexcept;
  void control_and_drive() noexcept;
  void run_monitors() noexcept;
  void finish_job() noexcept;
  // The axis goes into error: the running job fails with `code`, and the set values ramp down
  // on the emergency deceleration and jerk (SPEC A6). The first error is kept.
  void raise_error(ErrorCode code) noexcept;
  void reset_error() noexcept;
  bool controller_enabled() const noexcept;
  bool feed_enabled(double direction) const noexcept;

  // --- publish.cpp ---
  void publish(uint64_t cycle_counter) noexcept;

  AxisConfig config_;
  double cycle_time_;
  std::size_t index_;
  plc::AXIS_REF ref_{};

  MasterJob job_{};
  Profile scratch_{};  // a start is planned here first, so a refusal changes nothing
  PositionController controller_{};
  Drive drive_{};
  Monitors monitors_{};

  KinematicState set_{};  // set values of this cycle
  double set_jerk_ = 0.0;
  double previous_set_position_ = 0.0;
  double previous_measured_ = 0.0;
  double target_ = 0.0;  // end position of the last positioning / stop; window monitors use it

  ErrorCode error_ = ErrorCode::kNone;
  uint32_t warning_ = 0;
  bool locked_ = false;  // MC_Stop: motion commands refused until kStopRelease
  bool has_been_stopped_ = false;
  uint16_t cmd_no_ = 0;  // the command the axis executes (or executed last)
  plc::CommandState cmd_state_ = plc::CommandState::kFree;
};

}  // namespace nc::detail
