// One continuous servo (or encoder) axis of the kernel: its cyclic interface, its master job,
// position controller, drive, encoder and monitors (SPEC A3, A4, B1, B2).
//
// The kernel runs each phase over all axes (docs/architecture.md "One tick"): phase_commands,
// phase_set_values, phase_drive, phase_monitors, phase_publish. What the PLC side sees lives in
// the AxisChannel; a start is planned into the kernel's one scratch profile. The constructor is
// set-up (allocates the dead-time line); everything else runs in the cycle: noexcept, no
// allocation. An axis of kind kTwoSpeed is a slot of the same type whose phases hand over to its
// TwoSpeedAxis (two_speed/two_speed_axis.hpp) on the same AxisChannel.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "axis/axis_core.hpp"
#include "nc_core/axis_snapshot.hpp"
#include "nc_core/coupling_graph.hpp"
#include "plc_interface/axis_ref.hpp"

namespace nc::detail {

class ServoAxis;

// What the commands phase of one axis may reach of the others (MC_GearIn / MC_GearOut): the
// kernel's axes by index and its coupling graph. The kernel builds it for each cycle.
struct CouplingPort {
  std::span<const std::unique_ptr<ServoAxis>> axes;
  CouplingGraph& graph;
};

class ServoAxis : private AxisCore {
 public:
  // `scratch`: the kernel's planning profile, shared by all its axes (one plans at a time).
  ServoAxis(const AxisConfig& config, double cycle_time, std::size_t index, Profile& scratch);

  // The state the feature classes work on (axis_core.hpp); the coupling reaches other axes' too.
  AxisCore& core() noexcept { return *this; }
  plc::AXIS_REF& ref() noexcept { return channel_.ref(); }
  const plc::AXIS_REF& ref() const noexcept { return channel_.ref(); }
  const AxisConfig& config() const noexcept { return config_; }
  // The simulated reference cam's digital input (AxisConfig::homing_cam_*), on the raw encoder.
  bool reference_cam() const noexcept;
  // Kind kTwoSpeed: the 12-byte drive image of this cycle; nullptr for every other kind.
  const plc::NCTOIO_DRIVE_TWO_SPEED* two_speed_output() const noexcept {
    return two_speed_ ? &two_speed_->output() : nullptr;
  }

  // The phases of one NC cycle (steps a … f of docs/architecture.md "One tick"); the kernel
  // calls each for every axis before the next. The snapshot is what other axes may read.
  void phase_commands(CouplingPort& port) noexcept;  // (a)
  // (b); `snapshots`: every axis's, a slave reads its master's (computed before it this cycle).
  void phase_set_values(AxisSnapshot& snapshot, std::span<const AxisSnapshot> snapshots) noexcept;
  // (c) HLI coupling (SPEC D3), called only while the kernel's coupling stage is engaged: the
  // set values phase (d) controls to this cycle (NcToPlc.SetPos; without a call they are the
  // program's set values), and `stop` != kNone raises that axis error (program on its emergency
  // ramp). The windows and software limits stay in program coordinates (actual − (d − q)).
  // `role`: the axis's HLI part (a list in force: slave; a source of another axis's list:
  // master), kept until the next call, for CoupleState and the refusal of external setpoints.
  void phase_drive_command(const KinematicState& drive, ErrorCode stop,
                           plc::CoupleState role) noexcept;
  // What the HLI phase reads of the axis before phase (c): an axis error, the controller enable,
  // external setpoint generation enabled.
  bool has_error() const noexcept { return channel_.has_error(); }
  // Counts the axis errors raised (wrapping): an error raised and reset between two phases (c)
  // still shows as a change.
  uint32_t errors_raised() const noexcept { return errors_raised_; }
  bool controller_enabled() const noexcept { return channel_.controller_enabled(); }
  bool external_enabled() const noexcept { return stack_.external().enabled(); }
  void phase_drive(AxisSnapshot& snapshot) noexcept;     // (d)
  void phase_monitors(AxisSnapshot& snapshot) noexcept;  // (e)
  void phase_publish(uint64_t cycle_counter) noexcept;   // (f)
  // Phases (b), (d), (e), (f) one after the other, for a kernel in which no axis reads another
  // (no coupling, HLI stage not engaged): the same as the kernel's phase loops.
  void run_alone(AxisSnapshot& snapshot, std::span<const AxisSnapshot> snapshots,
                 uint64_t cycle_counter) noexcept {
    phase_set_values(snapshot, snapshots);
    phase_drive(snapshot);
    phase_monitors(snapshot);
    phase_publish(cycle_counter);
  }

 private:
  // --- commands.cpp ---
  void handle_commands(CouplingPort& port) noexcept;
  void handle(const plc::Command& command, CouplingPort& port) noexcept;
  // Acts on a command now (BufferMode not looked at); the error code of a refusal.
  ErrorCode handle_now(const plc::Command& command, CouplingPort& port) noexcept;
  ErrorCode start_position(const plc::Command& command) noexcept;
  ErrorCode start_velocity(const plc::Command& command) noexcept;
  ErrorCode start_halt_or_stop(const plc::Command& command) noexcept;
  // The checks of a Halt / Stop's inputs and the axis (error, lock, dynamics, enable).
  ErrorCode check_halt_or_stop(const plc::Command& command) const noexcept;
  // The checks of a positioning start once its absolute target is known (software limits,
  // enables, shorter than one increment), then start_positioning().
  ErrorCode start_to_target(uint16_t number, double target, const Limits& limits) noexcept;
  ErrorCode check_dynamics(const plc::Command& command, Limits& limits) const noexcept;
  // The checks every motion start (MoveAbsolute/Relative/Modulo/Velocity) makes, in this order:
  // axis error, MC_Stop lock, external generation enabled, buffer mode, Position finite (when
  // `has_position`), then the dynamics into `limits`.
  ErrorCode check_start(const plc::Command& command, bool has_position,
                        Limits& limits) const noexcept;

