// Phase a of one axis: the mailbox drained, each command checked, acted on and answered (contract
// in plc_interface/command.hpp): the starts of MoveAbsolute / MoveRelative / MoveModulo /
// MoveVelocity, Halt and Stop with their checks, MC_Reset and the stop release; every other
// command is handed to the class it belongs to (online_change.hpp, buffered_commands.hpp,
// slave_coupling.hpp, superposition_commands.hpp, homing/axis_homing.hpp, group_errors.hpp).
//
// A view on one axis's AxisCore for one call (it owns nothing). Cycle functions: noexcept, no
// allocation. A refused command changes nothing: every check runs before anything is written,
// and a start is planned into the kernel's scratch profile.
#pragma once

#include <cstdint>

#include "axis/axis_core.hpp"
#include "plc_interface/command.hpp"

namespace nc::detail {

struct CouplingPort;

class AxisCommands : public AxisPart {
 public:
  using AxisPart::AxisPart;

  // The commands posted since the last cycle, in order (nothing posted, the steady case: inline,
  // no call).
  void handle_commands(CouplingPort& port) noexcept {
    if (s_.channel_.ref().Mailbox.pending() != 0) drain(port);
  }
  // Acts on a command now (BufferMode not looked at); the error code of a refusal.
  ErrorCode handle_now(const plc::Command& command, CouplingPort& port) noexcept;
  // The checks every motion start (MoveAbsolute/Relative/Modulo/Velocity) makes, in this order:
  // axis error, MC_Stop lock, external generation enabled, buffer mode, Position finite (when
  // `has_position`), then the dynamics into `limits`.
  ErrorCode check_start(const plc::Command& command, bool has_position,
                        Limits& limits) const noexcept;
  // The checks of a Halt / Stop's inputs and the axis (error, lock, dynamics, enable).
  ErrorCode check_halt_or_stop(const plc::Command& command) const noexcept;
  // The end position of a modulo command for an axis coming to rest at `from` while moving in
  // `moving` (+1 / -1, 0 at standstill: MC_Current_Direction is refused then).
  ErrorCode modulo_end(const plc::Command& command, double from, double moving,
                       double& end) const noexcept;

 private:
  void drain(CouplingPort& port) noexcept;
  void handle(const plc::Command& command, CouplingPort& port) noexcept;
  ErrorCode start_position(const plc::Command& command) noexcept;
  ErrorCode start_velocity(const plc::Command& command) noexcept;
  ErrorCode start_halt_or_stop(const plc::Command& command) noexcept;
  // The checks of a positioning start once its absolute target is known (software limits,
  // enables, shorter than one increment), then start_positioning().
  ErrorCode start_to_target(uint16_t number, double target, const Limits& limits) noexcept;
  ErrorCode check_dynamics(const plc::Command& command, Limits& limits) const noexcept;
  ErrorCode start_modulo(const plc::Command& command) noexcept;
};

}  // namespace nc::detail
