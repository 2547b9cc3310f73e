// A scripted NC side for function-block tests.
//
// ScriptedNc plays the kernel's part of the PLC↔NC contract (see the command semantics in
// plc_interface/command.hpp) on one plc::AXIS_REF, without planning or simulating anything:
// cycle() takes the posted commands in order and answers them as the kernel must (accepted
// motion → kActive and the command it replaces → kAborted; Reset and StopRelease → kDone at once;
// Stop locks motion commands until StopRelease or Reset), and the test decides the rest —
// when the job reaches its velocity, ends, fails, or which command is refused with what code.
// That lets block tests drive every answer sequence, in any order, cycle by cycle.
// Position compensation (kMoveSuperImposed) runs beside the executing job without taking CmdNo
// (StateDWord bit 13; a second one while it runs is refused with 0x4245); kAbortSuperposition
// aborts it at once and is Done (0x4246 when none runs). While it runs, finish() ends it (not
// the executing job) and fail() fails it with the executing job. kExtSetPointGenEnable / Disable
// are Done at once and set / clear StateDWord bit 14 (enabling is refused on an axis in error or
// locked). Test code: it allocates (it keeps the history of taken commands).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "plc_interface/axis_ref.hpp"
#include "plc_interface/command.hpp"
#include "plc_interface/error_code.hpp"

namespace fbtest {

class ScriptedNc {
 public:
  explicit ScriptedNc(plc::AXIS_REF& axis) : axis_(axis) {
    set_operational(true);
    set_axis_state(plc::AxisState::kStandstill);
  }

  // One NC cycle: takes every posted command, oldest first, and answers it.
  void cycle() {
    plc::Command command;
    while (axis_.Mailbox.take(command)) {
      taken_.push_back(command);
      handle(command);
    }
    ++axis_.NcToPlc.CycleCounter;
  }

  // Test set-up: a position compensation runs, as if an MC_MoveSuperImposed had been taken —
  // without a trace in taken(). Returns its command number.
  uint16_t start_compensation() {
    plc::Command command;
    command.type = plc::CommandType::kMoveSuperImposed;
    axis_.Mailbox.post(command);
    axis_.Mailbox.take(command);
    handle(command);
    return command.number;
  }

  // The next command taken (of any type) is refused with `code`.
  void refuse_next(plc::ErrorCode code) { refusals_.push_back(code); }

  // Outcomes of the job the axis executes (no effect when none runs).
  void reach() { set_executing(plc::CommandState::kReached); }
  void finish() {
    if (end_compensation(plc::CommandState::kDone)) return;
    if (!set_executing(plc::CommandState::kDone)) return;
    // A finished stop leaves the axis stopping-and-locked until the release (Tc2_MC2 MC_Stop).
    set_axis_state(locked() ? plc::AxisState::kStopping : plc::AxisState::kStandstill);
  }
  // The axis goes into error during the job: the job fails with the axis's error code.
  void fail(plc::ErrorCode code) {
    end_compensation(plc::CommandState::kError, plc::to_id(code));
    set_executing(plc::CommandState::kError, plc::to_id(code));
    axis_.NcToPlc.ErrorCode = plc::to_id(code);
    axis_.NcToPlc.StateDWord = plc::with_bit(axis_.NcToPlc.StateDWord, plc::kStateError, true);
    set_axis_state(plc::AxisState::kErrorStop);
  }

  void set_operational(bool on) {
    axis_.NcToPlc.StateDWord = plc::with_bit(axis_.NcToPlc.StateDWord, plc::kStateOperational, on);
  }
  void set_axis_state(plc::AxisState state) {
    axis_.NcToPlc.AxisState = static_cast<uint32_t>(state);
  }

  bool locked() const {
    return plc::test_bit(axis_.NcToPlc.StateDWord, plc::kStateMotionCommandsLocked);
  }
  bool in_error() const { return plc::test_bit(axis_.NcToPlc.StateDWord, plc::kStateError); }
  // Number of the command the axis executes (0: none yet).
  uint16_t executing() const { return axis_.NcToPlc.CmdNo; }
  // Number of the running position compensation (0: none).
  uint16_t compensating() const { return compensation_; }

  // Every command taken so far, in order.
  const std::vector<plc::Command>& taken() const { return taken_; }
  std::size_t count(plc::CommandType type) const {
    std::size_t n = 0;
    for (const plc::Command& c : taken_)
      n += c.type == type ? 1U : 0U;
    return n;
  }
  // The last taken command of `type`; a default Command when there is none.
  plc::Command last(plc::CommandType type) const {
    for (auto it = taken_.rbegin(); it != taken_.rend(); ++it) {
      if (it->type == type) return *it;
    }
    return plc::Command{};
  }

 private:
  static bool is_motion(plc::CommandType type) {
    return type != plc::CommandType::kReset && type != plc::CommandType::kStopRelease &&
           type != plc::CommandType::kExtSetPointGenDisable &&
           type != plc::CommandType::kAbortSuperposition;
  }

