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

#include "axis/axis_channel.hpp"
#include "axis/command_buffer.hpp"
#include "axis/compensation.hpp"
#include "axis/drive.hpp"
#include "axis/error_propagation.hpp"
#include "axis/external_setpoint.hpp"
#include "axis/master_job.hpp"
#include "axis/monitors.hpp"
#include "axis/position_controller.hpp"
#include "axis/set_value_source.hpp"
#include "axis/slave_link.hpp"
#include "axis/superposition_stack.hpp"
#include "homing/homing_job.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/axis_snapshot.hpp"
#include "nc_core/coupling_graph.hpp"
#include "nc_core/profile.hpp"
#include "plc_interface/axis_ref.hpp"
#include "plc_interface/two_speed.hpp"
#include "two_speed/two_speed_axis.hpp"

namespace nc::detail {

class ServoAxis;

// The basic motion an axis's superpositions ride on (seed 000 §2.5, §3.2.4): the axis's own job,
// or, for a coupled slave, its master's path as the master's snapshot shows it (a slave's
// compensation ends with its master's path, and its remaining length is to its TargetPos).
struct BasicPath {
  bool running = false;
  bool stopping = false;
  bool positioning = false;
  bool has_target = false;
  double target = 0.0;
  double target_velocity = 0.0;
};

// What the commands phase of one axis may reach of the others (MC_GearIn / MC_GearOut): the
// kernel's axes by index and its coupling graph. The kernel builds it for each cycle.
struct CouplingPort {
  std::span<const std::unique_ptr<ServoAxis>> axes;
  CouplingGraph& graph;
};

class ServoAxis {
 public:
  // `scratch`: the kernel's planning profile, shared by all its axes (one plans at a time).
  ServoAxis(const AxisConfig& config, double cycle_time, std::size_t index, Profile& scratch);

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
  // The program set values q of this cycle for phase (c): the axis's own (its snapshot may
  // carry the filtered actual values its slaves follow instead, C8; fuzz finding K14); a
  // two-speed axis's are its snapshot's.
  KinematicState program_state(const AxisSnapshot& snapshot) const noexcept {
    if (two_speed_) {
      return KinematicState{snapshot.set_position, snapshot.set_velocity,
                            snapshot.set_acceleration};
    }
    return set_;
  }
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
  // (e), after every axis's monitors: the group reaction (SPEC C7 INSTANTANEOUS) reaches this
  // axis with the faulty axis's code; the first error stays. A slave goes on following (its
  // head master's emergency ramp brings it down); a master stops on its emergency ramp.
  void group_error(ErrorCode code) noexcept;

  // --- error_propagation.cpp (SPEC C7, C8; seed 000 §3.1) ---
  // Case 2 of C8: this head master's controller enable is off in a group that had no error and
  // every axis enabled when it went, and couple_slave_to_actual_values is set: the group follows
  // its actual values (pushed by hand). Losing the controller enable is no error then.
  bool follows_by_hand() const noexcept;
  // Kernel, after the group reactions of a cycle with couplings: `ready` = this axis heads a
  // group in which no axis has an error and every axis has its controller enable (the
  // precondition of case 2). An uncoupled axis sets it for itself in phase_monitors().
  void set_group_ready(bool ready) noexcept { group_ready_ = ready; }
  // Kernel::push_by_hand: the drive of this disabled continuous axis moves at `velocity` (mm/s)
  // from the next cycle on, until the controller enable returns or another velocity is given.
  ErrorCode push_by_hand(double velocity) noexcept;

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
  // +1 / -1 while the set velocity has that sign, 0 at standstill (MC_Current_Direction).
  double current_direction() const noexcept;
  // The new job replaces the running one: the replaced command is answered kAborted.
  void accept(JobKind kind, uint16_t number, const Profile& profile, double target,
              double target_velocity, const Limits& limits) noexcept;