  // --- servo_axis.cpp ---
  void check_enables() noexcept;
  // Step b: the basic source's set values, then the superposition stack on top.
  void generate_set_values(std::span<const AxisSnapshot> snapshots) noexcept;
  void control_and_drive() noexcept;
  void run_monitors() noexcept;
  void finish_job() noexcept;

  // --- override.cpp (B3 override, seed 000 §2.2) ---
  // Phase a, first: PlcToNc.Override into the job; above 1'000'000 it is not taken (warning
  // 0x4238).
  void read_override() noexcept;
  // The velocity level the override gives: the user's V (types 2, 4) or the level reduced at the
  // start (types 1, 3), times the override.
  double override_level(double user_velocity, double reduced_velocity,
                        uint32_t override_value) const noexcept;
  // A positioning / velocity job planned from set_ with the override in force, then accept().
  ErrorCode start_positioning(uint16_t number, double target, const Limits& limits) noexcept;
  ErrorCode start_continuous(uint16_t number, double velocity, const Limits& limits) noexcept;
  // The override changed: the running table is replanned (or kept, seed 000 §2.2).
  void apply_override() noexcept;
  // Into scratch_: to `target` at path velocity `level`, or for level 0 a rest on the path
  // (`final` false). False when the planner refuses.
  bool plan_table(const KinematicState& from, double target, const Limits& limits, double level,
                  bool& final) noexcept;

  // --- online_change.cpp (B4-B6 stop rules, new end position, new velocity; seed 000 §2.2-2.4)
  // Phase a, last: the override and a due new velocity act on the running job.
  void run_online_functions() noexcept;
  // A Halt or Stop runs or MC_Stop's lock is held: new-position functions are refused.
  bool stop_active() const noexcept;
  ErrorCode new_position(const plc::Command& command) noexcept;
  ErrorCode new_position_and_velocity(const plc::Command& command) noexcept;
  // The refusals common to both (axis error, stop, target, job, compensation, feed enable).
  ErrorCode check_new_target(double target) const noexcept;
  // Replans the running positioning to `target` with user velocity `velocity` (override
  // applied), from the basic motion's state.
  bool retarget(double target, double velocity) noexcept;
  // Seed 000 §2.4 "New velocity": VNew for the running positioning, reduced iteratively when
  // not reachable; false (table kept) when nothing fits.
  bool activate_velocity(double velocity) noexcept;
  // Installs scratch_ into the running job (planned from basic_state()), keeping the
  // superpositions on top.
  void install_table(double target, bool final, double level) noexcept;

  // --- homing/home_command.cpp (MC_Home, SPEC F; docs/behaviour.md "Homing") ---
  ErrorCode start_home(const plc::Command& command) noexcept;
  // Position setting: every displayed position (set, actual, target) moves by `delta`; nothing
  // moves physically and the following error stays.
  void shift_position(double delta) noexcept;
  // Phase b with the homing job as the source.
  void run_homing() noexcept;

  // --- modulo.cpp (B1 modulo start, seed 000 §2.1) ---
  ErrorCode start_modulo(const plc::Command& command) noexcept;
  // The end position of a modulo command for an axis coming to rest at `from` while moving in
  // `moving` (+1 / -1, 0 at standstill: MC_Current_Direction is refused then).
  ErrorCode modulo_end(const plc::Command& command, double from, double moving,
                       double& end) const noexcept;

  // --- command_buffer.cpp (BufferMode: one buffered command, blending; issue 14) ---
  // A move or halt with a BufferMode other than MC_Aborting: checked, then started at once when
  // the running job is already finished for it, else kept waiting (kBuffered) — a blending mode
  // replans the running positioning to pass its target. A second one is refused (kBufferFull).
  ErrorCode buffer_command(const plc::Command& command, CouplingPort& port) noexcept;
  // Phase a, after the commands and enables: the waiting command takes over once the running
  // job is finished for it; a pass with nothing to take over stops.
  void run_buffer(CouplingPort& port) noexcept;
  // The running job lets a buffered command start now: nothing runs, a positioning or halt has
  // ended its set values, a velocity job holds its velocity.
  bool ready_for_next() const noexcept;
  // The running command ends (Done, or CommandAborted for a velocity job) and the waiting one
  // starts from the set state (relative and modulo targets counted from the running target).
  void take_next(CouplingPort& port) noexcept;
  // With a blending command waiting behind a running positioning: its table replanned from the
  // basic state to pass the target at the blend velocity the path allows (none on a reversal).
  // `level`: the path velocity the running table has (override applied).
  void plan_blend(double level) noexcept;
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

  // --- superposition.cpp (B7 position compensation, B8 external setpoints: their commands, and
  // the stack's rules where the axis's basic state must follow) ---
  ErrorCode start_compensation(const plc::Command& command) noexcept;
  ErrorCode stop_compensation(const plc::Command& command) noexcept;
  ErrorCode enable_external(const plc::Command& command) noexcept;
  ErrorCode disable_external(const plc::Command& command) noexcept;
};

}  // namespace nc::detail
