// BufferMode behind a running MC_Home (SPEC F, Tc2_MC2: MC_Buffered starts when the running
// command is done): a buffered move posted while the default homing runs waits (kBuffered) and
// takes over in the NC cycle after the homing's Done; the homing is not aborted. A blending mode
// acts as MC_Buffered there (a homing ends at rest: nothing to pass a target with).
#include <catch2/catch.hpp>

#include <cmath>

#include "homing_rig.hpp"

using plc::CommandState;

namespace {

// Homes the axis (cam 100 … 110 mm, Position 0) with a move to 50 mm at 500 mm/s posted with
// `mode` 10 cycles into the homing; checks both answers cycle by cycle.
void check_waits_for_homing(int32_t mode) {
  kt::Harness h(kt::homing_axis());
  const uint16_t home = h.post(kt::home(plc::MC_DefaultHoming, 0.0));
  for (int i = 0; i < 10; ++i)
    kt::cam_cycle(h);
  REQUIRE(h.state_of(home) == CommandState::kActive);
  plc::Command move = kt::move_absolute(50.0, 500.0);
  move.buffer_mode = mode;
  const uint16_t next = h.post(move);
  int cycles = 0;
  while (h.state_of(home) == CommandState::kActive && cycles < 200000) {
    kt::cam_cycle(h);
    ++cycles;
    REQUIRE(h.state_of(next) == CommandState::kBuffered);
    REQUIRE(h.x->NcToPlc.CmdNo == home);
  }
  // The homing ran to its end: Done, homed, at rest near the new reference 0.
  REQUIRE(h.state_of(home) == CommandState::kDone);
  CHECK(plc::test_bit(h.x->NcToPlc.StateDWord, plc::kStateHomed));
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  CHECK(std::abs(h.x->NcToPlc.SetPos) < 1.0);
  // The next NC cycle takes the move.
  kt::cam_cycle(h);
  CHECK(h.state_of(next) == CommandState::kActive);
  CHECK(h.x->NcToPlc.CmdNo == next);
  for (int i = 0; i < 5000 && h.state_of(next) != CommandState::kDone; ++i)
    kt::cam_cycle(h);
  CHECK(h.state_of(next) == CommandState::kDone);
  CHECK(h.x->NcToPlc.SetPos == 50.0);
}

}  // namespace

TEST_CASE("MC_Buffered behind MC_Home waits for the homing's Done", "[buffer][homing]") {
  check_waits_for_homing(plc::MC_Buffered);
}

TEST_CASE("A blending mode behind MC_Home acts as MC_Buffered", "[buffer][homing]") {
  check_waits_for_homing(plc::MC_BlendingHigh);
  check_waits_for_homing(plc::MC_BlendingLow);
}