  // --- servo_axis.cpp ---
  void check_enables() noexcept;
  // --- enable_loss.cpp (issue 10 item 4) ---
  // The controller enable is missing in this cycle (`lost`: it was there in the last one): true
  // when that is the axis error 0x4260, i.e. a command runs (a job, a homing, or the coupling of
  // a slave). The one place that decides it.
  bool enable_loss_is_error(bool lost) const noexcept;
  // Step b: the basic source's set values, then the superposition stack on top.
  void generate_set_values(std::span<const AxisSnapshot> snapshots) noexcept;
  // The one basic source of this cycle (set_value_source.hpp).
  SetValueSource source() const noexcept;
  // The motion a new job, a stop or the error ramp takes over (its limits, K4, K5, K8): the
  // running homing's, else the job's.
  const MasterJob& running_motion() const noexcept {
    return homing_.active() ? homing_.motion() : job_;
  }
  void control_and_drive() noexcept;
  void run_monitors() noexcept;
  void finish_job() noexcept;
  // The axis goes into error: the running job fails with `code`, and the set values ramp down
  // on the emergency deceleration and jerk (SPEC A6). The first error is kept. `own`: the axis's
  // own error, which starts its group reaction (SPEC C7); false for the group's reaction itself.
  void raise_error(ErrorCode code, bool own = true) noexcept;
  void reset_error() noexcept;

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

  // --- coupling.cpp (C1, C3, C4; seed 000 §3.2.2-3.2.3) ---
  ErrorCode gear_in(const plc::Command& command, CouplingPort& port) noexcept;
  // The checks shared by MC_GearIn and MC_GearInDyn, in the order of docs/behaviour.md "Slave
  // axes": the factor (finite, not 0, |factor| <= 1e6); the slave's kind and the master index;
  // for a new coupling: loop, error, lock, enable, both at rest.
  static ErrorCode check_gear_ratio(double ratio) noexcept;
  ErrorCode check_gear_master(const plc::Command& command, CouplingPort& port) const noexcept;
  ErrorCode check_new_coupling(uint32_t master_index, CouplingPort& port) const noexcept;
  // A checked new coupling: graph, counts, slave link (linear, factor command.ratio), answered
  // kActive. False only when the graph refuses (a loop; checked before).
  bool couple_new(const plc::Command& command, uint32_t master_index, CouplingPort& port) noexcept;
  // --- cyclic_slave.cpp (C6; seed 000 §3.3; MC_GearInDyn) ---
  ErrorCode gear_in_dyn(const plc::Command& command, CouplingPort& port) noexcept;
  // The largest acceleration the axis's set values can have (mm/s²): max(A+, A-) of a master,
  // through its cascade for a slave (|factor| × its master's; a cyclic slave at least AccBound).
  double max_acceleration(const CouplingPort& port) const noexcept;
  // Phase b of a cyclic slave, before its sample: PlcToNc.GearRatio1 read (not taken when 0,
  // NaN, inf or above 1e6: warning 0x4F81) and the factor in force moved towards it within
  // AccBound (the smoothing law of docs/behaviour.md "Cyclic slave").
  void step_cyclic_factor(const AxisSnapshot& master) noexcept;
  ErrorCode gear_out(const plc::Command& command, CouplingPort& port) noexcept;
  // Online decoupling: the levels from the head of this slave's cascade down to it, and the
  // head. False (0x424D) when the head runs no PTP job or the cascade is too deep.
  bool decoupling_chain(CouplingPort& port, DecouplingChain& chain,
                        const ServoAxis*& head) const noexcept;
  // At rest for a coupling: no job, set velocity and acceleration 0, no compensation running,
  // no external generation enabled (seed 000 §3.2.2 "both axes are stationary").
  bool at_rest_for_coupling() const noexcept;
  // A coupled slave refuses this command (0x424E): starts, stops, new positions and external
  // setpoint generation (compensation is allowed: C5).
  static bool refused_while_coupled(plc::CommandType type) noexcept;

  // --- error_propagation.cpp ---
  // From raise_error() for the axis's own error: starts the countdown to the group reaction
  // (0 cycles unless DELAYED in a group); a DELAYED slave leaves its master's coupling at once
  // (its link stays in the graph, SlaveLink::detached, until MC_GearOut).
  void begin_error_propagation() noexcept;
  // The monitor phase: the group reaction of this axis's error is due in this cycle.
  bool group_reaction_due() noexcept;
  // MC_GearOut of a slave that left its master on its own error: the link leaves the graph.
  ErrorCode release_detached(const plc::Command& command, CouplingPort& port) noexcept;
  // C8: the slaves of this axis follow its filtered actual values in this cycle.
  bool drives_slaves_by_actual() const noexcept;
  // The set values phase: the snapshot's set values for the slaves, from the filtered actual
  // position of the previous cycle while drives_slaves_by_actual().
  void publish_for_slaves(AxisSnapshot& snapshot) noexcept;
  // check_enables(), first: enters case 2 when follows_by_hand() holds (a running job ends
  // CommandAborted) and leaves it when it no longer does (the push by hand ends). True while
  // in case 2: the lost controller enable is no error.
  bool update_by_hand() noexcept;
  // Not (or no longer) in case 2; a push by hand ends with the controller enable.
  void end_by_hand() noexcept {
    by_hand_ = false;
    if (channel_.controller_enabled()) hand_velocity_ = 0.0;
  }

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
  // The waiting command, if any, is answered `state` (an aborting command, a stop, an error).
  void drop_buffer(plc::CommandState state, uint32_t code = 0) noexcept;
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
  // The set state without the running compensation and the external offset: where a replan of
  // the basic motion starts when the superpositions are to go on.
  KinematicState basic_state() const noexcept;
  // A job planned from set_ starts: SuperpositionStack::fold(), and the basic motion is set_.
  void fold_superpositions(plc::CommandState state, ErrorCode code = ErrorCode::kNone) noexcept;
  // Reset, or the controller enable gone: the external generation is switched off at once.
  void end_external_generation() noexcept;

