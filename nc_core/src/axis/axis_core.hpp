// The state of one servo axis that all its parts read and write (set values, the running job,
// the channel, monitors, configuration, cycle time), and the few transitions every part uses:
// raising the axis error, a new job taking over, folding the superpositions.
//
// ServoAxis (servo_axis.hpp) owns it and runs the phases; each feature is a class of its own that
// takes the core by reference for one call (axis_commands.hpp, online_change.hpp,
// buffered_commands.hpp, slave_coupling.hpp, group_errors.hpp, superposition_commands.hpp,
// axis_motion.hpp, axis_monitoring.hpp, homing/axis_homing.hpp). The members
// keep their order: what a steady cycle touches first (docs/performance.md "Kernel cycle").
// Contract: the constructor is set-up; every member function is a cycle function (noexcept, no
// allocation, no lock).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "axis/axis_channel.hpp"
#include "axis/command_buffer.hpp"
#include "axis/compensation.hpp"
#include "axis/drive.hpp"
#include "axis/error_propagation.hpp"
#include "axis/external_setpoint.hpp"
#include "axis/master_job.hpp"
#include "axis/modulo_period.hpp"
#include "axis/monitors.hpp"
#include "axis/position_controller.hpp"
#include "axis/set_value_source.hpp"
#include "axis/slave_link.hpp"
#include "axis/superposition_stack.hpp"
#include "homing/homing_job.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/profile.hpp"
#include "part_of.hpp"
#include "plc_interface/two_speed.hpp"
#include "two_speed/two_speed_axis.hpp"

namespace nc::detail {

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

struct AxisCore;

// What phase (f) publishes that only events change (publish.cpp): the StateDWord bits of the
// enables and the error, the job, the homing, MC_Stop's lock and "has been stopped", the
// coupling, the superpositions and the C7 delay (kept here), what the constant-velocity bit
// needs of the job, and whether a rare state runs; event_image() also writes the NcToPlc fields
// that only events change (AxisState, CoupleState, the compensation's values, TargetVelo and
// GearRatio but a coupled slave's, the channel's five). AxisCore keeps one, renewed in the publish
// after note_event() or a change of the channel; event_image() computes it in full (the kept one
// and the published fields must always equal it: the tests and the fuzz watch compare them every
// cycle, KernelAxes::published_image_consistent).
struct EventImage {
  uint32_t state_bits = 0;
  JobKind job_kind = JobKind::kNone;
  // A homing, a superposition (compensation, external generation, held offset) or the C8 filter
  // runs: the steady cycle takes the full body of its phases (servo_axis.cpp,
  // ServoPhases::cycle_alone).
  bool rare = false;
  double constant_acceleration = 0.0;  // |SetAcc| up to this counts as constant velocity
  bool operator==(const EventImage&) const noexcept = default;
};
// The one full recomputation: the image, with its NcToPlc fields written into `out`.
EventImage event_image(const AxisCore& a, plc::NCTOPLC_AXIS_REF& out) noexcept;
// The kept image is event_image() and the published NcToPlc shows it (the check; a two-speed
// axis, which publishes in full, always passes). After a cycle, before the PLC writes PlcToNc.
bool image_consistent(const AxisCore& a) noexcept;

struct AxisCore {
  // `scratch`: the kernel's planning profile, shared by all its axes (one plans at a time).
  AxisCore(const AxisConfig& config, double cycle_time, std::size_t index, Profile& scratch)
      : cycle_time_(cycle_time), index_(index), scratch_(scratch), config_(config) {}

