// fuzz_blocks (issue 16): the input bytes become a PLC program against the real kernel — 1 to 4
// axes of assorted kinds, then a stream of operations: any block called with any inputs (NaN,
// ±inf, huge, denormal, zero, negative and plausible values), Execute edges, enables and
// override toggled (through MC_Power, MC_SetOverride and raw writes of PlcToNc.Override),
// GearRatio1 written, external setpoint packets fed, bursts of more commands than the mailbox
// holds, and faults injected: a feed enable or the controller enable lost, and axes whose drive
// saturates at 50 mm/s so that a fast move runs into its following-error limit (0x4550). A
// coupling program (bit 7 of the first byte) adds MC_GearIn (any master, ratio, denominator) and
// MC_GearOut on every axis; a slave in gear is checked to follow its master. A feature program
// (bit 4 of the first byte) adds, per axis, a homing configuration (reference cam, any homing
// values), a two-speed axis or DELAYED error propagation (any delay, actual-value coupling), and
// the operations MC_Home (any mode, position, cam signal), MC_GearInDyn (any factor per cycle,
// AccBound, Enable toggled) and Kernel::push_by_hand (any axis index, any velocity). An HLI
// program (bits 4 and 5) is a feature program whose axes also get a logical axis number and
// P-AXIS-00436 / 00460, with HLI_AxisCoupling lists (any sources, modes, fractions, unknown axis
// numbers, Execute edges, a null unit), raw writes into the control units and
// Kernel::command_position_request; the control units are checked after every NC cycle
// (hli_rules.hpp) and an HLI target's drive against Σ |K| × its sources' limits (axis_watch.hpp).
// Every PLC cycle calls every block of every axis that the program has used once (a block never
// given an edge or enable is idle and skipped), then the NC cycle runs. Checked at every
// cycle, each a crash when broken: the block output rules (block_rules.hpp) after every call, the
// axis invariants (axis_watch.hpp: finite image, set velocity and acceleration within the limits,
// every command answered within 2 cycles and never twice differently), and no allocation in the
// PLC calls and the NC cycle. Only the public API is used (fb blocks, nc::Kernel, AXIS_REF).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "allocation_count.hpp"
#include "axis_watch.hpp"
#include "block_rules.hpp"
#include "byte_reader.hpp"
#include "fail.hpp"
#include "fb/fb.hpp"
#include "hli_rules.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/config.hpp"
#include "nc_core/kernel.hpp"

