// The invariants of issue 16 on one axis, checked from the PLC side only (the public AXIS_REF),
// shared by fuzz_blocks and the soak program (tools/soak):
//  - every double of NcToPlc is finite;
//  - |SetVelo| stays within the axis's max velocity and |SetAcc| within its largest acceleration
//    limit (A+, A-, emergency deceleration), each widened only by what the PLC itself asked for
//    and docs/behaviour.md documents as allowed: accelerations / decelerations given to a
//    move, MC_Halt or MC_Stop; a compensation's VK and AK± on top of the basic motion, and the
//    a² / 2J an error ramp from its acceleration passes (B7, K23); the fed external set values
//    (B8). The widening lasts until the axis rests again. A coupled
//    slave instead has GearRatio times its master's set velocity and acceleration (C1, C2), plus
//    what its own compensation may add (C5, the VK and AK± the program gave it); a
//    slave decoupled in motion goes on as it would have as a slave (C4, factor x its former
//    master's plan, then a replan from that state), so its own limits are not checked until it
//    rests;
//  - a homing axis (docs/behaviour.md "Homing"): while HomingBusy, |SetVelo| stays within its
//    larger homing velocity, or, for a homing that took over a motion, within the peak that
//    motion's set state leads to at the axis's jerk (|v| + a² / 2J, where it started); not on
//    an HLI target, whose image shows its drive (bounded by hli() instead);
//  - a cyclic slave (MC_GearInDyn, C6): SetVelo = GearRatio × its master's, and in a cycle in
//    which the factor in force moves, |SetAcc| stays within max(AccBound, |held factor × the
//    master's SetAcc|) (the rate nearest the AccBound interval, clamped at the commanded factor);
//    both plus what its own compensation may add, as on a linear slave;
//  - a coupled slave shows a GearRatio != 0, except one that left its coupling on its own error
//    under DELAYED propagation (C7) or because its master's drive went off under it (K26): it
//    shows as a slave with GearRatio 0 until MC_GearOut; and a
//    cyclic slave after its coupling's first cycle: its factor in force may pass 0 on its way to a
//    commanded factor of the other sign (C6; K27);
//  - an HLI target (docs/behaviour.md "HLI axis coupling", D3: its own dynamic limits are not
//    monitored): while a list is in force, |SetVelo| and |SetAcc| stay within the list's
//    Σ |K| × each source's program limits (what the PLC passes to hli()); once the list is off
//    (switched off, or 70200 / 70195 / an error braking the drive from at most that velocity at
//    the emergency deceleration), within the larger of its own limits and that bound, until it
//    rests;
//  - a two-speed axis (E4): SetVelo is 0 or ± rapid_velocity / creep_velocity, SetAcc 0,
//    |ActVelo| at most rapid_velocity (its own limits replace the servo ones);
//  - the set velocity never steps (fuzz finding K25): from one cycle to the next it moves by at
//    most the cycle time × the acceleration bound of this or the last cycle (the axis's, or an
//    HLI target's hli() bound), while the controller enable is on in both cycles; not on a gear
//    slave (coupled, decoupled in motion, or in the cycle it couples or leaves), nor after fed
//    external set values (B8: a packet may step) or, on an HLI target, a source that may step
//    (fed) until the axis rests;
//  - every command number posted is answered (leaves kPosted) within 2 NC cycles, its answer
//    slot is never lost, the states only move forward (posted → active → reached → an outcome),
//    and an outcome, once given, never changes.
// check() returns nullptr or what broke. Fixed-size state: no allocation while checking.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "fail.hpp"
#include "nc_core/axis_config.hpp"
#include "plc_interface/axis_ref.hpp"
#include "plc_interface/two_speed.hpp"

