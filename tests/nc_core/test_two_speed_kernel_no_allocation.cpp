// No allocation per cycle for a two-speed axis in the kernel (brief: real-time discipline): a
// counting operator new over 40 000 cycles of blocks and kernel — positionings both ways with
// looping, MC_MoveRelative, a stop and a halt, override changes, a refused command, a disable
// during a move with its error and MC_Reset — counts 0. Runs only in the plain build.
#include <catch2/catch.hpp>

#include "counting_allocator.hpp"
#include "kernel_harness.hpp"
#include "two_speed_kernel_rig.hpp"

TEST_CASE("a two-speed axis in the kernel allocates nothing per cycle",
          "[no_allocation][two_speed][kernel]") {
  nc::AxisConfig c = ts::issue_axis();
  c.looping_distance_enabled = true;
  tsk::Rig rig(c);
  rig.record = false;
  rig.move.Velocity = 2000.0;
  const plc::Command refused = kt::move_velocity(100.0, 1);
  int moves_done = 0;  // cycles the blocks show Done / an error: the run did what it says
  int stops_done = 0;
  int errors = 0;
  rig.relative.Distance = 200.0;
  rig.relative.Velocity = 2000.0;
  rig.each = [&](tsk::Rig& r) {
    const uint64_t k = r.kernel.cycle_count() % 10000;
    r.move.Execute = k >= 10 && k < 6000;
    r.move.Position = (r.kernel.cycle_count() / 10000) % 2 == 0 ? 1500.0 : 0.0;
    r.power.Override = k > 600 && k < 900 ? 40.0 : (k >= 900 && k < 1200 ? 0.0 : 100.0);
    r.stop.Execute = k >= 6100 && k < 6600;  // at rest: Done at once, then the lock ends
    r.relative.Execute = k >= 6700 && k < 7500;
    r.power.Enable = k < 6800 || k >= 6850;  // during the relative move: 0x4356
    r.reset.Execute = k >= 6900 && k < 7000;
    r.halt.Execute = k >= 7100 && k < 7200;
    if (k == 100) (void)r.axis.Mailbox.post(refused);
    moves_done += r.move.Done ? 1 : 0;
    stops_done += r.stop.Done || r.halt.Done ? 1 : 0;
    errors += r.axis.NcToPlc.ErrorCode != 0 ? 1 : 0;
  };
  rig.cycle();
  ca::g_allocations = 0;
  ca::g_counting = true;
  for (int i = 0; i < 40000; ++i)
    rig.cycle();
  ca::g_counting = false;
  CHECK(ca::g_allocations == 0);
  CHECK(moves_done > 0);
  CHECK(stops_done > 0);
  CHECK(errors > 0);
  CHECK(rig.kernel.cycle_count() == 40002U);
}
