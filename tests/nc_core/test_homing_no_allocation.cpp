// No allocation per cycle with homing (brief; SPEC F): a counting operator new over a whole
// default homing on the simulated cam, a homing aborted by MC_Stop, MC_Direct and the
// calibration modes — 0 allocations. Runs only in the plain build.
#include <catch2/catch.hpp>

#include "counting_allocator.hpp"
#include "homing_rig.hpp"

TEST_CASE("homing allocates nothing per cycle", "[homing][no_allocation]") {
  kt::Harness h(kt::homing_axis());
  const plc::Command home = kt::home(plc::MC_DefaultHoming, 0.0);
  const plc::Command stop = kt::simple(plc::CommandType::kStop);
  const plc::Command release = kt::simple(plc::CommandType::kStopRelease);
  const plc::Command direct = kt::home(plc::MC_Direct, 250.0);
  const plc::Command force = kt::home(plc::MC_ForceCalibration);
  const plc::Command reset = kt::home(plc::MC_ResetCalibration);

  ca::g_allocations = 0;
  ca::g_counting = true;
  const uint16_t n = h.x->Mailbox.post(home);
  for (int i = 0; i < 5000 && h.x->Mailbox.answer(n).state != plc::CommandState::kDone; ++i)
    kt::cam_cycle(h);
  const bool done = h.x->Mailbox.answer(n).state == plc::CommandState::kDone;
  h.x->Mailbox.post(home);
  for (int i = 0; i < 300; ++i)
    kt::cam_cycle(h);
  h.x->Mailbox.post(stop);
  h.x->Mailbox.post(release);
  for (int i = 0; i < 300; ++i)
    kt::cam_cycle(h);
  h.x->Mailbox.post(direct);
  h.x->Mailbox.post(reset);
  h.x->Mailbox.post(force);
  for (int i = 0; i < 10; ++i)
    kt::cam_cycle(h);
  ca::g_counting = false;

  CHECK(ca::g_allocations == 0);
  CHECK(done);
  CHECK(kt::bit(*h.x, plc::kStateHomed));
  CHECK(h.x->NcToPlc.ErrorCode == 0);
}