namespace {

constexpr std::size_t kMaxAxes = 4;
constexpr std::size_t kBurst = 20;  // more than CommandMailbox::kQueueCapacity (16)
constexpr int kMaxCycles = 3000;    // per input, keeps an execution short
constexpr std::size_t kExecuteKinds = 13;
// Bit 7 of the first byte (the NC cycle) makes a coupling program: two more operations, MC_GearIn
// (any master, any ratio) and MC_GearOut, on every axis. Without it a program decodes as before,
// so the kept inputs keep their meaning.
constexpr uint8_t kCouplingProgram = 0x80U;
constexpr std::size_t kPlainOps = 12;
constexpr std::size_t kCouplingOps = 14;
// Bit 4 of the first byte makes a feature program: a second configuration byte per axis (homing,
// two-speed, error propagation) and three more operations (MC_Home, MC_GearInDyn, push by hand)
// besides the coupling ones. The bit is clear in every kept input (corpus and regressions), so
// they keep their meaning.
constexpr uint8_t kFeatureProgram = 0x10U;
constexpr std::size_t kFeatureOps = 18;
// Bits 4 and 5 of the first byte together make an HLI program: a feature program whose axes
// have a third configuration byte (logical axis number, P-AXIS-00436 / 00460) and four more
// operations: HLI_AxisCoupling lists, raw writes into the control unit, and
// Kernel::command_position_request. No kept input has both bits, so they keep their meaning.
constexpr uint8_t kHliProgram = 0x20U;
constexpr std::size_t kHliOps = 22;

// The blocks of one axis and the PLC program's own values for it.
struct AxisProgram {
  fb::MC_Power power;
  fb::MC_Reset reset;
  fb::MC_MoveAbsolute absolute;
  fb::MC_MoveRelative relative;
  fb::MC_MoveModulo modulo;
  fb::MC_MoveVelocity velocity;
  fb::MC_Halt halt;
  fb::MC_Stop stop;
  fb::MC_SetOverride set_override;
  fb::MC_NewPos new_pos;
  fb::MC_NewPosAndVelo new_pos_and_velo;
  fb::MC_MoveSuperImposed superimposed;
  fb::MC_AbortSuperposition abort_superposition;
  fb::MC_ExtSetPointGenEnable ext_enable;
  fb::MC_ExtSetPointGenDisable ext_disable;
  fb::MC_ReadStatus status;
  fb::MC_ReadActualPosition actual_position;
  fb::MC_ReadAxisError axis_error;
  // Coupling programs only (see kCouplingProgram): this axis as slave.
  fb::MC_GearIn gear_in;
  fb::MC_GearOut gear_out;
  // Feature programs only (see kFeatureProgram).
  fb::MC_Home home;
  uint8_t cam_source = 0;  // 0: the kernel's simulated reference cam; 1: off; 2: on
  bool cam = false;        // bCalibrationCam of this cycle
  fb::MC_GearInDyn gear_dyn;
  std::size_t dyn_master = 0;       // the master input of gear_dyn
  std::size_t dyn_edge_master = 0;  // ... when gear_dyn posted its last coupling command
  double dyn_edge_bound = 0.0;      // ... and its Acceleration (AccBound) then
  // MC_Home and MC_GearInDyn are called once the program has set their inputs: an untouched
  // MC_Home stays idle, and an untouched MC_GearInDyn would only write its default GearRatio
  // over the program's raw GearRatio1 writes.
  bool home_used = false;
  bool dyn_used = false;
  // HLI programs only (see kHliProgram): the coupling block on this axis's control unit.
  fb::HLI_AxisCoupling hli;
  bool hli_used = false;        // called every cycle once the program gave it an edge
  bool hli_null_unit = false;   // called with a null unit (Error 0x4F08)
  int hli_busy = 0;             // consecutive calls Busy since the last raw semaphore write
  bool hli_written = false;     // a list was ever written for this axis (block or raw)
  double hli_fract = 0.0;       // largest |fract_num / fract_denom| <= 1000 ever written for it
  bool gear_slave = false;      // ever given an MC_GearIn edge or MC_GearInDyn input
  std::size_t gear_master = 0;  // the master input of gear_in
  std::size_t edge_master = 0;  // the master input when gear_in posted its last command
  // The blocks the program has ever given an input edge or an enable (kCalled bits). One that
  // never had one is idle: its Execute (or Enable) has been false since it was made, so a call
  // starts nothing, posts nothing and leaves its outputs at their defaults (all false, ErrorID
  // 0; fb/src/execute_block.cpp begin_call / end_call in phase kIdle, MC_SetOverride with
  // Enable false). Such calls are skipped: they are most of a cycle's calls under the sanitizers.
  uint32_t called = 0;
  std::array<fb::MC_MoveRelative, kBurst> burst;
  // Burst blocks [0, bursts) have had a rising edge; the others have never been executed, so a
  // call leaves them idle and is skipped (the blocks are most of the calls of a cycle).
  std::size_t bursts = 0;
  double feed_p = 0.0, feed_v = 0.0, feed_a = 0.0;
  int32_t feed_direction = 0;
  bool feeding = false;
};

// kCalled bits: bit k (k < kExecuteKinds) for the Execute block of edit_execute_block's kind k,
// then MC_SetOverride, MC_GearIn and MC_GearOut.
constexpr uint32_t kCalledSetOverride = 1U << kExecuteKinds;
constexpr uint32_t kCalledGearIn = kCalledSetOverride << 1U;
constexpr uint32_t kCalledGearOut = kCalledGearIn << 1U;
constexpr uint32_t called_kind(std::size_t kind) {
  return 1U << kind;
}

// Calls the block (with the output rules) only once the program has ever set its input.
template <class Block>
void call_if_used(const AxisProgram& a, uint32_t bit, Block& block, plc::AXIS_REF& axis) noexcept {
  if ((a.called & bit) != 0) fuzz::call_checked(block, axis);
}

nc::AxisConfig axis_config(std::size_t index, uint8_t variant) {
  nc::AxisConfig c;
  c.name = "axis" + std::to_string(index);
  if ((variant & 0x01U) != 0) {
    c.sw_limit_min_enabled = c.sw_limit_max_enabled = true;
    c.sw_limit_min = -1000.0;
    c.sw_limit_max = 1000.0;
  }
  if ((variant & 0x02U) != 0) {
    c.drive_model = nc::DriveModel::kFirstOrderLag;
    c.drive_time_constant = 0.01;
    c.drive_dead_time = 0.002;
  }
  if ((variant & 0x04U) != 0) {
    // Fault injection: the drive saturates, a fast move lags into the following-error limit.
    c.drive_max_velocity = 50.0;
    c.following_error_limit = 1.0;
    c.following_error_filter_time = 0.0;
  }
  if ((variant & 0x08U) != 0) c.kind = nc::AxisKind::kEncoder;
  c.override_type = 1 + ((variant >> 4U) & 0x03U);
  if ((variant & 0x40U) != 0) c.ext_setpoint_delay = 0.004;
  if ((variant & 0x80U) != 0) {
    c.modulo_factor = 100.0;
    c.target_window_enabled = false;
  }
  return c;
}

fb::MC_BufferMode buffer_mode(fuzz::ByteReader& in) {
  return in.below(8) == 0 ? static_cast<fb::MC_BufferMode>(static_cast<int8_t>(in.byte()))
                          : fb::MC_Aborting;
}
fb::MC_Direction direction(fuzz::ByteReader& in) {
  const uint8_t b = in.byte();
  return static_cast<fb::MC_Direction>(b < 200 ? 1 + b % 4 : static_cast<int8_t>(b));
}

// Feature programs: the second configuration byte of an axis. Bits 0-1: 1 a homing axis (not
// homed at the start, any homing values), 2 a two-speed axis (any two-speed values), 3 a homing
// axis homed at the start; bit 2: DELAYED error propagation with any delay; bit 3: its slaves
// follow its actual values (C8). A value the configuration rules refuse keeps the default.
template <class T>
void try_field(nc::AxisConfig& c, T nc::AxisConfig::*field, T value) {
  const T before = c.*field;
  c.*field = value;
  try {
    nc::validate(c);
  } catch (const nc::ConfigError&) {
    c.*field = before;
  }
}

void feature_config(nc::AxisConfig& c, uint8_t feature, fuzz::ByteReader& in) {
  if (fuzz::g_trace) std::fprintf(stderr, " feature 0x%X", feature);
  const uint8_t kind = feature & 0x03U;
  if (kind == 1 || kind == 3) {
    c.homed_at_start = kind == 3;
    c.homing_cam_search_positive = in.flag();
    c.homing_sync_search_positive = in.flag();
    try_field(c, &nc::AxisConfig::homing_velocity_to_cam, in.number());
    try_field(c, &nc::AxisConfig::homing_velocity_off_cam, in.number());
    try_field(c, &nc::AxisConfig::homing_sync_pulse_distance, in.number());
    try_field(c, &nc::AxisConfig::homing_search_distance, in.number());
    try_field(c, &nc::AxisConfig::homing_reference_position, in.number());
    try_field(c, &nc::AxisConfig::homing_cam_position, in.number());
    try_field(c, &nc::AxisConfig::homing_cam_width, in.number());
  } else if (kind == 2) {
    c = nc::AxisConfig{c.name};  // the servo variants do not apply
    c.kind = nc::AxisKind::kTwoSpeed;
    try_field(c, &nc::AxisConfig::rapid_velocity, in.number());
    try_field(c, &nc::AxisConfig::creep_velocity, in.number());
    try_field(c, &nc::AxisConfig::creep_distance_positive, in.number());
    try_field(c, &nc::AxisConfig::creep_distance_negative, in.number());
    try_field(c, &nc::AxisConfig::braking_distance_positive, in.number());
    try_field(c, &nc::AxisConfig::braking_distance_negative, in.number());
    try_field(c, &nc::AxisConfig::creep_distance_stop, in.number());
    try_field(c, &nc::AxisConfig::two_speed_ramp_time, in.number());
    try_field(c, &nc::AxisConfig::looping_distance, in.number());
    try_field(c, &nc::AxisConfig::looping_distance_enabled, in.flag());
  }
  if ((feature & 0x04U) != 0) {
    c.error_propagation_mode = nc::ErrorPropagation::kDelayed;
    try_field(c, &nc::AxisConfig::error_propagation_delay, in.number());
  }
  if ((feature & 0x08U) != 0) c.couple_slave_to_actual_values = true;
}

// HLI programs: the third configuration byte of an axis. Bits 0-5: its logical axis number is
// index + 1 + 4 x those bits (unique in the kernel); bit 6: P-AXIS-00436 (forward mapping),
// bit 7: P-AXIS-00460 (absolute; taken only with 00436). Software limits (variant bit 0) and
// homed at the start (feature kind 3) make a FRACT target monitored by 70195.
void hli_config(nc::AxisConfig& c, std::size_t index, uint8_t b, fuzz::ByteReader&) {
  if (fuzz::g_trace) std::fprintf(stderr, " hli 0x%X", b);
  c.id = static_cast<int>(index + 1 + 4U * (b & 0x3FU));
  try_field(c, &nc::AxisConfig::recalc_link_main_input_position, (b & 0x40U) != 0);
  try_field(c, &nc::AxisConfig::recalc_input_position_absolute, (b & 0x80U) != 0);
}

// One PLC cycle of one axis: every block the program has used once, in a fixed order (the gear
// blocks in coupling programs only, `master` being gear_in's master input; MC_Home and
// MC_GearInDyn in feature programs only, `dyn_master` being gear_dyn's master input;
// HLI_AxisCoupling in HLI programs only, on `hli_unit`).
void plc_cycle(AxisProgram& a, plc::AXIS_REF& axis, const plc::AXIS_REF* master,
               const plc::AXIS_REF* dyn_master, plc::hli::HLI_AX* hli_unit) {
  a.power(axis);
  if (a.called != 0) {
    call_if_used(a, called_kind(0), a.reset, axis);
    call_if_used(a, called_kind(1), a.absolute, axis);
    call_if_used(a, called_kind(2), a.relative, axis);
    call_if_used(a, called_kind(3), a.modulo, axis);
    call_if_used(a, called_kind(4), a.velocity, axis);
    call_if_used(a, called_kind(5), a.halt, axis);
    call_if_used(a, called_kind(6), a.stop, axis);
    if ((a.called & kCalledSetOverride) != 0) a.set_override(axis);
    call_if_used(a, called_kind(7), a.new_pos, axis);
    call_if_used(a, called_kind(8), a.new_pos_and_velo, axis);
    call_if_used(a, called_kind(9), a.superimposed, axis);
    call_if_used(a, called_kind(10), a.abort_superposition, axis);
    call_if_used(a, called_kind(11), a.ext_enable, axis);
    call_if_used(a, called_kind(12), a.ext_disable, axis);
  }
  for (std::size_t i = 0; i < a.bursts; ++i)
    fuzz::call_checked(a.burst[i], axis);
  if (a.feeding) {
    (void)fb::MC_ExtSetPointGenFeed(a.feed_p, a.feed_v, a.feed_a, a.feed_direction, axis);
  }
  if (master != nullptr && (a.called & kCalledGearIn) != 0) {
    // An edge the block takes posts a new command (one while Busy is ignored).
    const uint16_t before = a.gear_in.command_number();
    a.gear_in(*master, axis);
    if (a.gear_in.command_number() != before) a.edge_master = a.gear_master;
    if (const char* broken = fuzz::broken_output_rule(a.gear_in)) fuzz::fail(broken);
    if (a.gear_in.InGear && !a.gear_in.Busy) fuzz::fail("InGear without Busy");
  }
  if (master != nullptr) call_if_used(a, kCalledGearOut, a.gear_out, axis);
  if (dyn_master != nullptr && a.home_used) {
    a.home.bCalibrationCam = a.cam;
    fuzz::call_checked(a.home, axis);
  }
  if (dyn_master != nullptr && a.dyn_used) {
    const uint16_t before = a.gear_dyn.command_number();
    a.gear_dyn(*dyn_master, axis);
    if (a.gear_dyn.command_number() != before) {
      a.dyn_edge_master = a.dyn_master;
      a.dyn_edge_bound = a.gear_dyn.Acceleration;
    }
    if (const char* broken = fuzz::broken_output_rule(a.gear_dyn)) fuzz::fail(broken);
    if (a.gear_dyn.InGear && !a.gear_dyn.Busy) fuzz::fail("InGear without Busy");
  }
  if (hli_unit != nullptr && a.hli_used) {
    a.hli(a.hli_null_unit ? nullptr : hli_unit);
    if (const char* broken = fuzz::broken_output_rule(a.hli)) fuzz::fail(broken);
    if (a.hli.Error && !fuzz::documented_hli_id(a.hli.ErrorID)) {
      fuzz::fail("HLI_AxisCoupling shows an ErrorID the kernel does not document");
    }
    // The NC evaluates a list in the cycle it sees the semaphore: the block writes in the call
    // after its edge at the latest (a raw write may hold the semaphore for one cycle).
    a.hli_busy = a.hli.Busy ? a.hli_busy + 1 : 0;
    if (a.hli_busy > 2) fuzz::fail("an HLI list is not answered within 2 NC cycles");
  }
  a.status(axis);
  a.actual_position(axis);
  a.axis_error(axis);
}

template <class Block>
void set_motion(Block& b, fuzz::ByteReader& in) {
  b.Velocity = in.number();
  b.Acceleration = in.number();
  b.Deceleration = in.number();
  b.Jerk = in.number();
  b.BufferMode = buffer_mode(in);
}

// Sets one Execute block's inputs and toggles its Execute; tells the watch what it may allow.
void edit_execute_block(AxisProgram& a, fuzz::AxisWatch& watch, fuzz::ByteReader& in) {
  const std::size_t kind = in.below(kExecuteKinds);
  if (fuzz::g_trace) std::fprintf(stderr, " block %zu", kind);
  a.called |= called_kind(kind);
  switch (kind) {
    case 0:
      a.reset.Execute = !a.reset.Execute;
      break;
    case 1:
      a.absolute.Position = in.number();
      set_motion(a.absolute, in);
      watch.allow_dynamics(a.absolute.Acceleration, a.absolute.Deceleration);
      a.absolute.Execute = !a.absolute.Execute;
      break;
    case 2:
      a.relative.Distance = in.number();
      set_motion(a.relative, in);
      watch.allow_dynamics(a.relative.Acceleration, a.relative.Deceleration);
      a.relative.Execute = !a.relative.Execute;
      break;
    case 3:
      a.modulo.Position = in.number();
      set_motion(a.modulo, in);
      a.modulo.Direction = direction(in);
      watch.allow_dynamics(a.modulo.Acceleration, a.modulo.Deceleration);
      a.modulo.Execute = !a.modulo.Execute;
      break;
    case 4:
      set_motion(a.velocity, in);
      a.velocity.Direction = direction(in);
      watch.allow_dynamics(a.velocity.Acceleration, a.velocity.Deceleration);
      a.velocity.Execute = !a.velocity.Execute;
      break;
    case 5:
      a.halt.Deceleration = in.number();
      a.halt.Jerk = in.number();
      a.halt.BufferMode = buffer_mode(in);
      watch.allow_dynamics(0.0, a.halt.Deceleration);
      a.halt.Execute = !a.halt.Execute;
      break;
    case 6:
      a.stop.Deceleration = in.number();
      a.stop.Jerk = in.number();
      watch.allow_dynamics(0.0, a.stop.Deceleration);
      a.stop.Execute = !a.stop.Execute;
      break;
    case 7:
      a.new_pos.NewPos = in.number();
      a.new_pos.Execute = !a.new_pos.Execute;
      break;
    case 8:
      a.new_pos_and_velo.NewPos = in.number();
      a.new_pos_and_velo.NewVelo = in.number();
      a.new_pos_and_velo.ActivationPos = in.number();
      a.new_pos_and_velo.Execute = !a.new_pos_and_velo.Execute;
      break;
    case 9: {
      fb::MC_MoveSuperImposed& c = a.superimposed;
      c.Distance = in.number();
      c.VelocityDiff = in.number();
      c.Acceleration = in.number();
      c.Deceleration = in.number();
      c.VelocityProcess = in.number();
      c.Length = in.number();
      watch.allow_compensation(c.VelocityDiff, c.Acceleration, c.Deceleration, c.VelocityProcess);
      c.Execute = !c.Execute;
      break;
    }
    case 10:
      a.abort_superposition.Execute = !a.abort_superposition.Execute;
      break;
    case 11: {
      a.ext_enable.Position = in.number();
      const uint8_t type = in.byte();
      a.ext_enable.PositionType =
          static_cast<fb::E_PositionType>(type < 250 ? 1 + type % 2 : static_cast<int8_t>(type));
      a.ext_enable.Execute = !a.ext_enable.Execute;
      break;
    }
    default:
      a.ext_disable.Execute = !a.ext_disable.Execute;
      break;
  }
}

// Feature programs: MC_Home's inputs and its Execute toggled. A default homing (from rest or
// aborting a move, with that move's dynamics) is a motion like any other for the watch.
void edit_home(AxisProgram& a, fuzz::ByteReader& in) {
  fb::MC_Home& h = a.home;
  a.home_used = true;
  const uint8_t mode = in.byte();
  h.HomingMode = static_cast<fb::MC_HomingMode>(mode < 200 ? mode % 7 : static_cast<int8_t>(mode));
  h.Position = in.flag() ? fb::DEFAULT_HOME_POSITION : in.number();
  h.BufferMode = buffer_mode(in);
  a.cam_source = static_cast<uint8_t>(in.below(3));
  if (fuzz::g_trace) std::fprintf(stderr, " home mode %d cam %u", h.HomingMode, a.cam_source);
  h.Execute = !h.Execute;
}

// Feature programs: MC_GearInDyn's factor (written every cycle), AccBound, master, Enable.
void edit_gear_dyn(AxisProgram& a, std::size_t n_axes, fuzz::ByteReader& in) {
  fb::MC_GearInDyn& g = a.gear_dyn;
  a.dyn_used = true;
  a.gear_slave = true;
  g.GearRatio = in.number();
  if (in.flag()) g.Acceleration = in.number();
  if (in.flag()) {
    a.dyn_master = in.below(n_axes);
    g.Enable = !g.Enable;
  }
}

// HLI programs: an ax_nr for a list entry or a query: mostly one of the kernel's axes, else a
// small number around them (0, negative, unknown) or any int32.
int32_t hli_axis_number(const std::array<int, kMaxAxes>& ids, std::size_t n_axes,
                        fuzz::ByteReader& in) {
  const uint8_t b = in.byte();
  if (b < 200) return ids[b % n_axes];
  if (b < 240) return static_cast<int32_t>(b) - 220;
  // Two statements: the operands of | are read in no specified order (see op 16).
  const uint32_t high = in.u16();
  const uint32_t low = in.u16();
  return static_cast<int32_t>((high << 16U) | low);
}

// HLI programs: one list entry as a PLC may write it: any source, mode (mostly 0 … 4), fraction.
plc::hli::HLI_AX_COUPLING_DESC hli_entry(const std::array<int, kMaxAxes>& ids, std::size_t n_axes,
                                         fuzz::ByteReader& in) {
  plc::hli::HLI_AX_COUPLING_DESC d;
  d.ax_nr = hli_axis_number(ids, n_axes, in);
  const uint8_t mode = in.byte();
  d.mode = mode < 240 ? static_cast<uint16_t>(mode % 5) : static_cast<uint16_t>(mode * 257U);
  if (d.mode == plc::hli::HLI_AXIS_COUPLING_FRACT) {
    d.fract_num = static_cast<int16_t>(in.u16());
    const uint8_t denom = in.byte();
    d.fract_denom = denom < 128 ? static_cast<int16_t>(static_cast<int>(denom % 9) - 4)
                                : static_cast<int16_t>(in.u16());
  }
  if (fuzz::g_trace) {
    std::fprintf(stderr, " {%d %u %d/%d}", d.ax_nr, d.mode, d.fract_num, d.fract_denom);
  }
  return d;
}

// What a FRACT entry may add to the bound of its target's drive (a refused one adds nothing).
double fract_factor(const plc::hli::HLI_AX_COUPLING_DESC& d) {
  if (d.mode != plc::hli::HLI_AXIS_COUPLING_FRACT || d.fract_denom == 0) return 0.0;
  const double k = std::fabs(static_cast<double>(d.fract_num) / d.fract_denom);
  return k <= plc::hli::HLI_AXIS_COUPLING_FACT_MAX ? k : 0.0;
}

// HLI programs: an HLI_AxisCoupling list (1-8 entries written, then maybe an INACTIVE end; the
// rest stays as it was) and its Execute toggled; rarely the block is called with a null unit.
void edit_hli(AxisProgram& a, const std::array<int, kMaxAxes>& ids, std::size_t n_axes,
              fuzz::ByteReader& in) {
  a.hli_used = true;
  a.hli_written = true;
  const std::size_t count = in.below(a.hli.desc.size() + 1);
  if (fuzz::g_trace) std::fprintf(stderr, " hli list %zu", count);
  for (std::size_t e = 0; e < count; ++e) {
    a.hli.desc[e] = hli_entry(ids, n_axes, in);
    a.hli_fract = std::max(a.hli_fract, fract_factor(a.hli.desc[e]));
  }
  if (count < a.hli.desc.size() && in.flag()) a.hli.desc[count] = {};
  a.hli_null_unit = in.below(32) == 0;
  a.hli.Execute = !a.hli.Execute;
}

struct Program {
  nc::Kernel kernel;
  std::vector<plc::AXIS_REF*> axes;
  std::vector<AxisProgram> programs;
  std::vector<fuzz::AxisWatch> watches;
  std::vector<std::string> names;
  std::vector<const plc::NCTOIO_DRIVE_TWO_SPEED*> two_speed_images;
  int cycles = 0;
  bool drive_went_off = false;  // some axis's drive went off in this cycle under moving set values
  bool coupling = false;
  bool features = false;
  bool hli = false;
  // HLI programs: the axes' logical numbers and the lists in force after the last cycle.
  std::array<int, kMaxAxes> ids{};
  std::array<std::array<plc::hli::HLI_AX_COUPLING_STATE_DESC, 8>, kMaxAxes> hli_last{};