namespace fuzz {

// The first NcToPlc double that is not finite, by name; nullptr when all are.
FUZZ_CHECKER inline const char* non_finite_field(const plc::NCTOPLC_AXIS_REF& n) noexcept {
  struct Field {
    const char* name;
    double value;
  };
  const std::array<Field, 15> fields{{{"ActPos", n.ActPos},
                                      {"ModuloActPos", n.ModuloActPos},
                                      {"ActVelo", n.ActVelo},
                                      {"ActAcc", n.ActAcc},
                                      {"PosDiff", n.PosDiff},
                                      {"SetPos", n.SetPos},
                                      {"ModuloSetPos", n.ModuloSetPos},
                                      {"SetVelo", n.SetVelo},
                                      {"SetAcc", n.SetAcc},
                                      {"SetJerk", n.SetJerk},
                                      {"TargetPos", n.TargetPos},
                                      {"TargetVelo", n.TargetVelo},
                                      {"CompensationDistance", n.CompensationDistance},
                                      {"CompensationLength", n.CompensationLength},
                                      {"CompensationVelocityDiff", n.CompensationVelocityDiff}}};
  for (const Field& f : fields) {
    if (!std::isfinite(f.value)) return f.name;
  }
  return nullptr;
}

class AxisWatch {
 public:
  // `cycle_time`: the kernel's NC cycle in s.
  AxisWatch(const nc::AxisConfig& config, double cycle_time) noexcept
      : cycle_time_(cycle_time),
        base_velocity_(config.max_velocity),
        base_acceleration_(
            std::max({config.acceleration, config.deceleration, config.emergency_deceleration})),
        delay_(config.ext_setpoint_delay),
        stop_jerk_(std::min(config.jerk, config.emergency_jerk)),
        homing_velocity_(std::max(config.homing_velocity_to_cam, config.homing_velocity_off_cam)),
        jerk_(config.jerk),
        two_speed_(config.kind == nc::AxisKind::kTwoSpeed),
        rapid_(config.rapid_velocity),
        creep_(config.creep_velocity) {
    rest();
  }

  // --- PLC side, before the NC cycle: what the program asked for.
  // A move, halt or stop with these dynamics (0 = axis default; invalid values are refused).
  void allow_dynamics(double acceleration, double deceleration) noexcept {
    widen_acceleration(acceleration);
    widen_acceleration(deceleration);
  }
  // A compensation: VK on the velocity, AK± and VK's share of the basic acceleration (the
  // extra velocity is scaled by |v| / VP) on the acceleration.
  void allow_compensation(double vk, double ak_plus, double ak_minus, double vp) noexcept {
    if (!usable(vk) || !usable(ak_plus) || !usable(ak_minus) || !usable(vp)) return;
    velocity_ += vk;
    acceleration_ += std::max(ak_plus, ak_minus) + vk / vp * acceleration_;
    compensated_ = true;
    // On a slave (SPEC C5) the same on top of factor × its master's set values.
    comp_velocity_ += vk;
    comp_acceleration_ += std::max(ak_plus, ak_minus);
    comp_share_ += vk / vp;
  }
  // A fed external setpoint packet, taken while external generation is on. The set state is the
  // packet's, and a stop or the error ramp starts from it (docs/behaviour.md): with its
  // acceleration a the jerk-limited stop first ramps a to 0, passing |v| + a² / (2 J) on the way.
  void allow_external(double v, double a) noexcept {
    fed_ = true;  // a packet may step the set velocity (whatever its values)
    if (!std::isfinite(v) || !std::isfinite(a)) return;
    velocity_ += std::fabs(v) + std::fabs(a) * delay_ + a * a / (2.0 * stop_jerk_);
    acceleration_ += std::fabs(a);
  }

  // A coupled slave (StateDWord bit kStateCoupled) follows its master: its set velocity and
  // acceleration are GearRatio times the master's of the same cycle (docs/behaviour.md, "Slave
  // axes"), checked instead of its own limits while both axes are operational (see
  // check_following). `master` is the master's image, nullptr when the PLC does not know it.
  // Set before every check().
  void follow(const plc::NCTOPLC_AXIS_REF* master) noexcept {
    master_ = master;
    cyclic_ = false;
  }
  // A cyclic slave (MC_GearInDyn) whose coupling command in force is `number`, latched with
  // `acc_bound`; `master` as for follow(). Set before every check() instead of follow().
  void follow_cyclic(const plc::NCTOPLC_AXIS_REF* master, uint16_t number,
                     double acc_bound) noexcept {
    master_ = master;
    cyclic_ = master != nullptr;
    cyclic_number_ = number;
    acc_bound_ = acc_bound;
  }

