// The part of an axis every axis kind shares with the PLC side (SPEC A7): its AXIS_REF, the
// command it executes (CmdNo / CmdState) and the answers to commands, the latched axis error, and
// the warnings — each warning a latched bit, NcToPlc.Warning the last one set that still holds.
// A servo axis uses it now; a two-speed axis can use it as it is.
//
// Cycle functions only (noexcept, no allocation). Answering never reads the command's parameters.
#pragma once

#include <cstdint>

#include "plc_interface/axis_ref.hpp"
#include "plc_interface/error_code.hpp"

namespace nc::detail {

// The warnings an axis latches (each also a code of the catalogue).
enum class Warning : uint8_t {
  kMovementSmallerThanIncrement,  // 0x4224, a start shorter than one increment
  kOverrideNotAllowed,            // 0x4238, PlcToNc.Override above 100 %: not taken
  kCompensationIncomplete,        // 0x4243, less than D compensated
  kAccBoundBelowStability,        // 0x4F80, cyclic slave: AccBound below the stability bound
  kGearRatio1NotTaken,            // 0x4F81, cyclic slave: GearRatio1 not taken
};

inline uint8_t warning_bit(Warning w) noexcept {
  return static_cast<uint8_t>(1U << static_cast<unsigned>(w));
}

// The warnings an axis latches: a bit each; NcToPlc.Warning shows the last one set while it still
// holds, otherwise the first still latched.
// `changed` is set by every change that may change code() (clear() only when the bit was set: the
// override's check clears in every cycle), and by the channel for its own (AxisChannel::changed()):
// one flag, so that the steady cycle tests one byte for both.
class AxisWarnings {
 public:
  void warn(Warning w) noexcept {
    bits_ = static_cast<uint8_t>(bits_ | warning_bit(w));
    last_ = w;
    changed = true;
  }
  void clear(Warning w) noexcept {
    if ((bits_ & warning_bit(w)) == 0) return;
    bits_ = static_cast<uint8_t>(bits_ & ~warning_bit(w));
    changed = true;
  }
  // All warnings but `keep` (kept when latched).
  void clear_except(Warning keep) noexcept {
    bits_ = static_cast<uint8_t>(bits_ & warning_bit(keep));
    changed = true;
  }
  void clear_all() noexcept {
    bits_ = 0;
    changed = true;
  }
  bool any() const noexcept { return bits_ != 0; }
  // NcToPlc.Warning (0: none).
  uint32_t code() const noexcept;

  bool changed = true;  // since the channel's last publish (AxisChannel::changed())

 private:
  uint8_t bits_ = 0;  // bit per Warning
  Warning last_ = Warning::kMovementSmallerThanIncrement;
};

class AxisChannel {
 public:
  plc::AXIS_REF& ref() noexcept { return ref_; }
  const plc::AXIS_REF& ref() const noexcept { return ref_; }

  bool controller_enabled() const noexcept {
    return plc::test_bit(ref_.PlcToNc.ControlDWord, plc::kControlEnable);
  }
  // The feed enable of a direction (> 0 plus, < 0 minus); 0 needs none.
  bool feed_enabled(double direction) const noexcept {
    const uint32_t word = ref_.PlcToNc.ControlDWord;
    if (direction > 0.0) return plc::test_bit(word, plc::kControlFeedEnablePlus);
    if (direction < 0.0) return plc::test_bit(word, plc::kControlFeedEnableMinus);
    return true;
  }

  // A command that does not become the axis's job (a refusal, a Done at once, an answer to a
  // superposition command).
  void answer(uint16_t number, plc::CommandState state, uint32_t code = 0) noexcept {
    ref_.Mailbox.set_answer(number, state, code);
  }
  // The job `job_number` is the command the axis executes and it is still running (kActive or
  // kReached): a new job or an error answers it.
  bool runs(uint16_t job_number) const noexcept;
  // `number` becomes the command the axis executes, answered kActive; a running one is answered
  // kAborted first.
  void take_over(uint16_t number, uint16_t running_job) noexcept;
  void answer_current(plc::CommandState state, uint32_t code = 0) noexcept;
  plc::CommandState cmd_state() const noexcept { return cmd_state_; }

  // The latched error: the first one stays until clear_error().
  plc::ErrorCode error() const noexcept { return error_; }
  bool has_error() const noexcept { return error_ != plc::ErrorCode::kNone; }
  // True when `code` is latched now (false: an error was already latched).
  bool raise(plc::ErrorCode code) noexcept;
  void clear_error() noexcept {
    error_ = plc::ErrorCode::kNone;
    warnings.changed = true;  // changed()
  }

  // CmdNo, CmdState, ErrorCode, Warning and AxisIndex of NcToPlc.
  void publish(int32_t index) noexcept {
    publish_to(ref_.NcToPlc, index);
    published();
  }
  void publish_to(plc::NCTOPLC_AXIS_REF& out, int32_t index) const noexcept {
    out.ErrorCode = plc::to_id(error_);
    out.Warning = warnings.any() ? warnings.code() : 0;
    out.CmdNo = cmd_no_;
    out.CmdState = static_cast<uint16_t>(cmd_state_);
    out.AxisIndex = index;
  }
  // Something publish_to() writes may have changed since published() (the error, the command
  // executed or its state, a warning): a servo axis publishes those five only then. The
  // warnings' flag is the channel's too (AxisWarnings).
  bool changed() const noexcept { return warnings.changed; }
  void published() noexcept { warnings.changed = false; }

 private:
  uint16_t cmd_no_ = 0;  // the command the axis executes (or executed last)
  plc::CommandState cmd_state_ = plc::CommandState::kFree;
  plc::ErrorCode error_ = plc::ErrorCode::kNone;

 public:
  AxisWarnings warnings{};  // a part of its own: every axis part sets and clears them

 private:
  plc::AXIS_REF ref_{};  // last: its mailbox is large and cold in a steady cycle
};

}  // namespace nc::detail
