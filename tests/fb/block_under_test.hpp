// One view of every Execute-type block, so that the output-rule suites run unchanged over all of
// them (TEMPLATE_TEST_CASE over kExecuteBlocks), and a bench that checks the rules that hold at
// EVERY call (exclusivity, Active, ErrorID) after each call of the block.
#pragma once

#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>

#include "fb/fb.hpp"
#include "plc_interface/axis_ref.hpp"
#include "scripted_nc.hpp"

namespace fbtest {

// The outputs of an Execute-type block, whichever it has (absent ones stay false).
struct Outputs {
  bool busy = false;
  bool active = false;
  bool done = false;
  bool in_velocity = false;
  bool aborted = false;
  bool error = false;
  uint32_t error_id = 0;
};

// Per block: the command it posts, the input latched into the command (if any) and how the
// command carries it, and which results the block can show.
template <class B>
struct Adapter;

template <>
struct Adapter<fb::MC_MoveAbsolute> {
  static constexpr plc::CommandType kType = plc::CommandType::kMoveAbsolute;
  static constexpr bool kHasDone = true;    // the job ends with Done
  static constexpr bool kAbortable = true;  // has CommandAborted
  static constexpr bool kHasActive = true;  // has Active
  static constexpr bool kHasInput = true;   // has a latched input besides Execute
  static void prepare(fb::MC_MoveAbsolute& b) {
    b.Position = 2000.0;
    b.Velocity = 1000.0;
  }
  static void set_input(fb::MC_MoveAbsolute& b, double x) { b.Position = x; }
  static double sent(const plc::Command& c) { return c.position; }
  static Outputs view(const fb::MC_MoveAbsolute& b) {
    return {b.Busy, b.Active, b.Done, false, b.CommandAborted, b.Error, b.ErrorID};
  }
};

template <>
struct Adapter<fb::MC_MoveRelative> {
  static constexpr plc::CommandType kType = plc::CommandType::kMoveRelative;
  static constexpr bool kHasDone = true;
  static constexpr bool kAbortable = true;
  static constexpr bool kHasActive = true;
  static constexpr bool kHasInput = true;
  static void prepare(fb::MC_MoveRelative& b) {
    b.Distance = 500.0;
    b.Velocity = 1000.0;
  }
  static void set_input(fb::MC_MoveRelative& b, double x) { b.Distance = x; }
  static double sent(const plc::Command& c) { return c.position; }
  static Outputs view(const fb::MC_MoveRelative& b) {
    return {b.Busy, b.Active, b.Done, false, b.CommandAborted, b.Error, b.ErrorID};
  }
};

template <>
struct Adapter<fb::MC_MoveVelocity> {
  static constexpr plc::CommandType kType = plc::CommandType::kMoveVelocity;
  static constexpr bool kHasDone = false;  // InVelocity while Busy; never Done
  static constexpr bool kAbortable = true;
  static constexpr bool kHasActive = true;
  static constexpr bool kHasInput = true;
  static void prepare(fb::MC_MoveVelocity& b) { b.Velocity = 300.0; }
  static void set_input(fb::MC_MoveVelocity& b, double x) { b.Velocity = x; }
  static double sent(const plc::Command& c) { return c.velocity; }
  static Outputs view(const fb::MC_MoveVelocity& b) {
    return {b.Busy, b.Active, false, b.InVelocity, b.CommandAborted, b.Error, b.ErrorID};
  }
};

template <>
struct Adapter<fb::MC_Halt> {
  static constexpr plc::CommandType kType = plc::CommandType::kHalt;
  static constexpr bool kHasDone = true;
  static constexpr bool kAbortable = true;
  static constexpr bool kHasActive = true;
  static constexpr bool kHasInput = true;
  static void prepare(fb::MC_Halt& b) { b.Deceleration = 2500.0; }
  static void set_input(fb::MC_Halt& b, double x) { b.Deceleration = x; }
  static double sent(const plc::Command& c) { return c.deceleration; }
  static Outputs view(const fb::MC_Halt& b) {
    return {b.Busy, b.Active, b.Done, false, b.CommandAborted, b.Error, b.ErrorID};
  }
};

template <>
struct Adapter<fb::MC_Stop> {
  static constexpr plc::CommandType kType = plc::CommandType::kStop;
  static constexpr bool kHasDone = true;
  static constexpr bool kAbortable = true;
  static constexpr bool kHasActive = true;
  static constexpr bool kHasInput = true;
  static void prepare(fb::MC_Stop& b) { b.Deceleration = 8000.0; }
  static void set_input(fb::MC_Stop& b, double x) { b.Deceleration = x; }
  static double sent(const plc::Command& c) { return c.deceleration; }
  static Outputs view(const fb::MC_Stop& b) {
    return {b.Busy, b.Active, b.Done, false, b.CommandAborted, b.Error, b.ErrorID};
  }
};

template <>
struct Adapter<fb::MC_Reset> {
  static constexpr plc::CommandType kType = plc::CommandType::kReset;
  static constexpr bool kHasDone = true;
  static constexpr bool kAbortable = false;  // no Active, no CommandAborted
  static constexpr bool kHasActive = false;
  static constexpr bool kHasInput = false;
  static void prepare(fb::MC_Reset&) {}
  static void set_input(fb::MC_Reset&, double) {}
  static double sent(const plc::Command&) { return 0.0; }
  static Outputs view(const fb::MC_Reset& b) {
    return {b.Busy, false, b.Done, false, false, b.Error, b.ErrorID};
  }
};

template <>
struct Adapter<fb::MC_MoveModulo> {
  static constexpr plc::CommandType kType = plc::CommandType::kMoveModulo;
  static constexpr bool kHasDone = true;
  static constexpr bool kAbortable = true;
  static constexpr bool kHasActive = true;
  static constexpr bool kHasInput = true;
  static void prepare(fb::MC_MoveModulo& b) {
    b.Position = 90.0;
    b.Velocity = 1000.0;
  }
  static void set_input(fb::MC_MoveModulo& b, double x) { b.Position = x; }
  static double sent(const plc::Command& c) { return c.position; }
  static Outputs view(const fb::MC_MoveModulo& b) {
    return {b.Busy, b.Active, b.Done, false, b.CommandAborted, b.Error, b.ErrorID};
  }
};

// The online changes (seed 000 §2.3, §2.4) have Done and CommandAborted but no Active, as in
// Tc2: their "running" is shown by Busy alone.
template <>
struct Adapter<fb::MC_NewPos> {
  static constexpr plc::CommandType kType = plc::CommandType::kNewPos;
  static constexpr bool kHasDone = true;
  static constexpr bool kAbortable = true;
  static constexpr bool kHasActive = false;
  static constexpr bool kHasInput = true;
  static void prepare(fb::MC_NewPos& b) { b.NewPos = 3000.0; }
  static void set_input(fb::MC_NewPos& b, double x) { b.NewPos = x; }
  static double sent(const plc::Command& c) { return c.position; }
  static Outputs view(const fb::MC_NewPos& b) {
    return {b.Busy, false, b.Done, false, b.CommandAborted, b.Error, b.ErrorID};
  }
};

template <>
struct Adapter<fb::MC_NewPosAndVelo> {
  static constexpr plc::CommandType kType = plc::CommandType::kNewPosAndVelo;
  static constexpr bool kHasDone = true;
  static constexpr bool kAbortable = true;
  static constexpr bool kHasActive = false;
  static constexpr bool kHasInput = true;
  static void prepare(fb::MC_NewPosAndVelo& b) {
    b.NewPos = 3000.0;
    b.NewVelo = 1000.0;
    b.ActivationPos = 1500.0;
  }
  static void set_input(fb::MC_NewPosAndVelo& b, double x) { b.NewPos = x; }
  static double sent(const plc::Command& c) { return c.position; }
  static Outputs view(const fb::MC_NewPosAndVelo& b) {
    return {b.Busy, false, b.Done, false, b.CommandAborted, b.Error, b.ErrorID};
  }
};

// Position compensation runs beside the axis's job: its Active follows its own answer, not
// CmdNo, and it ends early by a compensation stop (it cannot be taken over by another
// MC_MoveSuperImposed: the NC refuses that with 0x4245).
template <>
struct Adapter<fb::MC_MoveSuperImposed> {
  static constexpr plc::CommandType kType = plc::CommandType::kMoveSuperImposed;
  static constexpr bool kHasDone = true;
  static constexpr bool kAbortable = true;
  static constexpr bool kHasActive = true;
  static constexpr bool kHasInput = true;
  static constexpr bool kBesideJob = true;  // never takes CmdNo
  static void prepare(fb::MC_MoveSuperImposed& b) {
    b.Distance = 250.0;
    b.VelocityDiff = 300.0;
    b.Acceleration = 500.0;
    b.Deceleration = 1000.0;
    b.VelocityProcess = 2000.0;
    b.Length = 5000.0;
  }
  static void set_input(fb::MC_MoveSuperImposed& b, double x) { b.Distance = x; }
  static double sent(const plc::Command& c) { return c.position; }
  static Outputs view(const fb::MC_MoveSuperImposed& b) {
    return {b.Busy, b.Active, b.Done, false, b.CommandAborted, b.Error, b.ErrorID};
  }
  // Ends the running compensation early: a compensation stop.
  static void take_over(plc::AXIS_REF& axis) {
    plc::Command stop;
    stop.type = plc::CommandType::kAbortSuperposition;
    REQUIRE(axis.Mailbox.post(stop) != 0);
  }
};

template <>
struct Adapter<fb::MC_AbortSuperposition> {
  static constexpr plc::CommandType kType = plc::CommandType::kAbortSuperposition;
  static constexpr bool kHasDone = true;
  static constexpr bool kAbortable = false;
  static constexpr bool kHasActive = false;
  static constexpr bool kHasInput = false;
  static void prepare(fb::MC_AbortSuperposition&) {}
  // A compensation runs for the block to stop.
  static void arrange(ScriptedNc& nc) { nc.start_compensation(); }
  static void set_input(fb::MC_AbortSuperposition&, double) {}
  static double sent(const plc::Command&) { return 0.0; }
  static Outputs view(const fb::MC_AbortSuperposition& b) {
    return {b.Busy, false, b.Done, false, false, b.Error, b.ErrorID};
  }
};

template <>
struct Adapter<fb::MC_ExtSetPointGenEnable> {
  static constexpr plc::CommandType kType = plc::CommandType::kExtSetPointGenEnable;
  static constexpr bool kHasDone = true;
  static constexpr bool kAbortable = false;
  static constexpr bool kHasActive = false;
  static constexpr bool kHasInput = true;
  static void prepare(fb::MC_ExtSetPointGenEnable& b) {
    b.Position = 1500.0;
    b.PositionType = fb::POSITIONTYPE_ABSOLUTE;
  }
  static void set_input(fb::MC_ExtSetPointGenEnable& b, double x) { b.Position = x; }
  static double sent(const plc::Command& c) { return c.position; }
  static Outputs view(const fb::MC_ExtSetPointGenEnable& b) {
    return {b.Busy, false, b.Done, false, false, b.Error, b.ErrorID};
  }
};

template <>
struct Adapter<fb::MC_ExtSetPointGenDisable> {
  static constexpr plc::CommandType kType = plc::CommandType::kExtSetPointGenDisable;
  static constexpr bool kHasDone = true;
  static constexpr bool kAbortable = false;
  static constexpr bool kHasActive = false;
  static constexpr bool kHasInput = false;
  static void prepare(fb::MC_ExtSetPointGenDisable&) {}
  static void set_input(fb::MC_ExtSetPointGenDisable&, double) {}
  static double sent(const plc::Command&) { return 0.0; }
  static Outputs view(const fb::MC_ExtSetPointGenDisable& b) {
    return {b.Busy, false, b.Done, false, false, b.Error, b.ErrorID};
  }
};

// Every Execute-type block; those among them that start motion (they have Active,
// CommandAborted and a latched input besides Execute); the online changes of a running motion
// (CommandAborted and a latched input, no Active); and both together.
#define FBTEST_MOTION_BLOCKS                                                                     \
  fb::MC_MoveAbsolute, fb::MC_MoveRelative, fb::MC_MoveModulo, fb::MC_MoveVelocity, fb::MC_Halt, \
      fb::MC_Stop
#define FBTEST_ONLINE_BLOCKS fb::MC_NewPos, fb::MC_NewPosAndVelo
#define FBTEST_ABORTABLE_BLOCKS FBTEST_MOTION_BLOCKS, FBTEST_ONLINE_BLOCKS
// Blocks whose command runs beside the axis's job (Busy and Active while it runs, Done or
// CommandAborted at its end) without taking the axis from another block.
#define FBTEST_BESIDE_JOB_BLOCKS fb::MC_MoveSuperImposed
// Blocks the NC answers in the cycle it takes their command.
#define FBTEST_INSTANT_BLOCKS \
  fb::MC_Reset, fb::MC_AbortSuperposition, fb::MC_ExtSetPointGenEnable, fb::MC_ExtSetPointGenDisable
#define FBTEST_EXECUTE_BLOCKS \
  FBTEST_ABORTABLE_BLOCKS, FBTEST_BESIDE_JOB_BLOCKS, FBTEST_INSTANT_BLOCKS

// The command runs beside the axis's job (position compensation): it never takes CmdNo.
template <class B>
constexpr bool beside_job() {
  if constexpr (requires { Adapter<B>::kBesideJob; }) {
    return Adapter<B>::kBesideJob;
  } else {
    return false;
  }
}

// The number the scripted NC runs the block's job under.
template <class B>
uint16_t running_number(const ScriptedNc& nc) {
  return beside_job<B>() ? nc.compensating() : nc.executing();
}

// The block shows its command running: Active where the block has it, else Busy.
template <class B>
bool shows_running(const Outputs& o) {
  return Adapter<B>::kHasActive ? o.active : o.busy;
}

// The rules that hold at every call of every Execute-type block.
template <class B>
void check_every_call_rules(const Outputs& o, const plc::AXIS_REF& axis, uint16_t number) {
  const int results = int{o.done} + int{o.error} + int{o.aborted};
  INFO("busy " << o.busy << " active " << o.active << " done " << o.done << " in_velocity "
               << o.in_velocity << " aborted " << o.aborted << " error " << o.error << " error_id "
               << o.error_id);
  // Busy, Done, Error, CommandAborted: at most one.
  REQUIRE(int{o.busy} + results <= 1);
  // Active, Done, Error, CommandAborted: at most one.
  REQUIRE(int{o.active} + results <= 1);
  // Active only while the axis executes this block's command and the NC runs it.
  const plc::CommandState state = axis.Mailbox.answer(number).state;
  const bool runs = number != 0 && (beside_job<B>() || axis.NcToPlc.CmdNo == number) &&
                    (state == plc::CommandState::kActive || state == plc::CommandState::kReached);
  if constexpr (Adapter<B>::kHasActive) {
    REQUIRE(o.active == (o.busy && runs));
  } else {
    REQUIRE_FALSE(o.active);
  }
  // ErrorID only with Error, and never 0 with it.
  REQUIRE(o.error == (o.error_id != 0));
  // InVelocity only on a busy block whose job reached its velocity.
  if (o.in_velocity) {
    REQUIRE(o.busy);
    REQUIRE(state == plc::CommandState::kReached);
  }
}

// One block on one axis with a scripted NC; every call is checked.
template <class B>
struct Bench {
  plc::AXIS_REF axis{};
  ScriptedNc nc{axis};
  B block{};
  std::size_t calls = 0;

  Bench() {
    if constexpr (requires { Adapter<B>::arrange(nc); }) Adapter<B>::arrange(nc);
    Adapter<B>::prepare(block);
  }

  Outputs call() {
    block(axis);
    ++calls;
    INFO("call " << calls);
    const Outputs o = Adapter<B>::view(block);
    check_every_call_rules<B>(o, axis, block.command_number());
    return o;
  }
  Outputs call(bool execute) {
    block.Execute = execute;
    return call();
  }
  // Commands of this block's type the NC has taken so far.
  std::size_t taken() const { return nc.count(Adapter<B>::kType); }
};

}  // namespace fbtest