  // What a steady cycle touches comes first, close together (docs/performance.md "Kernel
  // cycle"); the job (with its profile), the AXIS_REF (with its mailbox), the homing, the buffer
  // and the configuration follow.
  // Kind kTwoSpeed: the phases run this instead of the servo path (AxisKind dispatch).
  std::unique_ptr<TwoSpeedAxis> two_speed_;
  double cycle_time_;
  std::size_t index_;
  // The configuration values a steady cycle reads, copied here (config_ below stays cold).
  bool encoder_ = false;  // config_.kind == AxisKind::kEncoder
  double modulo_factor_ = 360.0;
  double standstill_window_ = 0.0;
  PositionController controller_{};
  Drive drive_{};
  Monitors monitors_{};

  KinematicState set_{};   // set values of this cycle (basic motion + superpositions)
  KinematicState base_{};  // the basic source's own set values
  // Phase (c): what phase (d) controls to when given this cycle (else set_), and d − q of the
  // last cycle it was given (0 without HLI coupling): program coordinate = drive − offset.
  KinematicState drive_command_{};
  double previous_drive_position_ = 0.0;
  double drive_offset_ = 0.0;
  bool drive_command_given_ = false;
  plc::CoupleState hli_role_ = plc::CoupleState::kSingle;  // from phase (c), see there
  bool hli_target() const noexcept {
    return hli_role_ == plc::CoupleState::kSlave || hli_role_ == plc::CoupleState::kMasterAndSlave;
  }
  bool hli_source() const noexcept {
    return hli_role_ == plc::CoupleState::kMaster || hli_role_ == plc::CoupleState::kMasterAndSlave;
  }
  const KinematicState& drive_command() const noexcept {
    return drive_command_given_ ? drive_command_ : set_;
  }
  SlaveLink slave_link_{};
  uint32_t slave_count_ = 0;  // axes coupled to this one as their master
  BasicPath slave_path_{};    // while coupled: the master's path of this cycle, transformed
  // The axis's own job's path, or slave_path_ while coupled.
  BasicPath basic_path() const noexcept;
  double target_velocity() const noexcept {  // basic_path().target_velocity, without the rest
    if (slave_link_.coupled) return slave_path_.target_velocity;
    return job_.active() ? job_.target_velocity() : 0.0;
  }
  double set_jerk_ = 0.0;
  double previous_set_position_ = 0.0;
  double previous_measured_ = 0.0;
  double target_ = 0.0;  // end position of the last positioning / stop; window monitors use it

  // Referenced (StateDWord bit 1): the software limits are monitored only then.
  bool homed_ = true;
  void set_homed(bool homed) noexcept {
    homed_ = homed;
    monitors_.set_referenced(homed);
  }
  bool locked_ = false;  // MC_Stop: motion commands refused until kStopRelease
  bool has_been_stopped_ = false;
  bool error_event_ = false;  // an error was raised in this cycle
  bool enable_seen_ = false;  // the controller enable of the last check_enables()
  // C7 / C8 (error_propagation.cpp).
  PropagationDelay propagation_{};
  bool group_ready_ = false;    // see set_group_ready()
  bool by_hand_ = false;        // case 2 in force (follows_by_hand() latched)
  double hand_velocity_ = 0.0;  // push_by_hand(), mm/s
  ActualValueFilter actual_filter_{};
  uint32_t errors_raised_ = 0;

  SuperpositionStack stack_{};
  MasterJob job_{};
  AxisChannel channel_{};
  HomingJob homing_{};
  CommandBuffer buffer_{};
  Profile& scratch_;  // a start is planned here first, so a refusal changes nothing
  AxisConfig config_;
};

}  // namespace nc::detail