  // HLI programs, set before every check(): `target` while the axis has an HLI list in force;
  // `velocity` and `acceleration` bound its drive's set values by the lists of this cycle and the
  // last (Σ |K| × the sources' program limits), +inf where the PLC cannot bound them (a gear
  // slave among the axes); `steps` when a source may step (may_step()), so the drive may too. These
  // stay until the axis rests (a drive braking after its list went off starts from at most that
  // velocity).
  void hli(bool target, double velocity, double acceleration, bool steps) noexcept {
    hli_target_ = target;
    hli_velocity_ = std::max(hli_velocity_, velocity);
    hli_acceleration_ = std::max(hli_acceleration_, acceleration);
    hli_steps_ = hli_steps_ || steps;
  }
  // Some axis's drive went off in this cycle under moving set values: a slave may leave its
  // coupling (K26: it shows GearRatio 0 from then on, as one that left under DELAYED
  // propagation). Set before check(), for that cycle only.
  void leader_drive_went_off() noexcept { leader_drive_off_ = true; }
  // External set values were fed since the axis last rested: its set velocity may step.
  bool may_step() const noexcept { return fed_; }

  // --- After the PLC's calls of one cycle: the commands it posted (kernel drained the rest).
  FUZZ_CHECKER void posted(const plc::AXIS_REF& axis) noexcept {
    const std::size_t now = axis.Mailbox.pending();
    for (std::size_t i = pending_; i < now; ++i) {
      ++posted_total_;
      last_number_ = static_cast<uint16_t>(last_number_ + 1U);
      if (last_number_ == 0) last_number_ = 1;
      Tracked& t = tracked_[next_slot_];
      next_slot_ = (next_slot_ + 1) % tracked_.size();
      t = Tracked{last_number_, plc::CommandState::kPosted, 0, 0, true};
    }
    pending_ = now;
  }

