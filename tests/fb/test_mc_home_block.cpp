// fb::MC_Home on a kernel (SPEC F, API.md): its inputs reach the NC (mode, Position, the default
// Position), bCalibrationCam is written into PlcToNc on every call, refusals show Error with the
// NC's code, and a buffer mode other than MC_Aborting is refused by the block itself.
#include <catch2/catch.hpp>

#include "fb/fb.hpp"
#include "kernel_harness.hpp"

namespace {

nc::AxisConfig unhomed() {
  nc::AxisConfig c = kt::seed_axis();
  c.homed_at_start = false;
  c.homing_reference_position = 7.0;
  return c;
}

// Calls the block once per NC cycle until it leaves Busy; the number of calls, -1 past `limit`.
int run(fb::MC_Home& home, kt::Harness& h, int limit = 100) {
  for (int i = 1; i <= limit; ++i) {
    home(*h.x);
    if (!home.Busy) return i;
    h.kernel.cycle();
  }
  return -1;
}

}  // namespace

TEST_CASE("MC_Home MC_Direct: Done, the position set, Homed", "[fb][mc_home]") {
  kt::Harness h(unhomed());
  fb::MC_Home home;
  home.Execute = true;
  home.HomingMode = fb::MC_Direct;
  home.Position = 250.0;
  REQUIRE(run(home, h) > 0);
  CHECK(home.Done);
  CHECK_FALSE(home.Error);
  CHECK(h.x->NcToPlc.ActPos == Approx(250.0).margin(1e-9));
  CHECK(kt::bit(*h.x, plc::kStateHomed));
}

TEST_CASE("MC_Home's default Position is DEFAULT_HOME_POSITION: the configured one",
          "[fb][mc_home]") {
  kt::Harness h(unhomed());
  fb::MC_Home home;
  CHECK(home.Position == fb::DEFAULT_HOME_POSITION);
  CHECK(home.HomingMode == fb::MC_DefaultHoming);
  home.Execute = true;
  home.HomingMode = fb::MC_Direct;
  REQUIRE(run(home, h) > 0);
  CHECK(home.Done);
  CHECK(h.x->NcToPlc.ActPos == Approx(7.0).margin(1e-9));
}

TEST_CASE("MC_Home shows the NC's refusal of an unsupported mode", "[fb][mc_home]") {
  kt::Harness h(unhomed());
  for (fb::MC_HomingMode mode : {fb::MC_AbsSwitch, fb::MC_LimitSwitch, fb::MC_RefPulse}) {
    fb::MC_Home home;
    home.Execute = true;
    home.HomingMode = mode;
    REQUIRE(run(home, h) > 0);
    CHECK(home.Error);
    CHECK(home.ErrorID == kt::id(plc::ErrorCode::kHomingModeNotSupported));
    CHECK_FALSE(home.Done);
  }
  CHECK(h.x->NcToPlc.ErrorCode == 0);
}

TEST_CASE("MC_Home refuses a buffer mode other than MC_Aborting itself", "[fb][mc_home]") {
  kt::Harness h(unhomed());
  fb::MC_Home home;
  home.Execute = true;
  home.BufferMode = fb::MC_Buffered;
  home(*h.x);
  CHECK(home.Error);
  CHECK(home.ErrorID == kt::id(plc::ErrorCode::kBufferModeNotSupported));
  CHECK(h.x->Mailbox.pending() == 0);
}

TEST_CASE("bCalibrationCam is written into ControlDWord bit 5 on every call", "[fb][mc_home]") {
  kt::Harness h(unhomed());
  fb::MC_Home home;  // Execute stays low: only the cam signal is passed on
  home.bCalibrationCam = true;
  home(*h.x);
  CHECK(plc::test_bit(h.x->PlcToNc.ControlDWord, plc::kControlHomingSensor));
  CHECK(plc::test_bit(h.x->PlcToNc.ControlDWord, plc::kControlEnable));  // the rest untouched
  home.bCalibrationCam = false;
  home(*h.x);
  CHECK_FALSE(plc::test_bit(h.x->PlcToNc.ControlDWord, plc::kControlHomingSensor));
  CHECK(h.x->Mailbox.pending() == 0);
}