  // One tick: the PLC calls every block of every axis, then one NC cycle; then the checks.
  void tick() {
    if (features) {
      // The cam signals of this cycle (a set-up lookup by name: outside the counted region).
      for (std::size_t i = 0; i < axes.size(); ++i) {
        AxisProgram& a = programs[i];
        if (a.home_used)
          a.cam = a.cam_source == 0 ? kernel.reference_cam(names[i]) : a.cam_source == 2;
      }
    }
    {
      const fuzz::AllocationRegion region;
      for (std::size_t i = 0; i < axes.size(); ++i) {
        AxisProgram& a = programs[i];
        plc_cycle(a, *axes[i], coupling ? axes[a.gear_master] : nullptr,
                  features ? axes[a.dyn_master] : nullptr, hli ? kernel.gpAx()[i] : nullptr);
        // The packet the NC reads is the one in PlcToNc: the feed of this cycle, or an older one
        // when this cycle's was refused (a direction outside -1 … 1 writes nothing).
        const plc::PLCTONC_AXIS_REF& out = axes[i]->PlcToNc;
        if ((out.ExtSetDirection == 1 || out.ExtSetDirection == -1) &&
            (a.ext_enable.Execute ||
             plc::test_bit(axes[i]->NcToPlc.StateDWord, plc::kStateExtSetPointGenEnabled))) {
          watches[i].allow_external(out.ExtSetVelo, out.ExtSetAcc);
        }
        watches[i].posted(*axes[i]);
      }
      // An axis whose drive goes off in this cycle while its set values move (the image still
      // shows the last cycle's; an axis that had an HLI list may show its drive instead, while
      // its slaves follow its program): its slaves leave their coupling (K26, docs/behaviour.md
      // "A master whose drive goes off under its slaves").
      drive_went_off = false;
      for (std::size_t i = 0; i < axes.size(); ++i) {
        const plc::AXIS_REF& axis = *axes[i];
        drive_went_off =
            drive_went_off || (!plc::test_bit(axis.PlcToNc.ControlDWord, plc::kControlEnable) &&
                               (axis.NcToPlc.SetVelo != 0.0 || axis.NcToPlc.SetAcc != 0.0 ||
                                programs[i].hli_written));
      }
      kernel.cycle();
      if (region.allocations() != 0) fuzz::fail("allocation in the PLC calls or the NC cycle");
    }
    for (std::size_t i = 0; i < axes.size(); ++i) {
      // The coupling in force is gear_in's last command (master: that edge's) while the slave's
      // CmdNo is that command's number and the block shows InGear; otherwise unknown here (an
      // edge just posted, or refused while an older coupling holds).
      const AxisProgram& a = programs[i];
      // A gear master with an HLI list publishes its drive values, its slaves follow its program
      // (docs/behaviour.md: the combination is not checked further): not followed then.
      const bool known = coupling && a.gear_in.InGear &&
                         axes[i]->NcToPlc.CmdNo == a.gear_in.command_number() &&
                         !programs[a.edge_master].hli_written && !a.hli_written;
      watches[i].follow(known ? &axes[a.edge_master]->NcToPlc : nullptr);
      if (drive_went_off) watches[i].leader_drive_went_off();
      if (hli) check_hli(i);
      if (features && a.gear_dyn.Busy && axes[i]->NcToPlc.CmdNo == a.gear_dyn.command_number() &&
          !programs[a.dyn_edge_master].hli_written && !a.hli_written) {
        // The cyclic coupling in force is gear_dyn's last one (master and AccBound: that edge's).
        watches[i].follow_cyclic(&axes[a.dyn_edge_master]->NcToPlc, a.gear_dyn.command_number(),
                                 a.dyn_edge_bound);
      }
      // The image kept between events (StateDWord bits, AxisState, CoupleState, compensation
      // values) equals its full recomputation (docs/performance.md "Fourth pass").
      if (!kernel.published_image_consistent(i)) {
        fuzz::fail("the kept image differs from its recomputation (a missed note_event())");
      }
      if (two_speed_images[i] != nullptr) {
        if (const char* broken = fuzz::broken_two_speed_image(*two_speed_images[i])) {
          fuzz::fail(broken);
        }
      }
      if (fuzz::g_trace && coupling) {
        std::fprintf(stderr, "  [%d] axis %zu gear: InGear %d number %u master %zu ratio %.17g\n",
                     cycles, i, a.gear_in.InGear ? 1 : 0, a.gear_in.command_number(), a.edge_master,
                     axes[i]->NcToPlc.GearRatio);
      }
      if (fuzz::g_trace) {
        const plc::NCTOPLC_AXIS_REF& n = axes[i]->NcToPlc;
        std::fprintf(stderr, "  [%d] axis %zu p %.9g v %.9g a %.9g err 0x%X cmd %u/%u\n", cycles, i,
                     n.SetPos, n.SetVelo, n.SetAcc, n.ErrorCode, n.CmdNo, n.CmdState);
      }
      if (const char* broken = watches[i].check(*axes[i])) {
        const plc::NCTOPLC_AXIS_REF& n = axes[i]->NcToPlc;
        std::fprintf(stderr,
                     "axis %zu cycle %d: SetPos %.17g SetVelo %.17g SetAcc %.17g (limits v %.17g "
                     "a %.17g) ErrorCode 0x%X StateDWord 0x%X non-finite %s\n",
                     i, cycles, n.SetPos, n.SetVelo, n.SetAcc, watches[i].velocity_limit(),
                     watches[i].acceleration_limit(), n.ErrorCode, n.StateDWord,
                     fuzz::non_finite_field(n) != nullptr ? fuzz::non_finite_field(n) : "none");
        fuzz::fail(broken);
      }
    }
    ++cycles;
  }

