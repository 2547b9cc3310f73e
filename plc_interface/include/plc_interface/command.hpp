// The command ("axis function") channel between the PLC side and the NC side.
//
// A block posts a Command into its axis's mailbox and receives a command number. The NC kernel
// drains the mailbox in its next cycle and answers every number in the answer table: accepted
// (the job runs), refused (with an error code), and later the job's outcome (reached, done,
// aborted, failed). Blocks read only their own number's answer; the kernel never reads block
// state. Fixed capacity, no allocation: both sides may use it in the cycle.
#pragma once

#include <array>
#include <cstdint>

namespace plc {

// The enumerations of the PLCopen / Tc2_MC2 block inputs the NC reads from a Command, with
// Tc2_MC2's names and values. Defined once here and used by name on both sides (fb/types.hpp
// re-exports them); the numbers are part of the contract and must not be renumbered.
enum MC_Direction : int32_t {
  MC_Positive_Direction = 1,
  MC_Shortest_Way = 2,
  MC_Negative_Direction = 3,
  MC_Current_Direction = 4,
  MC_Undefined_Direction = 128,
};

enum E_PositionType : int32_t {
  POSITIONTYPE_ABSOLUTE = 1,
  POSITIONTYPE_RELATIVE = 2,
};

enum MC_BufferMode : int32_t {
  MC_Aborting = 0,
  MC_Buffered = 1,
  MC_BlendingLow = 2,
  MC_BlendingPrevious = 3,
  MC_BlendingNext = 4,
  MC_BlendingHigh = 5,
};

enum MC_HomingMode : int32_t {
  MC_DefaultHoming = 0,  // the NC's sequence: reference cam, then sync pulse (or cam edge)
  MC_AbsSwitch = 1,      // refused by ncsdk (as by Tc2_MC2)
  MC_LimitSwitch = 2,    // refused
  MC_RefPulse = 3,       // refused
  MC_Direct = 4,         // set the position, no motion
  MC_ForceCalibration = 5,
  MC_ResetCalibration = 6,
};

// MC_Home.Position's default (Tc2_MC2's DEFAULT_HOME_POSITION): take the axis's configured
// reference position (AxisConfig::homing_reference_position) instead.
inline constexpr double DEFAULT_HOME_POSITION = 99999999999.0;

// What a command asks the NC to do. Values are stable: they appear in traces.
enum class CommandType : uint16_t {
  kNone = 0,
  kReset = 1,                  // clear the axis error (MC_Reset)
  kMoveAbsolute = 2,           // position = target
  kMoveRelative = 3,           // position = distance
  kMoveModulo = 4,             // position = modulo target, direction = MC_Direction
  kMoveVelocity = 5,           // velocity (> 0), direction = MC_Direction (or +1 / -1)
  kHalt = 6,                   // deceleration, jerk (0 = the running motion's)
  kStop = 7,                   // deceleration, jerk; locks motion commands until kStopRelease
  kStopRelease = 8,            // MC_Stop's Execute fell after Done: unlock
  kNewPos = 9,                 // position = new end position
  kNewPosAndVelo = 10,         // position = EPos, velocity = VNew, activation_position = APos
  kMoveSuperImposed = 11,      // position = D, velocity = VK, acceleration = AK+,
                               // deceleration = AK-, process_velocity = VP, length = L
  kAbortSuperposition = 12,    // compensation stop
  kExtSetPointGenEnable = 13,  // position = target for window monitoring, mode = E_PositionType
  kExtSetPointGenDisable = 14,
  kGearIn = 15,     // ratio (factor, finite, != 0), other_axis = master (NcToPlc.AxisIndex);
                    // posted to the slave's mailbox
  kGearInDyn = 16,  // ratio (initial), acceleration = AccBound, other_axis = master
  kGearOut = 17,    // posted to the slave's mailbox
  kHome = 18,       // position = home position (DEFAULT_HOME_POSITION: the configured one),
                    // mode = MC_HomingMode
};

// Lifecycle of one command number, as the NC reports it in the answer table.
enum class CommandState : uint16_t {
  kFree = 0,      // slot unused / number unknown
  kPosted = 1,    // in the mailbox, not yet seen by the NC
  kActive = 2,    // accepted; the job runs (the axis executes this number)
  kReached = 3,   // the job's goal is reached but it goes on (InVelocity, InGear, Enabled)
  kDone = 4,      // the job has ended successfully (target reached, stopped, reset done)
  kAborted = 5,   // a later command took over the axis before this job ended
  kError = 6,     // refused at acceptance, or failed while running: see error_code
  kBuffered = 7,  // accepted into the axis's one buffer slot (BufferMode other than MC_Aborting):
                  // waits behind the running command, then kActive when it takes over
};

// One axis function with its parameters. Which fields a type uses is listed at CommandType;
// 0 for acceleration, deceleration or jerk means the axis default.
struct Command {
  CommandType type = CommandType::kNone;
  uint16_t number = 0;  // assigned by CommandMailbox::post
  double position = 0.0;
  double velocity = 0.0;
  double acceleration = 0.0;
  double deceleration = 0.0;
  double jerk = 0.0;
  double activation_position = 0.0;
  double process_velocity = 0.0;
  double length = 0.0;
  double ratio = 1.0;
  int32_t direction = 0;              // MC_Direction (kMoveVelocity also +1 / -1)
  int32_t mode = 0;                   // E_PositionType (kExtSetPointGenEnable); homing mode
  int32_t other_axis = -1;            // kernel index of the partner axis (coupling master)
  int32_t buffer_mode = MC_Aborting;  // MC_BufferMode of a move, halt or stop
};

// The NC's answer for one command number.
struct CommandAnswer {
  uint16_t number = 0;
  CommandState state = CommandState::kFree;
  uint32_t error_code = 0;  // non-zero only with kError
};

// Per-axis mailbox and answer table. Command numbers run 1 … 65535 and wrap, skipping 0.
class CommandMailbox {
 public:
  static constexpr std::size_t kQueueCapacity = 16;
  static constexpr std::size_t kAnswerSlots = 64;

