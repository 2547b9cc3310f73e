// The phases of the NC cycle for one axis (the kernel runs each over all axes), the NC→PLC image
// of phase (f) (SPEC A7), and the two parts they call in every cycle, kept in this file so that
// they inline into the phases: AxisMotion (set values, position control, drive) and
// AxisMonitoring (enables, monitors, job completion) (SPEC A3, A4, A6). run_cycles_alone() is
// all of the axes' cycle in one function (docs/performance.md "Fourth pass", "Sixth pass").
#include "axis/servo_axis.hpp"

#include <cmath>
#include <cstdlib>

#include "axis/axis_commands.hpp"
#include "axis/axis_monitoring.hpp"
#include "axis/axis_motion.hpp"
#include "axis/buffered_commands.hpp"
#include "axis/group_errors.hpp"
#include "axis/nc_to_plc.hpp"
#include "axis/online_change.hpp"
#include "axis/slave_coupling.hpp"
#include "axis/steady_lane.hpp"
#include "homing/axis_homing.hpp"

namespace nc::detail {

using plc::CommandState;

namespace {

// The snapshot but the group reaction and what a master driving its slaves by its actual values
// gives them (written by the phases): the target and the basic path, the set values (with the
// jerk), the actual values, the error with its event and the enables, as the axis has them now
// (ServoAxis::fill_snapshot()).
void write_snapshot(const AxisCore& a, AxisSnapshot& snapshot) noexcept {
  const BasicPath path = a.basic_path();
  snapshot.target_position = a.target_;
  snapshot.target_velocity = path.target_velocity;
  snapshot.path_running = path.running;
  snapshot.path_stopping = path.stopping;
  snapshot.path_positioning = path.positioning;
  snapshot.path_has_target = path.has_target;
  snapshot.error = a.channel_.error();
  snapshot.error_event = a.error_event_;
  const uint32_t control = a.control_seen_;  // the enables of this cycle (PlcToNc may have changed)
  snapshot.controller_enabled = plc::test_bit(control, plc::kControlEnable);
  snapshot.feed_enabled_plus = plc::test_bit(control, plc::kControlFeedEnablePlus);
  snapshot.feed_enabled_minus = plc::test_bit(control, plc::kControlFeedEnableMinus);
  snapshot.set_position = a.set_.p;  // without the controller enable it follows the actual one
  snapshot.set_velocity = a.set_.v;
  snapshot.set_acceleration = a.set_.a;
  snapshot.set_jerk = a.set_jerk_;
  snapshot.actual_position = a.drive_.measured_position();
  snapshot.actual_velocity = a.drive_.velocity();
  snapshot.actual_acceleration = a.drive_.acceleration();
}

// The set values phase (d) controls to: phase (c)'s drive command when given this cycle, else the
// program's. `kAlone`: in ServoAxis::run_cycles_alone() (HLI stage not engaged), where it is never
// given.
template <bool kAlone>
const KinematicState& drive_command(const AxisCore& a) noexcept {
  if constexpr (kAlone) return a.set_;
  return a.drive_command();
}

// The phases of a servo axis (not a two-speed one): the bodies of ServoAxis's phases, which hand a
// two-speed axis over to its TwoSpeedAxis first. run_cycles_alone() looks at the kind once and
// runs these (the check in each phase cost 14 instructions per axis-cycle, docs/performance.md
// "Fifth pass").
// `kAlone`: the bodies for cycle_alone(), which the kernel runs only while nothing is coupled,
// no coupling command waits and the HLI stage is not engaged; there no axis is a coupled or
// detached slave or has slaves, and phase (c) gives no drive command, so those tests are left out
// (docs/performance.md "Sixth pass"). `kQuiet`: the bodies of phases (b) to (e) for an axis in
// no rare state (EventImage::rare: no homing, no superposition, no C8 filter), which only phase
// (a) could start; cycle_alone() chooses them after phase (a) when nothing has happened
// since the last publish.
class ServoPhases : public AxisPart {
 public:
  using AxisPart::AxisPart;
  template <bool kAlone>
  void commands(CouplingPort& port) noexcept {
    AxisCore& a = s_;
    // The steady lane's horizon holds only from one cycle_alone() to the next.
    if constexpr (!kAlone) SteadyLane::leave(a.job_.table);
    a.error_event_ = false;
    a.drive_command_given_ = false;
    OnlineChange(a).read_override();
    AxisCommands(a).handle_commands(port);
    AxisMonitoring(a).check_enables<kAlone>();
    // command_buffer.cpp: a waiting command takes over; a pass left alone stops. Neither without
    // a waiting command or a pass.
    if (a.buffer_waiting_ || a.job_.passing()) {
      a.note_event();
      BufferedCommands(a).run_buffer(port);
    }
    if (a.job_.is_motion()) {
      OnlineChange(a).run_online_functions();  // only a motion job has online functions
    }
  }
  template <bool kAlone, bool kQuiet = false>
  void set_values(AxisSnapshot& snapshot, std::span<const AxisSnapshot> snapshots,
                  bool shared) noexcept {
    AxisCore& a = s_;
    // K26: a slave whose master's drive went off under it leaves and brakes on its own ramp.
    if (!kAlone && a.slave_link_.coupled) {
      GroupErrors(a).leave_master_without_drive(snapshots[a.slave_link_.master]);
    }
    if (!kAlone && a.slave_link_.coupled) {
      // Seed 000 §3.2.2: slave target velocity = coupling factor × master target velocity; the
      // target position likewise (a compensation on the slave moves it on, seed 000 §3.2.4).
      const AxisSnapshot& master = snapshots[a.slave_link_.master];
      a.slave_path_ =
          BasicPath{master.path_running,
                    master.path_stopping,
                    master.path_positioning,
                    master.path_has_target,
                    a.slave_link_.factor * master.target_position + a.slave_link_.offset,
                    a.slave_link_.factor * master.target_velocity};
      a.target_ = a.slave_path_.target;
    }
    AxisMotion(a).generate_set_values<kAlone, kQuiet>(snapshots);
    // The set values and the path, read in this cycle by slaves and the HLI stage (after the
    // cycle Kernel::snapshot() fills the snapshot in).
    if (shared) write_snapshot(a, snapshot);
    // C8: the filtered actual values instead (error_propagation.cpp); without slaves and a filter
    // running it has nothing to do.
    if ((!kAlone && a.slave_count_ != 0) || (!kQuiet && a.actual_filter_.active)) {
      GroupErrors(a).publish_for_slaves(snapshot);
    }
  }
  template <bool kAlone>
  void drive() noexcept {
    AxisCore& a = s_;
    AxisMotion(a).control_and_drive<kAlone>();
    a.previous_drive_position_ = drive_command<kAlone>(a).p;
    // The set and actual values the snapshot shows after the cycle: no axis reads them in the
    // rest of it, so Kernel::snapshot() fills them (fill_snapshot()).
  }
  template <bool kAlone, bool kQuiet = false>
  void monitors(AxisSnapshot& snapshot, bool shared) noexcept {
    AxisCore& a = s_;
    AxisMonitoring(a).run_monitors<kAlone, kQuiet>();
    AxisMonitoring(a).finish_job<kQuiet>();
    if (a.propagation_.pending) {
      a.note_event();  // the C7 delay runs (StateDWord bit 6) and ends here
      snapshot.group_reaction_due = GroupErrors(a).group_reaction_due();
    } else {
      snapshot.group_reaction_due = false;
    }
    // The group reactions read the errors and the enables (after the cycle Kernel::snapshot()
    // fills the snapshot in).
    if (shared) write_snapshot(a, snapshot);
    // The precondition of SPEC C8 case 2 for the group of this axis alone; for the head of a larger
    // group the kernel replaces it after the group reactions (Kernel::mark_ready_groups).
    if (kAlone || (!a.slave_link_.coupled && !a.slave_link_.detached)) {
      a.group_ready_ =
          !a.channel_.has_error() && plc::test_bit(a.control_seen_, plc::kControlEnable);
    }
  }
  // `kLane`: in the steady lane (lane()), where no event has happened and the job is a
  // positioning whose generation runs.
  template <bool kAlone, bool kLane = false>
  void publish(uint64_t cycle_counter) noexcept {
    AxisCore& a = s_;
    plc::NCTOPLC_AXIS_REF& out = a.channel_.ref().NcToPlc;
    if (!kLane && (a.events_ || a.channel_.changed())) {
      // Something the image shows may have changed since the last publish (note_event(), or the
      // channel's error, command or warnings).
      a.events_ = false;
      a.channel_.published();
      a.image_ = event_image(a, out);
    }
    if (!kAlone && a.slave_link_.coupled) {  // the master's target velocity, a cyclic factor
      out.TargetVelo = a.slave_path_.target_velocity;
      out.GearRatio = a.slave_link_.factor;
    }
    const double actual = a.drive_.measured_position();

    const KinematicState& command = drive_command<kAlone>(a);  // d: what phase (d) controlled to
    out.SetPos = command.p;
    out.SetVelo = command.v;
    out.SetAcc = command.a;
    out.SetJerk = a.set_jerk_;
    out.ActPos = actual;
    out.ActVelo = a.drive_.velocity();
    out.ActAcc = a.drive_.acceleration();
    out.PosDiff = command.p - actual;
    out.ModuloActPos = a.modulo_act_.position(actual, a.modulo_factor_);
    out.ModuloSetPos = a.modulo_set_.position(command.p, a.modulo_factor_);
    out.TargetPos = a.target_;
    out.CycleCounter = static_cast<uint32_t>(cycle_counter);

    // Constant velocity: a velocity job at its level, or the cruise phase of a positioning.
    const JobKind kind = a.image_.job_kind;
    const bool cruise = (a.set_.v != 0.0) & (std::abs(a.set_.a) <= a.image_.constant_acceleration) &
                        (a.set_jerk_ == 0.0);
    const bool constant_velocity =
        kLane ? cruise
              : (kind == JobKind::kVelocity && a.job_.table.velocity_reached()) ||
                    (kind == JobKind::kPosition && !a.job_.table.generation_ended() && cruise);

    uint32_t word = a.image_.state_bits | a.monitors_.window_state_bits();
    set_state_bit(word, plc::kStateNotMoving, std::abs(a.drive_.velocity()) < a.standstill_window_);
    set_state_bit(word, plc::kStatePositiveDirection, a.set_.v > 0.0);
    set_state_bit(word, plc::kStateNegativeDirection, a.set_.v < 0.0);
    set_state_bit(word, plc::kStateConstantVelocity, constant_velocity);
    set_state_bit(word, plc::kStateSoftLimitMinExceeded, a.monitors_.below_min(actual));
    set_state_bit(word, plc::kStateSoftLimitMaxExceeded, a.monitors_.above_max(actual));
    out.StateDWord = word;
#ifdef NCSDK_CHECK_EVENT_IMAGE
    // A check build (-DNCSDK_CHECK_EVENT_IMAGE): a missed note_event() stops the program here.
    if (!image_consistent(a)) std::abort();
#endif
  }
  // The steady lane (steady_lane.hpp): phases (b) to (f) of a cycle in which, within the
  // horizon, the full bodies would decide nothing but the following error's.
  void lane(AxisSnapshot& snapshot, uint64_t cycle_counter) noexcept {
    AxisCore& a = s_;
#ifdef NCSDK_CHECK_EVENT_IMAGE
    check_lane();
#endif
    // (b): generate_set_values() of a running positioning, its sample in the horizon's segment.
    a.previous_set_position_ = a.set_.p;
    a.base_ = SteadyLane::advance(a.job_.table, a.cycle_time_);
    a.set_jerk_ = a.job_.table.jerk();
    a.set_ = KinematicState{a.base_.p + a.stack_.held(), a.base_.v, a.base_.a};
    drive<true>();
    // (e): the following error; once it counts, the full monitors take this cycle on.
    if (!a.monitors_.lag_within(a.set_.p - a.drive_.measured_position())) {
      monitors<true, true>(snapshot, false);
      publish<true>(cycle_counter);
      SteadyLane::enter(a);
      return;
    }
    publish<true, true>(cycle_counter);
  }
#ifdef NCSDK_CHECK_EVENT_IMAGE
  // A check build: the lane's cycle is the one the full bodies would run. Its horizon is the one
  // SteadyLane::enter() finds now (the state it was computed from has not changed), phase (a)
  // has nothing to do, and the next sample is the table's inner path on the cursor's segment.
  // What no horizon covers: the rare states (EventImage::rare) and the C8 filter.
  void check_lane() const {
    const AxisCore& a = s_;
    if (!SteadyLane::lane_holds(a) || a.channel_.ref().Mailbox.pending() != 0 ||
        a.stack_.held() != 0.0 || !a.stack_.empty() || a.homing_.active() ||
        a.actual_filter_.active) {
      std::abort();
    }
  }
#endif
  // Phases (a) to (f) in ServoAxis::run_cycles_alone().
  void cycle_alone(CouplingPort& port, AxisSnapshot& snapshot,
                   std::span<const AxisSnapshot> snapshots, uint64_t cycle_counter) noexcept {
    AxisCore& a = s_;
#ifdef NCSDK_CHECK_EVENT_IMAGE
    // A check build: what the kAlone bodies take as known holds.
    if (a.slave_link_.coupled || a.slave_link_.detached || a.slave_count_ != 0) std::abort();
#endif
    // Within the steady lane's horizon, with the PLC's side as the last cycle saw it (nothing
    // posted, ControlDWord and Override unchanged) and no event since: the lane.
    const plc::PLCTONC_AXIS_REF& in = a.channel_.ref().PlcToNc;
    if (SteadyLane::next(a.job_.table) && a.channel_.ref().Mailbox.pending() == 0 &&
        in.ControlDWord == a.control_seen_ && in.Override == a.job_.online.override_value() &&
        !(a.events_ | a.channel_.changed())) {
      lane(snapshot, cycle_counter);
      return;
    }
    commands<true>(port);
    // Nothing happened since the last publish (its image says no rare state runs) and phase (a)
    // started nothing: the quiet bodies.
    if (a.events_ || a.image_.rare || a.channel_.changed()) {
      set_values<true>(snapshot, snapshots, false);
      drive<true>();
      monitors<true>(snapshot, false);
    } else {
#ifdef NCSDK_CHECK_EVENT_IMAGE
      // A check build: what the quiet bodies take as known holds.
      if (a.homing_.active() || !a.stack_.empty() || a.actual_filter_.active) std::abort();
#endif
      set_values<true, true>(snapshot, snapshots, false);
      drive<true>();
      monitors<true, true>(snapshot, false);
    }
    publish<true>(cycle_counter);
    SteadyLane::enter(a);
  }
};

}  // namespace

ServoAxis::ServoAxis(const AxisConfig& config, double cycle_time, std::size_t index,
                     Profile& scratch)
    : AxisCore(config, cycle_time, index, scratch) {
  encoder_ = config_.kind == AxisKind::kEncoder;
  modulo_factor_ = config_.modulo_factor;
  standstill_window_ = config_.standstill_window;
  controller_.kv = config_.position_kv;
  controller_.feed_forward = config_.velocity_feed_forward;
  drive_.configure(config_, cycle_time_, 0.0);
  monitors_.configure(config_, cycle_time_);
  set_homed(config_.homed_at_start);
  set_ = KinematicState{drive_.measured_position(), 0.0, 0.0};
  previous_set_position_ = set_.p;
  target_ = set_.p;
  if (config_.kind == AxisKind::kTwoSpeed) {
    two_speed_ = std::make_unique<TwoSpeedAxis>(config_, cycle_time_, channel_);
  }
  phase_publish(0);
}

void ServoAxis::phase_commands(CouplingPort& port) noexcept {
  if (two_speed_) return two_speed_->phase_commands();
  ServoPhases(*this).commands<false>(port);
}

namespace {

// How many axes ahead the steady loop asks for an axis's lines at fixed places, and for those
// they point to (docs/performance.md "Tenth pass").
constexpr std::size_t kLinesAhead = 4;
constexpr std::size_t kDataAhead = 2;

}  // namespace

// Flattened: the phases and their parts in this file inline into one function, so the steady
// path of an axis's cycle is one body (docs/performance.md "Fourth pass": 68 instructions per
// axis-cycle fewer than five calls); the axis's kind is looked at once ("Fifth pass"); and that
// body is the loop's, so the registers are saved once per cycle, not once per axis ("Sixth pass").
[[gnu::flatten]] void ServoAxis::run_cycles_alone(std::span<const std::unique_ptr<ServoAxis>> axes,
                                                  std::span<AxisSnapshot> snapshots,
                                                  CouplingPort& port,
                                                  uint64_t cycle_counter) noexcept {
  // The arrays in locals: the call of each axis could change the members, so they would be
  // loaded again after each (the vectors do not change in a cycle).
  const std::unique_ptr<ServoAxis>* const axis = axes.data();
  AxisSnapshot* const snapshot = snapshots.data();
  const std::size_t n = axes.size();
  const std::span<const AxisSnapshot> all(snapshot, n);
  for (std::size_t i = 0; i < n; ++i) {
    // The data of the next axes is on its way while this one runs.
    if (i + kLinesAhead < n) prefetch_axis_lines(*axis[i + kLinesAhead]);
    if (i + kDataAhead < n) prefetch_cycle_data(*axis[i + kDataAhead], snapshot[i + kDataAhead]);
    ServoAxis& s = *axis[i];
    if (s.two_speed_) {
      s.phase_commands(port);
      s.run_alone(snapshot[i], all, cycle_counter);
    } else {
      ServoPhases(s).cycle_alone(port, snapshot[i], all, cycle_counter);
    }
  }
}

void ServoAxis::phase_set_values(AxisSnapshot& snapshot, std::span<const AxisSnapshot> snapshots,
                                 bool shared) noexcept {
  if (two_speed_) return two_speed_->phase_set_values(snapshot);
  ServoPhases(*this).set_values<false>(snapshot, snapshots, shared);
}

// Phase (f): the NC→PLC image; what only events change comes from image_ (publish.cpp).
void ServoAxis::phase_publish(uint64_t cycle_counter) noexcept {
  if (two_speed_) return two_speed_->phase_publish(cycle_counter, static_cast<int32_t>(index_));
  ServoPhases(*this).publish<false>(cycle_counter);
}

void ServoAxis::phase_drive_command(const KinematicState& drive, ErrorCode stop,
                                    plc::CoupleState role) noexcept {
  if (two_speed_) return;  // never an HLI target (the stage refuses it, 0x4040): d = q
  if (stop != ErrorCode::kNone) raise_error(stop);
  if (role != hli_role_) note_event();  // CoupleState, AxisState
  hli_role_ = role;
  drive_command_ = drive;
  drive_offset_ = drive.p - set_.p;
  drive_command_given_ = true;
}

void ServoAxis::phase_drive(AxisSnapshot& snapshot) noexcept {
  if (two_speed_) return two_speed_->phase_drive(snapshot);
  ServoPhases(*this).drive<false>();
}

void ServoAxis::fill_snapshot(AxisSnapshot& snapshot) const noexcept {
  if (two_speed_) return;  // its phases write them
  write_snapshot(*this, snapshot);
}

void ServoAxis::phase_monitors(AxisSnapshot& snapshot, bool shared) noexcept {
  if (two_speed_) return two_speed_->phase_monitors(snapshot);
  ServoPhases(*this).monitors<false>(snapshot, shared);
}

// --- AxisMonitoring ---

template <bool kAlone>
void AxisMonitoring::check_enables() noexcept {
  AxisCore& a = s_;  // held in a register: no reload of s_ after each store
  const uint32_t control = a.channel_.ref().PlcToNc.ControlDWord;
  const bool enabled = plc::test_bit(control, plc::kControlEnable);
  const bool seen = plc::test_bit(a.control_seen_, plc::kControlEnable);
  const bool lost = seen && !enabled;
  if (enabled != seen) a.note_event();  // StateDWord's Operational, AxisState
  a.control_seen_ = control;
  if (kAlone || a.slave_count_ == 0) {  // no group follows this axis: never case 2
    GroupErrors(a).end_by_hand();
  } else {
    a.note_event();
    if (GroupErrors(a).update_by_hand()) return;  // C8 case 2: the group follows by hand
  }
  if (!enabled) {
    a.note_event();
    // Losing the controller enable while a command runs is an axis error (enable_loss.cpp);
    // there is no ramp to run (the drive is off), so the job ends here and the set values follow
    // the actual position.
    if (GroupErrors(a).enable_loss_is_error(lost)) a.raise_error(ErrorCode::kControllerEnableLost);
    a.job_.clear();
    return;
  }
  // Feed enable removed in the direction of travel: the axis stops on its error ramp (also when
  // external setpoints move it; a coupled slave's error stops its group, see Kernel).
  if ((a.job_.is_motion() || a.homing_.active() || a.stack_.external.enabled() ||
       (!kAlone && a.slave_link_.coupled)) &&
      !a.channel_.has_error()) {
    if (a.set_.v > 0.0 && !a.channel_.feed_enabled(1.0)) {
      a.raise_error(ErrorCode::kFeedEnablePlusMissing);
    } else if (a.set_.v < 0.0 && !a.channel_.feed_enabled(-1.0)) {
      a.raise_error(ErrorCode::kFeedEnableMinusMissing);
    }
  }
}

template <bool kAlone, bool kQuiet>
void AxisMonitoring::run_monitors() noexcept {
  AxisCore& a = s_;  // held in a register: no reload of s_ after each store
  const double actual = a.drive_.measured_position();
  const bool armed = a.channel_.controller_enabled() && !a.channel_.has_error();
  if (a.monitors_.following_error(drive_command<kAlone>(a).p - actual, armed)) {
    a.raise_error(ErrorCode::kFollowingErrorPosition);
  }
  // Software limits during motion: the set position passes an enabled limit while it moves
  // outward. Moving back in from outside (seed 000 §2.1 note 5) is not an error.
  const bool moving_on_its_own = a.job_.active() && a.job_.kind() != JobKind::kEmergencyStop;
  if (!a.channel_.has_error() && (moving_on_its_own || (!kAlone && a.slave_link_.coupled))) {
    if (a.set_.v > 0.0 && a.monitors_.above_max(a.set_.p)) {
      a.raise_error(ErrorCode::kSoftLimitMaxDuringMotion);
    } else if (a.set_.v < 0.0 && a.monitors_.below_min(a.set_.p)) {
      a.raise_error(ErrorCode::kSoftLimitMinDuringMotion);
    }
  }
  // The windows count only once set-value generation rests: the job has ended and the external
  // generator (seed 000 §2.6) is not feeding a motion (direction ±1), so a fed motion passing
  // through its target window is not "in target position".
  const bool settled = a.channel_.controller_enabled() && (kQuiet || !a.stack_.external.moving()) &&
                       (kAlone || !a.slave_link_.coupled) && (kQuiet || !a.homing_.active()) &&
                       (!a.job_.active() ||
                        (a.job_.kind() != JobKind::kVelocity && a.job_.table.generation_ended()));
  a.monitors_.windows(actual - a.drive_offset_, a.target_, settled);  // in program coordinates
}

template <bool kQuiet>
void AxisMonitoring::finish_job() noexcept {
  AxisCore& a = s_;  // held in a register: no reload of s_ after each store
  // A job answers Done only while it is the command the axis executes and still runs: a job
  // without a number of its own (a slave decoupled in motion goes on with its master's plan)
  // must not answer CmdNo, which may be a command already answered (fuzz finding K12). Asked
  // as the cycle's monitors left the channel: before a homing's Done, else when a job ends
  // (nothing between here and there answers).
  // (Not a constant in the quiet body, so that the lambda's captures stay the same in both.)
  bool homing_done = false;
  if constexpr (!kQuiet) homing_done = a.homing_.finished();
  const bool own_before_homing = homing_done && a.channel_.runs(a.job_.number());
  const auto own = [&a, homing_done, own_before_homing]() noexcept {
    return homing_done ? own_before_homing : a.channel_.runs(a.job_.number());
  };
  if (homing_done) {
    a.note_event();
    a.channel_.answer_current(CommandState::kDone);
    a.homing_.clear();
    a.target_ = a.set_.p;  // where the homing stopped: the windows watch it from now on
  }
  switch (a.job_.kind()) {
    case JobKind::kNone:
      break;
    case JobKind::kPosition:
      // Done = set-value generation ended and the target window reached (or switched off). A
      // pass (blending) is done when the waiting command takes over (command_buffer.cpp).
      if (a.job_.table.generation_ended() && !a.job_.passing() &&
          a.monitors_.in_target_position()) {
        a.note_event();
        if (own()) a.channel_.answer_current(CommandState::kDone);
        a.job_.clear();
      }
      break;
    case JobKind::kVelocity:
      if (a.job_.table.velocity_reached() && a.channel_.cmd_state() == CommandState::kActive) {
        a.channel_.answer_current(CommandState::kReached);
      }
      break;
    case JobKind::kHalt:
    case JobKind::kStop:
      if (a.job_.table.generation_ended()) {
        a.note_event();
        if (own()) a.channel_.answer_current(CommandState::kDone);
        a.job_.clear();
      }
      break;
    case JobKind::kEmergencyStop:
      if (a.job_.table.generation_ended()) {
        a.note_event();
        a.job_.clear();
      }
      break;
  }
}

// --- AxisMotion ---

template <bool kAlone, bool kQuiet>
void AxisMotion::generate_set_values(std::span<const AxisSnapshot> snapshots) noexcept {
  AxisCore& a = s_;  // held in a register: no reload of s_ after each store
  a.previous_set_position_ = a.set_.p;
  if (!a.channel_.controller_enabled()) {
    a.set_jerk_ = 0.0;  // no generation: control_and_drive() makes the set position follow
    a.end_external_generation();  // seed 000 §2.6: the controller enable's edge switches it off
    // A coupled slave follows again from where it stands when the enable returns; its
    // compensation ends with the enable (the offset taken anew includes what it did).
    if (!kAlone && a.slave_link_.coupled) {
      a.slave_link_.retake_offset = true;
      if (a.stack_.compensation.running() || a.stack_.held() != 0.0) {
        a.fold_superpositions(CommandState::kAborted);
      }
    }
    return;
  }
  bool not_finite = false;
  bool too_large = false;
  bool absolute_ended = false;
  switch (a.source(!kAlone, kQuiet)) {
    case SetValueSource::kPtpJob:
      a.base_ = a.job_.advance(a.cycle_time_);
      a.set_jerk_ = a.job_.table.jerk();
      break;
    case SetValueSource::kExternalAbsolute: {
      a.note_event();  // the generator may end
      const ExternalSetpoint::Step step =
          a.stack_.external.take(a.channel_.ref().PlcToNc, a.cycle_time_);
      a.base_ = step.state;
      a.set_jerk_ = 0.0;
      not_finite = step.not_finite;
      too_large = step.too_large;
      absolute_ended = step.finished;
      break;
    }
    case SetValueSource::kSlaveLink: {
      const AxisSnapshot& master = snapshots[a.slave_link_.master];
      if (a.slave_link_.cyclic) SlaveCoupling(a).step_cyclic_factor(master);
      a.base_ = a.slave_link_.sample(master, a.set_.p);
      a.set_jerk_ = a.slave_link_.factor * master.followed_jerk();
      break;
    }
    case SetValueSource::kHomingJob:
      a.note_event();  // the homing's steps (set_homed(), its end)
      AxisHoming(a).run_homing();
      break;
    case SetValueSource::kHold:
      if (!kQuiet && a.stack_.moves_alone()) {
        a.base_.v = 0.0;  // the basic motion holds; a superposition may still move the axis
        a.base_.a = 0.0;
      } else {
        a.base_ = KinematicState{a.set_.p, 0.0, 0.0};  // the axis holds where it is
        // The held offset ends here (no offset while quiet): EventImage::rare changes.
        if (!kQuiet && a.stack_.held() != 0.0) a.note_event();
        a.stack_.drop_held();
      }
      a.set_jerk_ = 0.0;
      break;
  }
  if (kQuiet || a.stack_.empty()) {
    // The steady case: superimpose() would add the held ±0.0 and nothing else (the addition
    // kept for the sign of a zero). Without the stack there is no absolute packet either.
    a.set_ = KinematicState{a.base_.p + a.stack_.held(), a.base_.v, a.base_.a};
    return;
  }
  a.note_event();  // a compensation or the external generation may start or end here
  const BasicPath path = a.basic_path();
  SuperpositionStack::Basic basic;
  basic.state = a.base_;
  basic.path_running = path.running;
  basic.has_target = path.has_target;
  basic.target = path.target;
  const SuperpositionStack::Result r =
      a.stack_.superimpose(basic, a.channel_.ref().PlcToNc, a.channel_, a.cycle_time_);
  a.set_ = r.set;
  if (r.target_moved) a.target_ = r.target;
  if (absolute_ended) {
    a.base_ = KinematicState{a.set_.p, 0.0, 0.0};  // the last packet taken: the axis holds there
    a.stack_.drop_held();
  }
  // A packet with NaN or inf is not taken; the axis must not run on it (SPEC B8).
  if (not_finite || r.not_finite) a.raise_error(ErrorCode::kParameterNotFinite);
  // A finite packet out of range (external_setpoint.hpp) is not taken either: 0x4359.
  if (too_large || r.too_large) a.raise_error(ErrorCode::kSetVelocityNotAllowed);
}

template <bool kAlone>
void AxisMotion::control_and_drive() noexcept {
  AxisCore& a = s_;  // held in a register: no reload of s_ after each store
  if (a.encoder_) {
    // Encoder / virtual axis: no controller, the actual values are the set values.
    const KinematicState& command = drive_command<kAlone>(a);
    a.drive_.follow(command.p, command.v, command.a);
    return;
  }
  if (!a.channel_.controller_enabled()) {
    // TwinCAT: without controller enable the drive is off and the set position follows the
    // actual position, so there is no following error to jump at when the enable returns.
    a.drive_.step(a.hand_velocity_, a.hand_velocity_ != 0.0);  // Kernel::push_by_hand, else off
    a.drive_command_ = KinematicState{a.drive_.measured_position(), 0.0, 0.0};
    a.set_ = KinematicState{a.drive_.measured_position() - a.drive_offset_, 0.0, 0.0};
    a.target_ = a.set_.p;
    return;
  }
  const double previous =
      !kAlone && a.drive_command_given_ ? a.previous_drive_position_ : a.previous_set_position_;
  const double command = a.controller_.command(previous, drive_command<kAlone>(a).p,
                                               a.drive_.measured_position(), a.cycle_time_);
  a.drive_.step(command, true);
}

}  // namespace nc::detail
