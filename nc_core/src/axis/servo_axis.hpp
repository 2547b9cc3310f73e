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

#include "axis/axis_core.hpp"
#include "axis/steady_lane.hpp"
#include "nc_core/axis_snapshot.hpp"
#include "nc_core/coupling_graph.hpp"
#include "plc_interface/axis_ref.hpp"

namespace nc::detail {

class ServoAxis;

// What the commands phase of one axis may reach of the others (MC_GearIn / MC_GearOut): the
// kernel's axes by index and its coupling graph. The kernel builds it for each cycle.
struct CouplingPort {
  std::span<const std::unique_ptr<ServoAxis>> axes;
  CouplingGraph& graph;
};

class ServoAxis : private AxisCore {
 public:
  // `scratch`: the kernel's planning profile, shared by all its axes (one plans at a time).
  ServoAxis(const AxisConfig& config, double cycle_time, std::size_t index, Profile& scratch);

  // The state the feature classes work on (axis_core.hpp); the coupling reaches other axes' too,
  // the HLI phase reads an axis's error, errors_raised_ and enables before phase (c).
  AxisCore& core() noexcept { return *this; }
  const AxisCore& core() const noexcept { return *this; }
  plc::AXIS_REF& ref() noexcept { return channel_.ref(); }
  const plc::AXIS_REF& ref() const noexcept { return channel_.ref(); }
  const AxisConfig& config() const noexcept { return config_; }

  // The phases of one NC cycle (steps a … f of docs/architecture.md "One tick"); the kernel
  // calls each for every axis before the next. The snapshot is what other axes may read.
  void phase_commands(CouplingPort& port) noexcept;  // (a)
  // (b); `snapshots`: every axis's, a slave reads its master's (computed before it this cycle).
  // `shared`: other axes read this cycle's set values (false: no axis reads another).
  void phase_set_values(AxisSnapshot& snapshot, std::span<const AxisSnapshot> snapshots,
                        bool shared = true) noexcept;
  // (c) HLI coupling (SPEC D3), called only while the kernel's coupling stage is engaged: the
  // set values phase (d) controls to this cycle (NcToPlc.SetPos; without a call they are the
  // program's set values), and `stop` != kNone raises that axis error (program on its emergency
  // ramp). The windows and software limits stay in program coordinates (actual − (d − q)).
  // `role`: the axis's HLI part (a list in force: slave; a source of another axis's list:
  // master), kept until the next call, for CoupleState and the refusal of external setpoints.
  void phase_drive_command(const KinematicState& drive, ErrorCode stop,
                           plc::CoupleState role) noexcept;
  void phase_drive(AxisSnapshot& snapshot) noexcept;  // (d)
  // The axis as the cycle left it into `snapshot` (all but the group reaction and a C8 master's
  // filtered values, which its phases write): Kernel::snapshot(). A servo axis's phases write the
  // snapshot only when `shared` (some axis reads another this cycle).
  void fill_snapshot(AxisSnapshot& snapshot) const noexcept;
  // (e); `shared`: the group reactions read the snapshot's errors and enables this cycle.
  void phase_monitors(AxisSnapshot& snapshot, bool shared = true) noexcept;
  void phase_publish(uint64_t cycle_counter) noexcept;  // (f)
  // Phases (b), (d), (e), (f) one after the other, for a kernel in which no axis reads another
  // (no coupling, HLI stage not engaged): the same as the kernel's phase loops.
  void run_alone(AxisSnapshot& snapshot, std::span<const AxisSnapshot> snapshots,
                 uint64_t cycle_counter) noexcept {
    phase_set_values(snapshot, snapshots, false);
    phase_drive(snapshot);
    phase_monitors(snapshot, false);
    phase_publish(cycle_counter);
  }
  // The kernel's loop while no axis reads another (no coupling, no coupling command waiting, HLI
  // stage not engaged): phase (a), then run_alone()'s phases, of each axis before the next one.
  // `snapshots`: every axis's, by index.
  static void run_cycles_alone(std::span<const std::unique_ptr<ServoAxis>> axes,
                               std::span<AxisSnapshot> snapshots, CouplingPort& port,
                               uint64_t cycle_counter) noexcept;
};

// Asks the CPU for the cache lines from `from` to `from + bytes` (a hint: no effect on a value).
// Always inline: GCC takes a function that only prefetches for one without effect and drops
// calls to it.
[[gnu::always_inline]] inline void prefetch_lines(const void* from, std::size_t bytes) noexcept {
  const char* p = static_cast<const char*>(from);
  for (std::size_t k = 0; k < bytes; k += 64)
    __builtin_prefetch(p + k);
}

// The kernel's loop asks for an axis's lines in two steps (docs/performance.md "Tenth pass"):
// first those at fixed places, then, some axes later, those the first ones point to.
//
// The lines at fixed places that a cycle in the steady lane reads (axis_core.hpp): the hot
// members up to the C7 delay's flag, the stack's first line, the channel's first four (PlcToNc,
// NcToPlc and the mailbox's count) and the job's first two (its kind and override, the table
// with its horizon, the profile's header with its cursor).
[[gnu::always_inline]] inline void prefetch_axis_lines(const ServoAxis& axis) noexcept {
  const AxisCore& a = axis.core();
  const auto hot = static_cast<std::size_t>(reinterpret_cast<const char*>(&a.propagation_) -
                                            reinterpret_cast<const char*>(&a));
  prefetch_lines(&a, hot + 1);
  prefetch_lines(&a.stack_, 1);
  prefetch_lines(&a.channel_, 256);
  prefetch_lines(&a.job_, 128);
}

// The lines prefetch_axis_lines() points to, read from them: the segment of the profile's cursor
// (the lane's sample) and the drive's dead-time slot; and, for an axis whose next cycle is not
// the lane's (no horizon), what the full bodies read beyond it: the job's next three lines (the
// first segments) and the snapshot's group reaction, which the lane does not write.
[[gnu::always_inline]] inline void prefetch_cycle_data(const ServoAxis& axis,
                                                       const AxisSnapshot& snapshot) noexcept {
  const AxisCore& a = axis.core();
  SteadyLane::prefetch(a.job_.table);
  __builtin_prefetch(a.drive_.next_slot());
  if (!SteadyLane::next(a.job_.table)) {
    prefetch_lines(reinterpret_cast<const char*>(&a.job_) + 128, 192);
    __builtin_prefetch(&snapshot.group_reaction_due);
  }
}

}  // namespace nc::detail