  // PLC side. Returns the command's number, or 0 when the queue is full (nothing posted).
  uint16_t post(Command command) noexcept;
  // PLC side. The answer for `number`; state kFree when the number is unknown or so old that its
  // slot was reused. Inline: every busy block asks it in every PLC cycle.
  CommandAnswer answer(uint16_t number) const noexcept {
    const CommandAnswer& slot = answers_[number % kAnswerSlots];
    if (number == 0 || slot.number != number) return CommandAnswer{number, CommandState::kFree, 0};
    return slot;
  }

  // NC side. Takes the oldest posted command; false when the queue is empty.
  bool take(Command& out) noexcept;
  // NC side. Records the state (and error code) of `number` — unless its slot already holds a
  // newer number's answer: then `number` is so old that the PLC reads kFree for it anyway, and
  // the newer answer stays (fuzz finding K21).
  void set_answer(uint16_t number, CommandState state, uint32_t error_code = 0) noexcept;

  std::size_t pending() const noexcept { return count_; }
  // NC side. Whether a posted command not yet taken has a type for which `pred(type)` holds.
  template <class Pred>
  bool holds(Pred pred) const noexcept {
    for (std::size_t k = 0; k < count_; ++k) {
      if (pred(queue_[(head_ + k) % kQueueCapacity].type)) return true;
    }
    return false;
  }

 private:
  // The queue's bookkeeping first: the NC reads `count_` every cycle, the slots only on a post.
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  uint16_t last_number_ = 0;
  std::array<Command, kQueueCapacity> queue_{};
  std::array<CommandAnswer, kAnswerSlots> answers_{};
};

}  // namespace plc