  // k ticks, as long as the program may run.
  void run(std::size_t k) {
    for (std::size_t i = 0; i < k && cycles < kMaxCycles; ++i)
      tick();
  }

  // HLI programs: a raw write into an axis's control unit, as a second writer besides the block:
  // one entry, and the semaphore set or not.
  void raw_hli(AxisProgram& a, std::size_t i, fuzz::ByteReader& in) {
    plc::hli::HLI_AX_COUPLING_COMMAND& command =
        kernel.gpAx()[i]->lr_mc_control.axis_coupling.command_w;
    const std::size_t slot = in.below(command.desc.size());
    if (fuzz::g_trace) std::fprintf(stderr, " raw hli [%zu]", slot);
    command.desc[slot] = hli_entry(ids, axes.size(), in);
    a.hli_fract = std::max(a.hli_fract, fract_factor(command.desc[slot]));
    if (in.flag()) {
      command.semaphor_rw = true;
      a.hli_written = true;
      a.hli_busy = 0;
    }
  }

  // HLI programs: Kernel::command_position_request of any ax_nr: finite for a known axis (its
  // drive position, or the program coordinate the list maps it to), NaN for an unknown one.
  void query_hli(fuzz::ByteReader& in) {
    const int32_t ax_nr = hli_axis_number(ids, axes.size(), in);
    const double q = kernel.command_position_request(ax_nr);
    if (fuzz::g_trace) std::fprintf(stderr, " cmdpos %d -> %.17g", ax_nr, q);
    const bool known =
        std::find(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(axes.size()), ax_nr) !=
        ids.begin() + static_cast<std::ptrdiff_t>(axes.size());
    if (known && !std::isfinite(q)) fuzz::fail("command position request of an axis not finite");
    if (!known && !std::isnan(q)) fuzz::fail("command position request of an unknown axis not NaN");
  }

