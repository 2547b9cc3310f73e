// An override above 1'000'000 (100 %) is not a valid value (SPEC B3): the NC does not take it —
// the last valid override stays in force, nothing about the motion changes, and NcToPlc.Warning
// shows 0x4238 (kOverrideNotAllowed) while the value is out of range.
#include <catch2/catch.hpp>

#include "kernel_harness.hpp"

using plc::CommandState;

namespace {

// The images without the warning.
bool same_but_warning(const kt::TwinKernels& t) {
  plc::NCTOPLC_AXIS_REF probe = t.probe.x->NcToPlc;
  probe.Warning = t.reference.x->NcToPlc.Warning;
  return kt::same_image(probe, t.reference.x->NcToPlc);
}

}  // namespace

TEST_CASE("an override above 100 % is refused with warning 0x4238 and the last value stays",
          "[override][refusals]") {
  kt::TwinKernels t;
  kt::set_override(*t.probe.x, 75.0);
  kt::set_override(*t.reference.x, 75.0);
  t.both(kt::move_absolute(5000.0, 2000.0));
  t.cycles(1000);
  for (uint32_t bad : {1'000'001u, 2'000'000u, 0xFFFFFFFFu}) {
    INFO("Override " << bad);
    t.probe.x->PlcToNc.Override = bad;
    for (int i = 0; i < 200; ++i) {
      t.cycles(1);
      REQUIRE(t.probe.x->NcToPlc.Warning == kt::id(plc::ErrorCode::kOverrideNotAllowed));
      REQUIRE(same_but_warning(t));
    }
  }
  CHECK(t.probe.x->NcToPlc.SetVelo == Approx(1500.0).margin(1e-9));
  kt::set_override(*t.probe.x, 75.0);
  t.cycles(1);
  CHECK(t.probe.x->NcToPlc.Warning == 0);
  CHECK(t.same());
  CHECK(t.probe.x->NcToPlc.ErrorCode == 0);
}

TEST_CASE("a start while the override is out of range runs with the last valid override",
          "[override][refusals]") {
  kt::TwinKernels t;
  kt::set_override(*t.probe.x, 40.0);
  kt::set_override(*t.reference.x, 40.0);
  t.cycles(1);
  t.probe.x->PlcToNc.Override = 1'500'000;
  const uint16_t move = t.both(kt::move_absolute(1000.0, 2000.0));
  for (int i = 0; i < 2000; ++i) {
    t.cycles(1);
    REQUIRE(t.probe.x->NcToPlc.Warning == kt::id(plc::ErrorCode::kOverrideNotAllowed));
    REQUIRE(same_but_warning(t));
  }
  CHECK(t.probe.state_of(move) == CommandState::kDone);
}