  // --- After the NC cycle: the invariants. nullptr when all hold.
  FUZZ_CHECKER const char* check(const plc::AXIS_REF& axis) noexcept {
    pending_ = axis.Mailbox.pending();
    const plc::NCTOPLC_AXIS_REF& n = axis.NcToPlc;
    if (non_finite_field(n) != nullptr) return "NcToPlc double not finite";
    if (two_speed_) {
      if (const char* broken = check_two_speed(n)) return broken;
      return check_answers(axis.Mailbox);
    }
    const bool coupled = plc::test_bit(n.StateDWord, plc::kStateCoupled);
    if (const char* broken = check_step(axis, coupled && !hli_target_)) return broken;
    // rest() ends it at once when at rest; an HLI target's drive keeps the bound of hli().
    if (was_coupled_ && !coupled && !was_hli_target_) decoupled_ = true;
    was_coupled_ = coupled;
    was_hli_target_ = hli_target_;
    left_ = coupled && (left_ || plc::test_bit(n.StateDWord, plc::kStateErrorPropagationDelayed) ||
                        (leader_drive_off_ && n.GearRatio == 0.0));
    leader_drive_off_ = false;
    const bool homing = plc::test_bit(n.StateDWord, plc::kStateHomingBusy);
    // An HLI target's image shows its drive, not the homing's program motion (docs/behaviour.md
    // "HLI axis coupling": SetVelo shows d); since it last rested its drive values are bounded
    // by hli() instead (finding K13 was this rule without it).
    const bool hli_drive = hli_target_ || hli_velocity_ > 0.0;
    if (homing && !homing_) {
      // A homing started from the last cycle's set state: it may first bring that state's
      // acceleration back at J (the aborted motion's larger J brings it back sooner). Unknown
      // when that state was an HLI drive's.
      homing_bound_ = hli_drive ? std::numeric_limits<double>::infinity()
                                : std::max(homing_velocity_,
                                           std::fabs(last_v_) + last_a_ * last_a_ / (2.0 * jerk_));
    }
    homing_ = homing;
    last_v_ = n.SetVelo;
    last_a_ = n.SetAcc;
    if (homing && !hli_drive && std::fabs(n.SetVelo) > homing_bound_ * (1.0 + 1e-9) + 1e-9) {
      return "homing set velocity above its homing velocity";
    }
    const bool cyclic = coupled && cyclic_ && n.CmdNo == cyclic_number_;
    const bool moved = cyclic && was_cyclic_ && n.GearRatio != last_ratio_;
    const double held_ratio = last_ratio_;
    was_cyclic_ = cyclic;
    last_ratio_ = n.GearRatio;
    if (hli_target_) {
      if (std::fabs(n.SetVelo) > hli_velocity_ * (1.0 + 1e-9) + 1e-9) {
        return "HLI target set velocity above sum |K| x its sources' limits";
      }
      if (std::fabs(n.SetAcc) > hli_acceleration_ * (1.0 + 1e-6) + 1e-6) {
        return "HLI target set acceleration above sum |K| x its sources' limits";
      }
    } else if (cyclic) {
      if (const char* broken = check_cyclic(n, moved, held_ratio)) return broken;
    } else if (coupled) {
      if (const char* broken = check_following(n)) return broken;
    } else if (!decoupled_) {
      // hli_velocity_ / hli_acceleration_ are 0 unless the axis was an HLI target since it rested.
      if (std::fabs(n.SetVelo) > std::max(stop_velocity(), hli_velocity_) * (1.0 + 1e-9) + 1e-9) {
        return "set velocity above limit";
      }
      if (std::fabs(n.SetAcc) > std::max(acceleration_, hli_acceleration_) * (1.0 + 1e-6) + 1e-6) {
        return "set acceleration above limit";
      }
    }
    // A coupling the PLC no longer knows (master_ nullptr: MC_GearInDyn's command ended with an
    // error of the axis, the coupling stays until MC_GearOut) keeps the kind last known.
    cyclic_coupling_ = coupled && (cyclic || (cyclic_coupling_ && master_ == nullptr));
    const bool resting = n.SetVelo == 0.0 && n.SetAcc == 0.0 &&
                         !plc::test_bit(n.StateDWord, plc::kStateHasJob) &&
                         !plc::test_bit(n.StateDWord, plc::kStateCompensating) &&
                         !plc::test_bit(n.StateDWord, plc::kStateExtSetPointGenEnabled);
    if (resting) rest();
    return check_answers(axis.Mailbox);
  }

  long commands_posted() const noexcept { return posted_total_; }
  long commands_answered() const noexcept { return answered_total_; }
  double velocity_limit() const noexcept { return stop_velocity(); }
  double acceleration_limit() const noexcept { return acceleration_; }

 private:
  struct Tracked {
    uint16_t number = 0;
    plc::CommandState state = plc::CommandState::kFree;
    uint32_t error_code = 0;
    int age = 0;  // NC cycles since it was posted
    bool live = false;
  };

  // K25: |SetVelo - last cycle's| <= cycle time × the acceleration bound. Called before check()
  // updates its state of the last cycle (last_v_, was_coupled_, was_hli_target_).
  FUZZ_CHECKER const char* check_step(const plc::AXIS_REF& axis, bool gear) noexcept {
    const plc::NCTOPLC_AXIS_REF& n = axis.NcToPlc;
    const bool enabled = plc::test_bit(axis.PlcToNc.ControlDWord, plc::kControlEnable);
    const bool external = plc::test_bit(n.StateDWord, plc::kStateExtSetPointGenEnabled);
    const bool gear_before = was_coupled_ && !was_hli_target_;
    const double bound = std::max(acceleration_, hli_acceleration_);
    const bool checked = enabled && was_enabled_ && !gear && !gear_before && !decoupled_ && !fed_ &&
                         !hli_steps_ && !external && !was_external_;
    const double allowed = cycle_time_ * std::max(bound, last_bound_) * (1.0 + 1e-6) +
                           1e-9 * (std::fabs(n.SetVelo) + std::fabs(last_v_)) + 1e-9;
    was_enabled_ = enabled;
    was_external_ = external;
    last_bound_ = bound;
    if (checked && std::fabs(n.SetVelo - last_v_) > allowed) {
      return "set velocity stepped by more than the acceleration bound allows in one cycle";
    }
    return nullptr;
  }

