// A two-speed (rapid/creep) axis in the kernel (SPEC E1-E6, seed 004): the commands of its
// AxisChannel drive a TwoSpeedSequencer, whose 12-byte image drives a TwoSpeedPlant, whose
// encoder is the actual position. The servo path (planner, controller, drive) is not used.
//
// The owner (the kernel's axis slot, ServoAxis for kind kTwoSpeed) calls the phases of the NC
// cycle in the kernel's order. What each block does on a two-speed axis, the refusals and the
// NcToPlc fields are in docs/behaviour.md "Two-speed axis". The constructor is set-up (throws
// ConfigError on a bad configuration); everything else is a cycle function: noexcept, no
// allocation.
#pragma once

#include <cstdint>

#include "axis/axis_channel.hpp"
#include "axis/monitors.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/axis_snapshot.hpp"
#include "plc_interface/command.hpp"
#include "plc_interface/error_code.hpp"
#include "plc_interface/two_speed.hpp"
#include "two_speed/two_speed_plant.hpp"
#include "two_speed/two_speed_sequencer.hpp"

namespace nc::detail {

class TwoSpeedAxis {
 public:
  // `channel` is the owner's; it outlives this object.
  TwoSpeedAxis(const AxisConfig& config, double cycle_time, AxisChannel& channel);

  void phase_commands() noexcept;                          // (a) mailbox, enables, override
  void phase_set_values(AxisSnapshot& snapshot) noexcept;  // (b) the sequencer's step
  void phase_drive(AxisSnapshot& snapshot) noexcept;       // (d) the plant and its encoder
  void phase_monitors(AxisSnapshot& snapshot) noexcept;    // (e) target windows
  void phase_publish(uint64_t cycle_counter, int32_t index) noexcept;  // (f)

  const plc::NCTOIO_DRIVE_TWO_SPEED& output() const noexcept { return sequencer_.image(); }

 private:
  void handle(const plc::Command& command) noexcept;
  plc::ErrorCode start(const plc::Command& command) noexcept;
  plc::ErrorCode stop(const plc::Command& command) noexcept;
  void check_enables() noexcept;
  // The first error stays until MC_Reset: the running command fails, the brake comes on.
  void raise_error(plc::ErrorCode code) noexcept;
  // Signed speed the image commands: ± rapid_velocity / creep_velocity, 0 without travel.
  double commanded_velocity() const noexcept;

  const AxisConfig& config_;
  double cycle_time_;
  AxisChannel& channel_;
  TwoSpeedSequencer sequencer_;
  TwoSpeedPlant plant_;
  Monitors monitors_{};

  uint16_t job_ = 0;     // the command the sequencer runs (a positioning, stop or halt)
  bool locked_ = false;  // MC_Stop: motion commands refused until kStopRelease
  bool has_been_stopped_ = false;
  double previous_velocity_ = 0.0;  // the plant's, one cycle earlier (ActAcc)
};

}  // namespace nc::detail