  // The one basic source of this cycle (set_value_source.hpp). `may_be_coupled` false: the caller
  // knows the axis is no coupled slave; `quiet`: no homing and no external generation runs
  // (ServoPhases::cycle_alone); those tests are left out.
  SetValueSource source(bool may_be_coupled = true, bool quiet = false) const noexcept;
  // The motion a new job, a stop or the error ramp takes over (its limits, K4, K5, K8): the
  // running homing's, else the job's.
  const MasterJob& running_motion() const noexcept {
    return homing_.active() ? homing_.motion() : job_;
  }
  // +1 / -1 while the set velocity has that sign, 0 at standstill (MC_Current_Direction).
  double current_direction() const noexcept {
    return set_.v > 0.0 ? 1.0 : (set_.v < 0.0 ? -1.0 : 0.0);
  }
  // The axis goes into error: the running job fails with `code`, and the set values ramp down
  // on the emergency deceleration and jerk (SPEC A6). The first error is kept. `own`: the axis's
  // own error, which starts its group reaction (SPEC C7); false for the group's reaction itself.
  void raise_error(ErrorCode code, bool own = true) noexcept;
  // SPEC A6: the set values ramp down from the set state they have now, on the emergency
  // deceleration and jerk (with `running`'s larger jerk where needed, K5); without the controller
  // enable the job just ends (the drive is off).
  void start_error_ramp(const MasterJob& running) noexcept;
  // The new job replaces the running one: the replaced command is answered kAborted.
  void accept(JobKind kind, uint16_t number, const Profile& profile, double target,
              double target_velocity, const Limits& limits) noexcept;
  // The set state without the running compensation and the external offset: where a replan of
  // the basic motion starts when the superpositions are to go on.
  KinematicState basic_state() const noexcept { return stack_.basic_state(base_, set_); }
  // A job planned from set_ starts: SuperpositionStack::fold(), and the basic motion is set_.
  void fold_superpositions(plc::CommandState state, ErrorCode code = ErrorCode::kNone) noexcept {
    note_event();
    stack_.fold(channel_, state, code);
    base_ = set_;
  }
  // Reset, or the controller enable gone: the external generation is switched off at once.
  void end_external_generation() noexcept {
    if (!stack_.external.taking()) return;  // nothing to end (end_external() would do nothing)
    note_event();
    if (stack_.end_external()) base_ = KinematicState{set_.p, 0.0, 0.0};
  }

  // What a steady cycle touches comes first, close together (docs/performance.md "Kernel cycle",
  // "Third pass"): the hot members, then the parts of which it reads only the flag they keep
  // first; the stack and the channel each from a cache line of their own; the job with its
  // profile's header first; the configuration last. prefetch_axis_lines and prefetch_cycle_data
  // (servo_axis.hpp) name these lines: keep them in step.
  // Kind kTwoSpeed: the phases run this instead of the servo path (AxisKind dispatch).
  std::unique_ptr<TwoSpeedAxis> two_speed_;
  double cycle_time_;
  // The configuration values a steady cycle reads, copied here (config_ below stays cold); and
  // encoder_ below, with the other flags.
  double modulo_factor_ = 360.0;
  double standstill_window_ = 0.0;
  // The periods of the published ModuloActPos and ModuloSetPos (phase (f)).
  ModuloPeriod modulo_act_{};
  ModuloPeriod modulo_set_{};
  PositionController controller_{};
  Drive drive_{};
  Monitors monitors_{};

  KinematicState set_{};   // set values of this cycle (basic motion + superpositions)
  KinematicState base_{};  // the basic source's own set values
  // d − q of the last cycle phase (c) gave a drive command (0 without HLI coupling): program
  // coordinate = drive − offset; and the drive position phase (d) controlled to last.
  double previous_drive_position_ = 0.0;
  double drive_offset_ = 0.0;
  double set_jerk_ = 0.0;
  double previous_set_position_ = 0.0;
  EventImage image_{};   // kept: see EventImage
  double target_ = 0.0;  // end position of the last positioning / stop; window monitors use it
  double hand_velocity_ = 0.0;        // push_by_hand(), mm/s
  uint32_t control_seen_ = 0;         // PlcToNc.ControlDWord as the last check_enables() read it
  bool encoder_ = false;              // config_.kind == AxisKind::kEncoder
  bool drive_command_given_ = false;  // phase (c) gave drive_command_ in this cycle
  bool error_event_ = false;          // an error was raised in this cycle
  bool group_ready_ = false;          // see set_group_ready()
  bool by_hand_ = false;              // case 2 in force (follows_by_hand() latched)
  bool events_ = true;                // an event since image_ was computed (note_event())
  bool buffer_waiting_ = false;       // a command waits in buffer_ (command_buffer.hpp)
  // C7 / C8 (error_propagation.cpp), the coupling link and the homing: a steady cycle reads only
  // the flag each keeps first, so they follow the members above in the order of their size.
  PropagationDelay propagation_{};
  // Read on events only (a command, an error, a coupling, the image's recomputation), so after
  // the C7 delay's flag: the hot members above stay within seven cache lines.
  std::size_t index_;
  uint32_t slave_count_ = 0;  // axes coupled to this one as their master
  // The axis errors raised, counted wrapping (the HLI phase: an error raised and reset between two
  // phases (c) still shows as a change).
  uint32_t errors_raised_ = 0;
  plc::CoupleState hli_role_ = plc::CoupleState::kSingle;  // from phase (c), see there
  // Referenced (StateDWord bit 1): the software limits are monitored only then.
  bool homed_ = true;
  bool locked_ = false;  // MC_Stop: motion commands refused until kStopRelease
  bool has_been_stopped_ = false;
  ActualValueFilter actual_filter_{};
  SlaveLink slave_link_{};
  HomingJob homing_{};  // its phase first: a steady cycle that is not quiet reads only that
  // Phase (c): what phase (d) controls to when given this cycle (else set_).
  KinematicState drive_command_{};
  BasicPath slave_path_{};  // while coupled: the master's path of this cycle, transformed