  static bool near(double x, double y) noexcept {
    return std::fabs(x - y) <= 1e-9 * (std::fabs(x) + std::fabs(y)) + 1e-9;
  }
  FUZZ_CHECKER const char* check_two_speed(const plc::NCTOPLC_AXIS_REF& n) const noexcept {
    const double v = std::fabs(n.SetVelo);
    if (v != 0.0 && v != rapid_ && v != creep_)
      return "two-speed set velocity not a contactor speed";
    if (n.SetAcc != 0.0) return "two-speed set acceleration not 0";
    if (std::fabs(n.ActVelo) > rapid_ * (1.0 + 1e-9))
      return "two-speed actual velocity above rapid";
    return nullptr;
  }
  // C6: the velocity is factor × the master's; the factor moves only where |a| <= AccBound, or,
  // where holding it already passes AccBound (below the stability bound, or a master beyond its
  // own limits: documented), only so that |a| stays within the held factor × the master's.
  FUZZ_CHECKER const char* check_cyclic(const plc::NCTOPLC_AXIS_REF& n, bool moved,
                                        double held_ratio) const noexcept {
    if (n.GearRatio == 0.0 && !zero_ratio_allowed(n)) return "a coupled slave shows no gear ratio";
    if (!plc::test_bit(n.StateDWord, plc::kStateOperational) ||
        !plc::test_bit(master_->StateDWord, plc::kStateOperational)) {
      return nullptr;
    }
    // Its own compensation adds on top as on a linear slave (C5; finding K20 was this rule
    // without it: a superimposed move started on a cyclic slave in motion).
    const double basic_v = n.GearRatio * master_->SetVelo;
    if (beyond_compensation(n.SetVelo, basic_v, comp_velocity_)) {
      return "cyclic slave set velocity is not gear ratio x master set velocity";
    }
    const double bound = std::max(acc_bound_, std::fabs(held_ratio * master_->SetAcc));
    if (moved &&
        std::fabs(n.SetAcc) > (bound + compensation_acceleration(bound)) * (1.0 + 1e-9) + 1e-9) {
      return "cyclic slave factor moved with its acceleration above AccBound";
    }
    return nullptr;
  }
  // `value` is further from `basic` than the rounding and `allowance` (what the slave's own
  // compensations may add) together.
  static bool beyond_compensation(double value, double basic, double allowance) noexcept {
    return !near(value, basic) && std::fabs(value - basic) > allowance * (1.0 + 1e-9) + 1e-9;
  }
  // What the slave's own compensations may add to a basic acceleration of size `basic`: AK± and
  // VK / VP of it (SPEC C5, B7).
  double compensation_acceleration(double basic) const noexcept {
    return comp_acceleration_ + comp_share_ * std::fabs(basic);
  }
  const char* check_following(const plc::NCTOPLC_AXIS_REF& n) const noexcept {
    if (n.GearRatio == 0.0 && !zero_ratio_allowed(n)) return "a coupled slave shows no gear ratio";
    // Not checked while either axis is not operational: a master without its controller enable
    // publishes set values that follow its actual position (a slave in motion has left it then,
    // K26), and a slave in error may have left it too.
    if (master_ == nullptr || !plc::test_bit(n.StateDWord, plc::kStateOperational) ||
        !plc::test_bit(master_->StateDWord, plc::kStateOperational)) {
      return nullptr;
    }
    // Its own compensation (SPEC C5) may add up to VK and AK± + VK / VP of the basic
    // acceleration (finding K10 was this checker without it: AK 3.5e-4 on a factor -0.5 slave).
    const double basic_v = n.GearRatio * master_->SetVelo;
    const double basic_a = n.GearRatio * master_->SetAcc;
    if (beyond_compensation(n.SetVelo, basic_v, comp_velocity_)) {
      return "slave set velocity is not gear ratio x master set velocity";
    }
    if (beyond_compensation(n.SetAcc, basic_a, compensation_acceleration(basic_a))) {
      return "slave set acceleration is not gear ratio x master set acceleration";
    }
    return nullptr;
  }