  // HLI programs, after the NC cycle: the control unit's rules (hli_rules.hpp) and the bound of
  // the target's drive for the watch: Σ |K| × each source's program limits over the lists in
  // force now and after the last cycle (the cycle a list goes off still moves by the old one).
  void check_hli(std::size_t i) {
    const plc::hli::HLI_AX& unit = *kernel.gpAx()[i];
    if (const char* broken =
            fuzz::broken_hli_unit(unit, std::span<const int>(ids.data(), axes.size()))) {
      fuzz::fail(broken);
    }
    const plc::hli::HLI_AX_COUPLING_STATE& state = unit.lr_mc_control.axis_coupling.state_r;
    double velocity = 0.0;
    double acceleration = 0.0;
    double last_velocity = 0.0;
    double last_acceleration = 0.0;
    bool steps = false;
    bound_list(i, state.desc, velocity, acceleration, steps);
    bound_list(i, hli_last[i], last_velocity, last_acceleration, steps);
    velocity = std::max(velocity, last_velocity);
    acceleration = std::max(acceleration, last_acceleration);
    if (fuzz::g_trace) {
      const fb::HLI_AxisCoupling& b = programs[i].hli;
      std::fprintf(
          stderr,
          "  [%d] axis %zu hli: active %d error_r %u block %d%d%d 0x%X bound v %.9g a %.9g\n",
          cycles, i, state.active_r ? 1 : 0, state.error_r, b.Busy ? 1 : 0, b.Done ? 1 : 0,
          b.Error ? 1 : 0, b.ErrorID, velocity, acceleration);
    }
    watches[i].hli(state.active_r, velocity, acceleration, steps);
    hli_last[i] = state.desc;
  }
  // `steps`: set when a source of the list may step its program velocity, which the target's
  // drive then follows: fed external set values (B8). (A source whose drive goes off under its
  // moving program does not step its targets: they leave their lists and brake, K26.)
  void bound_list(std::size_t target,
                  const std::array<plc::hli::HLI_AX_COUPLING_STATE_DESC, 8>& list, double& velocity,
                  double& acceleration, bool& steps) const {
    constexpr double kUnbounded = std::numeric_limits<double>::infinity();
    if (programs[target].gear_slave) velocity = acceleration = kUnbounded;
    for (const plc::hli::HLI_AX_COUPLING_STATE_DESC& e : list) {
      if (e.mode == plc::hli::HLI_AXIS_COUPLING_INACTIVE) break;
      if (e.mode == plc::hli::HLI_AXIS_COUPLING_ZERO) continue;
      const double k =
          e.mode == plc::hli::HLI_AXIS_COUPLING_FRACT ? programs[target].hli_fract : 1.0;
      if (k == 0.0) continue;
      const std::size_t s = static_cast<std::size_t>(
          std::find(ids.begin(), ids.begin() + static_cast<std::ptrdiff_t>(axes.size()), e.ax_nr) -
          ids.begin());
      if (s >= axes.size() || programs[s].gear_slave) {
        velocity = acceleration = kUnbounded;
        continue;
      }
      steps = steps || watches[s].may_step();
      velocity += k * watches[s].velocity_limit();
      acceleration += k * watches[s].acceleration_limit();
    }
  }

