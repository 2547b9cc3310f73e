// Compensation is a linear path control (seed 000 §2.5 general note 3): it follows every change of
// the basic dynamics. With override 0 the basic motion rests on its path, the compensation's
// velocity is scaled down to 0 with it (SPEC B7: min(1, v / VP)) while its time T runs on, so less
// than D is done (seed 000 §2.5 start-parameter note 3) — warning 0x4243 — and the end of the
// positioning is the target plus what was done.
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::ErrorCode;

TEST_CASE("override 0 during the compensation gives less than D", "[compensation][override]") {
  kt::Harness h;
  const uint16_t move = h.post(kt::move_absolute(10000.0, 2000.0));
  REQUIRE(h.cycles_until(
              [&] { return h.x->NcToPlc.SetVelo == 2000.0 && h.x->NcToPlc.SetAcc == 0.0; }) > 0);
  const uint16_t comp = h.post(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
  h.cycles(1000);
  const double done_before = h.x->NcToPlc.CompensationDistance;
  h.x->PlcToNc.Override = 0;
  // T = 2.5 s ends while the basic motion rests: the compensation ends with less than D.
  const int left = h.cycles_until([&] { return h.state_of(comp) != CommandState::kActive; });
  CHECK(left == 1500);
  CHECK(h.state_of(comp) == CommandState::kDone);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  const double done = h.x->NcToPlc.CompensationDistance;
  // Peak 106.85 mm/s: while the basic motion brakes (well under 1 s) at most that much more.
  CHECK(done > done_before);
  CHECK(done < done_before + 106.85);
  CHECK(done < 250.0 - 50.0);
  CHECK(h.x->NcToPlc.Warning == kt::id(ErrorCode::kCompensationIncomplete));
  const double resting = h.x->NcToPlc.SetPos;
  h.cycles(200);
  CHECK(h.x->NcToPlc.SetPos == resting);  // nothing moves at override 0
  h.x->PlcToNc.Override = plc::kOverrideFull;
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == Approx(10000.0 + done).epsilon(1e-14));
}