  // Something EventImage shows may have changed (a command, an error, a job's end, a coupling,
  // a superposition, the C7 delay, …): the next publish computes the image anew. Called where
  // those change; a call too many costs one recomputation, one too few a stale image.
  void note_event() noexcept { events_ = true; }
  bool hli_target() const noexcept {
    return hli_role_ == plc::CoupleState::kSlave || hli_role_ == plc::CoupleState::kMasterAndSlave;
  }
  bool hli_source() const noexcept {
    return hli_role_ == plc::CoupleState::kMaster || hli_role_ == plc::CoupleState::kMasterAndSlave;
  }
  const KinematicState& drive_command() const noexcept {
    return drive_command_given_ ? drive_command_ : set_;
  }
  // The axis's own job's path, or slave_path_ while coupled.
  BasicPath basic_path() const noexcept;
  double target_velocity() const noexcept {  // basic_path().target_velocity, without the rest
    if (slave_link_.coupled) return slave_path_.target_velocity;
    return job_.active() ? job_.goal.target_velocity() : 0.0;
  }
  void set_homed(bool homed) noexcept {
    note_event();
    homed_ = homed;
    monitors_.set_referenced(homed);
  }

  // Each at the start of a cache line: the stack's first 128 bytes, the channel's first 256
  // (its AXIS_REF's PlcToNc, NcToPlc and the mailbox's count) and the job's first lines (its
  // kind, online state, table and profile header and the current segment) are what a steady
  // cycle reads.
  alignas(64) SuperpositionStack stack_{};
  alignas(64) AxisChannel channel_{};
  alignas(64) MasterJob job_{};
  CommandBuffer buffer_{};
  Profile& scratch_;  // a start is planned here first, so a refusal changes nothing
  AxisConfig config_;
};

// Inline: both run in every cycle's set values phase.
inline BasicPath AxisCore::basic_path() const noexcept {
  if (slave_link_.coupled) return slave_path_;
  const JobKind kind = job_.kind();
  BasicPath path;
  path.running = job_.active() && !job_.table.generation_ended();
  path.stopping =
      kind == JobKind::kHalt || kind == JobKind::kStop || kind == JobKind::kEmergencyStop;
  path.positioning = kind == JobKind::kPosition;
  path.has_target = job_.active() && kind != JobKind::kVelocity;
  path.target = job_.goal.target();
  path.target_velocity = job_.active() ? job_.goal.target_velocity() : 0.0;
  return path;
}

inline SetValueSource AxisCore::source(bool may_be_coupled, bool quiet) const noexcept {
  // A coupled slave has no job.
  if (may_be_coupled && slave_link_.coupled) return SetValueSource::kSlaveLink;
  if (!quiet && homing_.active()) return SetValueSource::kHomingJob;
  if (job_.active()) return SetValueSource::kPtpJob;
  if (quiet) return SetValueSource::kHold;
  const ExternalSetpoint& external = stack_.external;
  if (external.taking() && external.type() == ExternalSetpoint::Type::kAbsolute) {
    return SetValueSource::kExternalAbsolute;
  }
  return SetValueSource::kHold;
}

// The base of the parts of a servo axis (axis_commands.hpp, online_change.hpp, …).
using AxisPart = PartOf<AxisCore>;

}  // namespace nc::detail