  // Between cycles, as a test or sample would: a push is taken (from the next cycle on) or
  // refused with one of its documented codes; either way no image changes now.
  void push_by_hand(std::size_t index, double velocity) {
    std::array<plc::NCTOPLC_AXIS_REF, kMaxAxes> before{};
    for (std::size_t i = 0; i < axes.size(); ++i)
      std::memcpy(&before[i], &axes[i]->NcToPlc, sizeof before[i]);  // padding too
    const plc::ErrorCode code = kernel.push_by_hand(index, velocity);
    if (fuzz::g_trace) std::fprintf(stderr, " push %zu -> 0x%X", index, plc::to_id(code));
    switch (code) {
      case plc::ErrorCode::kNone:
      case plc::ErrorCode::kInvalidAxisReference:
      case plc::ErrorCode::kParameterNotFinite:
      case plc::ErrorCode::kVelocityNotAllowed:
      case plc::ErrorCode::kAxisKindNotAllowed:
      case plc::ErrorCode::kPushByHandControllerEnabled:
        break;
      default:
        fuzz::fail("push_by_hand answered a code it does not document");
    }
    for (std::size_t i = 0; i < axes.size(); ++i) {
      if (std::memcmp(&before[i], &axes[i]->NcToPlc, sizeof before[i]) != 0) {
        fuzz::fail("push_by_hand changed an axis image");
      }
    }
  }
};

nc::KernelConfig kernel_config(uint8_t b) {
  static constexpr std::array<double, 4> kCycles{0.001, 0.002, 0.0005, 0.004};
  return nc::KernelConfig{kCycles[b % kCycles.size()]};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  fuzz::g_trace = std::getenv("FUZZ_TRACE") != nullptr;
  fuzz::ByteReader in(data, size);
  const uint8_t first = in.byte();
  const bool features = (first & kFeatureProgram) != 0;
  const bool hli = features && (first & kHliProgram) != 0;
  Program p{nc::Kernel(kernel_config(first)),
            {},
            {},
            {},
            {},
            {},
            0,
            features || (first & kCouplingProgram) != 0,
            features};
  const std::size_t n_axes = 1 + in.below(kMaxAxes);
  p.hli = hli;
  p.programs.resize(n_axes);
  for (std::size_t i = 0; i < n_axes; ++i) {
    nc::AxisConfig config = axis_config(i, in.byte());
    if (features) feature_config(config, in.byte(), in);
    if (hli) hli_config(config, i, in.byte(), in);
    p.axes.push_back(&p.kernel.add_axis(config));
    p.ids[i] = p.kernel.config(config.name).id;
    p.watches.emplace_back(config, p.kernel.cycle_time());
    p.names.push_back(config.name);
    p.two_speed_images.push_back(
        config.kind == nc::AxisKind::kTwoSpeed ? &p.kernel.two_speed_output(config.name) : nullptr);
    AxisProgram& a = p.programs[i];
    a.power.Enable = a.power.Enable_Positive = a.power.Enable_Negative = true;
    a.status.Enable = a.actual_position.Enable = a.axis_error.Enable = true;
  }

  while (!in.empty() && p.cycles < kMaxCycles) {
    AxisProgram& a = p.programs[in.below(n_axes)];
    const std::size_t axis_index = static_cast<std::size_t>(&a - p.programs.data());
    plc::AXIS_REF& axis = *p.axes[axis_index];
    fuzz::AxisWatch& watch = p.watches[axis_index];
    const std::size_t op = in.below(
        hli ? kHliOps : (features ? kFeatureOps : (p.coupling ? kCouplingOps : kPlainOps)));
    if (fuzz::g_trace) std::fprintf(stderr, "\nop %zu axis %zu:", op, axis_index);
    switch (op) {
      case 0:
      case 1:
      case 2:
      case 3:
        edit_execute_block(a, watch, in);
        break;
      case 4:
        a.power.Enable = in.flag();
        a.power.Enable_Positive = in.flag();
        a.power.Enable_Negative = in.flag();
        if (in.flag()) a.power.Override = in.number();
        break;
      case 5:
        a.called |= kCalledSetOverride;
        a.set_override.Enable = in.flag();
        a.set_override.VelFactor = in.number();
        break;
      case 6:
        a.feeding = in.flag() || a.feeding;
        a.feed_p = in.number();
        a.feed_v = in.number();
        a.feed_a = in.number();
        {
          const uint8_t d = in.byte();
          a.feed_direction = d < 240 ? static_cast<int32_t>(d % 3) - 1 : static_cast<int8_t>(d);
        }
        break;
      case 7:
        // Raw writes a PLC program may make: any override word, any cyclic coupling factor.
        if (in.flag()) axis.PlcToNc.Override = static_cast<uint32_t>(in.u16()) * 32U;
        axis.PlcToNc.GearRatio1 = in.number();
        break;
      case 8: {
        // A burst: more rising edges in one cycle than the mailbox holds.
        const std::size_t k = 1 + in.below(kBurst);
        const double distance = in.number();
        const double velocity = in.number();
        for (std::size_t i = 0; i < kBurst; ++i) {
          a.burst[i].Distance = distance;
          a.burst[i].Velocity = velocity;
          a.burst[i].Execute = i < k;
        }
        a.bursts = std::max(a.bursts, k);
        break;
      }
      case 9:
        // Faults: a feed enable or the controller enable lost (or back).
        switch (in.below(3)) {
          case 0:
            a.power.Enable_Positive = !a.power.Enable_Positive;
            break;
          case 1:
            a.power.Enable_Negative = !a.power.Enable_Negative;
            break;
          default:
            a.power.Enable = !a.power.Enable;
            break;
        }
        break;
      case 12:
        // Coupling programs: this axis as slave of any axis (itself too), any ratio.
        a.gear_in.RatioNumerator = in.number();
        a.gear_in.RatioDenominator = in.flag() ? in.u16() : 1;
        a.gear_master = in.below(n_axes);
        a.gear_in.Execute = !a.gear_in.Execute;
        a.called |= kCalledGearIn;
        a.gear_slave = true;
        break;
      case 13:
        a.called |= kCalledGearOut;
        a.gear_out.Execute = !a.gear_out.Execute;
        break;
      case 14:
        edit_home(a, in);
        break;
      case 15:
        edit_gear_dyn(a, n_axes, in);
        break;
      case 16: {
        // Read in this order on every compiler (the order of a call's arguments is not
        // specified: GCC read the velocity first, so its replay decoded other programs).
        const std::size_t index = in.below(n_axes + 1);  // n_axes: an unknown axis
        const double velocity = in.number();
        p.push_by_hand(index, velocity);
        break;
      }
      case 17:
      case 18:
        if (hli) {
          edit_hli(a, p.ids, n_axes, in);
        } else {
          p.run(1 + in.below(64));  // op 17 of a feature program
        }
        break;
      case 19:
        p.raw_hli(a, axis_index, in);
        break;
      case 20:
        p.query_hli(in);
        break;
      default:
        p.run(1 + in.below(64));
        break;
    }
  }
  for (int i = 0; i < 3; ++i)
    p.tick();  // the last commands get their answers
  return 0;
}
