// No allocation per cycle when a default homing takes over a hard-accelerating move with its
// larger jerk and is itself aborted by a move, MC_Halt and the error ramp (fuzz finding K8,
// docs/behaviour.md "Homing"): a counting operator new over all of it — 0 allocations. Runs
// only in the plain build.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "counting_allocator.hpp"
#include "homing_rig.hpp"

TEST_CASE("a homing aborting and aborted in motion allocates nothing per cycle",
          "[homing][no_allocation]") {
  kt::Harness h(kt::homing_axis());
  const plc::Command hard = kt::move_absolute(100000.0, 2200.0, 20000.0, 20000.0, 1e6);
  const plc::Command home = kt::home(plc::MC_DefaultHoming);
  const plc::Command velocity = kt::move_velocity(500.0, 1);
  const plc::Command halt = kt::simple(plc::CommandType::kHalt);

  ca::g_allocations = 0;
  ca::g_counting = true;
  double peak = 0.0;
  const auto run = [&](int n) {
    for (int i = 0; i < n; ++i) {
      kt::cam_cycle(h);
      peak = std::max(peak, std::abs(h.x->NcToPlc.SetVelo));
    }
  };
  h.x->Mailbox.post(hard);
  run(40);
  h.x->Mailbox.post(home);  // takes over the move's J 1e6
  run(2);
  h.x->Mailbox.post(velocity);  // takes over the homing's J 1e6
  run(60);
  h.x->Mailbox.post(home);
  run(2);
  h.x->Mailbox.post(halt);  // the homing's deceleration and jerk
  run(1000);
  h.x->Mailbox.post(hard);
  run(40);
  h.x->Mailbox.post(home);
  run(2);
  kt::set_enables(*h.x, true, false, true);  // the error ramp, with the homing's jerk
  run(1000);
  ca::g_counting = false;

  CHECK(ca::g_allocations == 0);
  CHECK(peak <= 2200.0);
  CHECK(h.x->NcToPlc.ErrorCode == plc::to_id(plc::ErrorCode::kFeedEnablePlusMissing));
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
}
