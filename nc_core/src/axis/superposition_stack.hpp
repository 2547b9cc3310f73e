// What an axis adds on top of its basic set value (SPEC B7, B8): the held offsets of ended
// superpositions, the running position compensation (seed 000 §2.5) and relative external
// setpoints (seed 000 §2.6). It owns the fold/rebase rule, so a caller only says what happened:
// - a new job planned from the set state (accept, error ramp): fold() — the superpositions end,
//   their offset so far is in the set state, nothing is held;
// - a new table planned from basic_state() (online functions): rebase() — the held offset is in
//   the table now, the running superpositions go on;
// - a Halt / Stop planned from stop_start_state(): on_stop() — offsets are in the stop, the
//   compensation gets its compensation stop and goes on.
// It also keeps the external generator's state when that is the absolute basic source (one
// generator per axis: its type says which role it plays).
//
// Cycle functions only: noexcept, no allocation.
#pragma once

#include "axis/axis_channel.hpp"
#include "axis/compensation.hpp"
#include "axis/external_setpoint.hpp"
#include "nc_core/profile.hpp"

namespace nc::detail {

class SuperpositionStack {
 public:
  // The basic motion of this cycle as the stack needs to see it.
  struct Basic {
    KinematicState state;       // the basic source's set values
    bool path_running = false;  // a PTP job runs and has not ended its generation
    bool has_target = false;    // a positioning / halt / stop: superpositions move its end
    double target = 0.0;        // that job's end position
  };
  struct Result {
    KinematicState set;   // basic motion + everything on top
    double target = 0.0;  // the job's end moved by the superpositions (when target_moved)
    bool target_moved = false;
    bool not_finite = false;  // a relative external packet held NaN / inf (not taken)
    bool too_large = false;   // a relative external packet was out of range (not taken)
  };

  // Step b: the set values = basic + held + compensation + relative external offset. Ends a
  // compensation whose time is over (kDone / kAborted after a compensation stop) or whose basic
  // path ended first (kAborted), answering it on `channel`.
  Result superimpose(const Basic& basic, const plc::PLCTONC_AXIS_REF& in, AxisChannel& channel,
                     double cycle_time) noexcept;

  // Where a replan of the basic motion starts when the superpositions are to go on.
  KinematicState basic_state(const KinematicState& base, const KinematicState& set) const noexcept;
  // Where a Halt / Stop starts: the set state without the running compensation.
  KinematicState stop_start_state(const KinematicState& set) const noexcept;

  void fold(AxisChannel& channel, plc::CommandState state,
            ErrorCode code = ErrorCode::kNone) noexcept;
  void rebase() noexcept { held_ = 0.0; }
  void on_stop() noexcept;
  // The basic motion holds with nothing on top: the held offset is absorbed.
  void drop_held() noexcept { held_ = 0.0; }
  // External generation switched off at once (reset, controller enable gone). True when it was
  // the absolute basic source (the caller then holds its set position); a relative offset is held.
  bool end_external() noexcept;

  // A superposition moves the axis while the basic motion holds.
  bool moves_alone() const noexcept { return compensation.running() || external.taking(); }
  // Nothing on top: superimpose() would give the basic state (p + held, held ±0.0) and change
  // nothing else.
  bool empty() const noexcept { return held_ == 0.0 && !moves_alone(); }
  double held() const noexcept { return held_; }

 private:
  void end_compensation(AxisChannel& channel, plc::CommandState state) noexcept;

  double held_ = 0.0;  // offsets of ended superpositions, kept until the basic job changes

 public:
  // The two superpositions, parts of their own: their commands start and stop them in place;
  // superimpose(), fold() and end_external() keep them and the held offset consistent.
  // (External first: with the held offset, its flags and the compensation's first members a
  // steady cycle reads lie on two cache lines.)
  ExternalSetpoint external{};
  Compensation compensation{};
};

}  // namespace nc::detail
