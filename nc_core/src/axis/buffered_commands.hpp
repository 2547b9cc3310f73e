// BufferMode (Tc2_MC2, issue 14; docs/behaviour.md "BufferMode"): when the axis's one waiting
// command (CommandBuffer, command_buffer.hpp) takes over, and the blend: the running positioning
// replanned to pass its target at the blend velocity, so that the next command starts there
// without stopping.
//
// A view on one axis's AxisCore for one call (it owns nothing). Cycle functions: noexcept, no
// allocation; a refused command leaves the waiting one and the running job as they are.
#pragma once

#include <cstdint>

#include "axis/axis_core.hpp"
#include "plc_interface/command.hpp"

namespace nc::detail {

struct CouplingPort;

class BufferedCommands : public AxisPart {
 public:
  using AxisPart::AxisPart;

  // A move or halt with a BufferMode other than MC_Aborting: checked, then started at once when
  // the running job is already finished for it, else kept waiting (kBuffered) — a blending mode
  // replans the running positioning to pass its target. A second one is refused (kBufferFull).
  ErrorCode buffer_command(const plc::Command& command, CouplingPort& port) noexcept;
  // Phase a, after the commands and enables: the waiting command takes over once the running
  // job is finished for it; a pass with nothing to take over stops.
  void run_buffer(CouplingPort& port) noexcept;
  // With a blending command waiting behind a running positioning: its table replanned from the
  // basic state to pass the target at the blend velocity the path allows (none on a reversal).
  // `level`: the path velocity the running table has (override applied).
  void plan_blend(double level) noexcept;

 private:
  // The running job lets a buffered command start now: nothing runs, a positioning or halt has
  // ended its set values, a velocity job holds its velocity.
  bool ready_for_next() const noexcept;
  // The running command ends (Done, or CommandAborted for a velocity job) and the waiting one
  // starts from the set state (relative and modulo targets counted from the running target).
  void take_next(CouplingPort& port) noexcept;
  // Into scratch_: from `from` to `target` passed at `speed` along `direction`, not above the
  // level `limits.velocity` until the last speed-up; false when it would move backwards.
  bool plan_pass(const KinematicState& from, double target, double direction, double speed,
                 const Limits& limits) noexcept;
  // The direction (+1 / -1; 0: none or unknown) in which `next` moves on from the end
  // `from` of the running positioning (which moves in `direction`), and its end position (NaN
  // for a velocity move or a halt).
  double next_direction(const plc::Command& next, double from, double direction,
                        double& end) const noexcept;
  // A pass table ended with nothing to take over: the axis stops from where it is.
  void stop_pass() noexcept;
};

}  // namespace nc::detail