  // A coupled slave whose GearRatio may be 0 (check_following, check_cyclic):
  //  - SPEC C7 DELAYED (docs/behaviour.md "Error propagation"): a slave whose own error is raised
  //    leaves its master's coupling (no factor in force: GearRatio 0) but still shows as a slave
  //    until MC_GearOut, also after MC_Reset. Known from bit 6 (kStateErrorPropagationDelayed),
  //    which shows only on such a faulty axis, from its error's cycle on; kept while it shows as
  //    a slave (see check());
  //  - SPEC C6 (docs/behaviour.md "Cyclic slave"): the factor in force lies between its former
  //    value and the commanded ones, so on its way to a commanded factor of the other sign it may
  //    pass 0, and stop on it where AccBound leaves no other rate (finding K27: a master's
  //    followed velocity 0 with an acceleration not 0 allows only f' × am = 0). Only after the
  //    coupling's first cycle, which shows the factor the coupling gave (0 is refused).
  bool zero_ratio_allowed(const plc::NCTOPLC_AXIS_REF&) const noexcept {
    return left_ || cyclic_coupling_;
  }
  static bool usable(double x) noexcept { return std::isfinite(x) && x > 0.0; }
  // The velocity bound of an axis that is not coupled. A compensation's AK± is a step of the set
  // acceleration, not a ramp; an error ramp (or stop) that starts from the compensated set state
  // brings that acceleration back at the stop's jerk and passes |v| + a² / (2 J) on the way
  // (docs/behaviour.md "Position compensation"; finding K23 was this rule without it).
  double stop_velocity() const noexcept {
    if (!compensated_) return velocity_;
    return velocity_ + acceleration_ * acceleration_ / (2.0 * stop_jerk_);
  }
  void widen_acceleration(double x) noexcept {
    if (usable(x)) acceleration_ = std::max(acceleration_, x);
  }
  void rest() noexcept {
    velocity_ = base_velocity_;
    acceleration_ = base_acceleration_;
    comp_velocity_ = 0.0;
    comp_acceleration_ = 0.0;
    comp_share_ = 0.0;
    compensated_ = false;
    decoupled_ = false;
    hli_velocity_ = 0.0;
    hli_acceleration_ = 0.0;
    fed_ = false;
    hli_steps_ = false;
  }

  static int rank(plc::CommandState s) noexcept {
    switch (s) {
      case plc::CommandState::kFree:
        return -1;
      case plc::CommandState::kPosted:
        return 0;
      case plc::CommandState::kBuffered:  // accepted, waits behind the running command
      case plc::CommandState::kActive:
        return 1;
      case plc::CommandState::kReached:
        return 2;
      default:
        return 3;  // an outcome
    }
  }

  FUZZ_CHECKER const char* check_answers(const plc::CommandMailbox& mailbox) noexcept {
    for (Tracked& t : tracked_) {
      if (!t.live) continue;
      ++t.age;
      const plc::CommandAnswer a = mailbox.answer(t.number);
      if (a.state == plc::CommandState::kFree) return "a posted command's answer is lost";
      if (a.state == plc::CommandState::kPosted && t.age >= 2) {
        return "a command is not answered within 2 NC cycles";
      }
      const int before = rank(t.state);
      const int after = rank(a.state);
      if (after < before) return "a command's state went backwards";
      if (before == 3 && (a.state != t.state || a.error_code != t.error_code)) {
        return "a command was answered twice with different outcomes";
      }
      if (before < 1 && after >= 1) ++answered_total_;
      t.state = a.state;
      t.error_code = a.error_code;
      // An outcome is watched for a few more cycles, then the slot is free for a new number.
      if (after == 3 && t.age > kWatchOutcome) t.live = false;
    }
    return nullptr;
  }

