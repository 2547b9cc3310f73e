// Warnings are latched bits with one shown code (issue 8 item 3, docs/behaviour.md "Errors and
// reset"): NcToPlc.Warning shows the last warning raised while it holds; when it clears, a
// warning still latched shows again instead of 0; Reset clears them all.
#include <catch2/catch.hpp>

#include "kernel_harness.hpp"

using plc::CommandState;

TEST_CASE("a cleared warning uncovers one still latched; Reset clears both", "[kernel][warnings]") {
  kt::Harness h;  // encoder increment 1e-4 mm
  const uint16_t tiny = h.post(kt::move_relative(0.5e-4, 1000.0));
  h.cycles(1);
  REQUIRE(h.state_of(tiny) == CommandState::kDone);
  CHECK(h.x->NcToPlc.Warning == 0x4224);  // shorter than one increment

  kt::set_override(*h.x, 150.0);  // above 100 %: not taken
  h.cycles(1);
  CHECK(h.x->NcToPlc.Warning == 0x4238);  // the last one raised shows

  kt::set_override(*h.x, 100.0);  // valid again: 0x4238 clears, 0x4224 is still latched
  h.cycles(1);
  CHECK(h.x->NcToPlc.Warning == 0x4224);

  const uint16_t reset = h.post(kt::simple(plc::CommandType::kReset));
  h.cycles(2);
  CHECK(h.state_of(reset) == CommandState::kDone);
  CHECK(h.x->NcToPlc.Warning == 0);
}