  void handle(const plc::Command& command) {
    if (!refusals_.empty()) {
      const plc::ErrorCode code = refusals_.front();
      refusals_.pop_front();
      answer(command.number, plc::CommandState::kError, plc::to_id(code));
      return;
    }
    switch (command.type) {
      case plc::CommandType::kReset:
        // Clears the error and the MC_Stop lock (Tc2_MC2 MC_Reset); does not change CmdNo.
        axis_.NcToPlc.ErrorCode = 0;
        axis_.NcToPlc.StateDWord = plc::with_bit(axis_.NcToPlc.StateDWord, plc::kStateError, false);
        set_lock(false);
        set_axis_state(plc::AxisState::kStandstill);
        answer(command.number, plc::CommandState::kDone);
        return;
      case plc::CommandType::kStopRelease:
        if (locked()) set_axis_state(plc::AxisState::kStandstill);
        set_lock(false);
        answer(command.number, plc::CommandState::kDone);
        return;
      case plc::CommandType::kExtSetPointGenDisable:
        set_state_bit(plc::kStateExtSetPointGenEnabled, false);
        answer(command.number, plc::CommandState::kDone);
        return;
      case plc::CommandType::kAbortSuperposition:
        if (!end_compensation(plc::CommandState::kAborted)) {
          answer(command.number, plc::CommandState::kError,
                 plc::to_id(plc::ErrorCode::kCompensationNotActive));
          return;
        }
        answer(command.number, plc::CommandState::kDone);
        return;
      default:
        break;
    }
    if (is_motion(command.type) && in_error()) {
      answer(command.number, plc::CommandState::kError,
             plc::to_id(plc::ErrorCode::kAxisInErrorState));
      return;
    }
    if (locked() && command.type != plc::CommandType::kStop) {
      answer(command.number, plc::CommandState::kError,
             plc::to_id(plc::ErrorCode::kMotionCommandsLocked));
      return;
    }
    // Jobs beside the executing one: they do not take CmdNo.
    if (command.type == plc::CommandType::kExtSetPointGenEnable) {
      set_state_bit(plc::kStateExtSetPointGenEnabled, true);
      answer(command.number, plc::CommandState::kDone);
      return;
    }
    if (command.type == plc::CommandType::kMoveSuperImposed) {
      if (compensation_ != 0) {
        answer(command.number, plc::CommandState::kError,
               plc::to_id(plc::ErrorCode::kCompensationActive));
        return;
      }
      compensation_ = command.number;
      set_state_bit(plc::kStateCompensating, true);
      answer(command.number, plc::CommandState::kActive);
      return;
    }
    // Accepted: the job it replaces is aborted; the axis now executes this number.
    const plc::CommandAnswer previous = axis_.Mailbox.answer(axis_.NcToPlc.CmdNo);
    if (previous.state == plc::CommandState::kActive ||
        previous.state == plc::CommandState::kReached) {
      answer(previous.number, plc::CommandState::kAborted);
    }
    axis_.NcToPlc.CmdNo = command.number;
    answer(command.number, plc::CommandState::kActive);
    switch (command.type) {
      case plc::CommandType::kMoveVelocity:
        set_axis_state(plc::AxisState::kContinuousMotion);
        break;
      case plc::CommandType::kStop:
        set_lock(true);
        set_axis_state(plc::AxisState::kStopping);
        break;
      default:
        set_axis_state(plc::AxisState::kDiscreteMotion);
        break;
    }
  }

  // Sets the answer of the executing job if it still runs; false when none runs.
  bool set_executing(plc::CommandState state, uint32_t code = 0) {
    const plc::CommandAnswer current = axis_.Mailbox.answer(axis_.NcToPlc.CmdNo);
    if (current.state != plc::CommandState::kActive &&
        current.state != plc::CommandState::kReached) {
      return false;
    }
    answer(current.number, state, code);
    return true;
  }

  void answer(uint16_t number, plc::CommandState state, uint32_t code = 0) {
    axis_.Mailbox.set_answer(number, state, code);
    if (number == axis_.NcToPlc.CmdNo) axis_.NcToPlc.CmdState = static_cast<uint16_t>(state);
  }

  // Ends the running compensation with `state`; false when none runs.
  bool end_compensation(plc::CommandState state, uint32_t code = 0) {
    if (compensation_ == 0) return false;
    answer(compensation_, state, code);
    compensation_ = 0;
    set_state_bit(plc::kStateCompensating, false);
    return true;
  }

  void set_state_bit(uint32_t bit, bool on) {
    axis_.NcToPlc.StateDWord = plc::with_bit(axis_.NcToPlc.StateDWord, bit, on);
  }

  void set_lock(bool on) {
    axis_.NcToPlc.StateDWord =
        plc::with_bit(axis_.NcToPlc.StateDWord, plc::kStateMotionCommandsLocked, on);
  }

  plc::AXIS_REF& axis_;
  std::vector<plc::Command> taken_;
  std::deque<plc::ErrorCode> refusals_;
  uint16_t compensation_ = 0;
};

}  // namespace fbtest