  static constexpr int kWatchOutcome = 8;
  // Fewer than CommandMailbox::kAnswerSlots: a tracked number's slot is never reused by a
  // newer number while it is tracked (a block posts at most once per call).
  std::array<Tracked, 48> tracked_{};
  std::size_t next_slot_ = 0;
  uint16_t last_number_ = 0;
  std::size_t pending_ = 0;  // in the mailbox after the last NC cycle (0: all taken)
  long posted_total_ = 0;
  long answered_total_ = 0;

  double cycle_time_;
  double base_velocity_;
  double base_acceleration_;
  double delay_;
  double stop_jerk_;
  double velocity_ = 0.0;
  const plc::NCTOPLC_AXIS_REF* master_ = nullptr;
  double acceleration_ = 0.0;
  // What compensations the program started may add on a slave until it rests (check_following,
  // check_cyclic).
  double comp_velocity_ = 0.0;
  double comp_acceleration_ = 0.0;
  bool compensated_ = false;  // a compensation was allowed since the axis last rested
  double comp_share_ = 0.0;
  bool was_coupled_ = false;
  bool decoupled_ = false;  // decoupled in motion (C4): own limits unchecked until at rest
  // Homing.
  double homing_velocity_;
  double jerk_;
  bool homing_ = false;
  double homing_bound_ = 0.0;
  double last_v_ = 0.0;
  double last_a_ = 0.0;
  // Cyclic slave.
  bool cyclic_ = false;
  bool was_cyclic_ = false;
  uint16_t cyclic_number_ = 0;
  double acc_bound_ = 0.0;
  double last_ratio_ = 0.0;
  // The coupling in force was known to be a cyclic one in an earlier cycle, and the axis has
  // shown as a slave since (zero_ratio_allowed()).
  bool cyclic_coupling_ = false;
  bool left_ = false;              // a slave that left its coupling (zero_ratio_allowed())
  bool leader_drive_off_ = false;  // leader_drive_went_off() in this cycle
  // HLI target (hli()).
  bool hli_target_ = false;
  bool was_hli_target_ = false;
  double hli_velocity_ = 0.0;
  double hli_acceleration_ = 0.0;
  // The set velocity's steps (check_step()).
  bool fed_ = false;        // external set values fed since the axis last rested
  bool hli_steps_ = false;  // an HLI source may have stepped since the axis last rested
  bool was_enabled_ = false;
  bool was_external_ = false;
  double last_bound_ = 0.0;
  // Two-speed axis.
  bool two_speed_;
  double rapid_;
  double creep_;
};

// The 12-byte NC→I/O image of a two-speed axis (E4): both control bytes say the same, travel
// and brake never together, the unused fields 0. nullptr when it holds.
FUZZ_CHECKER inline const char* broken_two_speed_image(
    const plc::NCTOIO_DRIVE_TWO_SPEED& image) noexcept {
  if (!plc::control_bytes_consistent(image)) return "two-speed control bytes disagree";
  const plc::TwoSpeedDriveCommand c = plc::read_control_byte(image.nControlByte);
  if (c.brake && c.velocity != plc::TwoSpeedVelocity::kOff &&
      c.direction != plc::TwoSpeedDirection::kNone) {
    return "two-speed travel bit with the brake on";
  }
  if (image.nOutData1 != 0 || image.nOutData2 != 0 || image.nReserved != 0) {
    return "two-speed unused image fields not 0";
  }
  return nullptr;
}

}  // namespace fuzz
