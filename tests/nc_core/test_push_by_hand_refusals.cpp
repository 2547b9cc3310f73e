// Kernel::push_by_hand (SPEC C8, the simulated drive moved by hand; docs/behaviour.md "Error
// propagation and actual-value coupling"): it moves a disabled continuous axis at the given
// velocity, without an error; every bad call is refused with its code and changes nothing (every
// axis's NC→PLC image the same as a twin kernel's that got no call).
#include <catch2/catch.hpp>

#include <limits>

#include "propagation_rig.hpp"

using plc::ErrorCode;

namespace {

struct Twins {
  pr::Group probe;
  pr::Group reference;
  static void tune(std::size_t i, nc::AxisConfig& c) {
    if (i == 2) c.kind = nc::AxisKind::kEncoder;
  }
  Twins() : probe(3, tune), reference(3, tune) {
    kt::set_enables(probe.at(1), false);
    kt::set_enables(reference.at(1), false);
    probe.cycles(1);
    reference.cycles(1);
  }
  bool same_after(int cycles) {
    probe.cycles(cycles);
    reference.cycles(cycles);
    for (std::size_t i = 0; i < 3; ++i) {
      if (!kt::same_image(probe.at(i).NcToPlc, reference.at(i).NcToPlc)) return false;
    }
    return true;
  }
};

}  // namespace

TEST_CASE("push_by_hand refuses bad calls with a code and changes nothing", "[by_hand]") {
  Twins t;
  const double inf = std::numeric_limits<double>::infinity();
  nc::Kernel& k = t.probe.kernel;
  CHECK(k.push_by_hand(3, 10.0) == ErrorCode::kInvalidAxisReference);
  CHECK(k.push_by_hand(SIZE_MAX, 10.0) == ErrorCode::kInvalidAxisReference);
  CHECK(k.push_by_hand(1, std::numeric_limits<double>::quiet_NaN()) ==
        ErrorCode::kParameterNotFinite);
  CHECK(k.push_by_hand(1, -inf) == ErrorCode::kParameterNotFinite);
  CHECK(k.push_by_hand(1, 2200.001) == ErrorCode::kVelocityNotAllowed);
  CHECK(k.push_by_hand(2, 10.0) == ErrorCode::kAxisKindNotAllowed);
  CHECK(k.push_by_hand(0, 10.0) == ErrorCode::kPushByHandControllerEnabled);
  CHECK(t.same_after(100));
  CHECK(plc::error_text(ErrorCode::kPushByHandControllerEnabled) ==
        "push by hand: the axis has its controller enable (the drive holds it)");
}

TEST_CASE("push_by_hand moves a disabled axis at the velocity given, without an error",
          "[by_hand]") {
  Twins t;
  REQUIRE(t.probe.kernel.push_by_hand(1, -2200.0) == ErrorCode::kNone);
  t.probe.cycles(500);
  CHECK(t.probe.at(1).NcToPlc.ActPos == Approx(-1100.0).margin(1e-4));
  CHECK(t.probe.at(1).NcToPlc.ActVelo == -2200.0);
  CHECK(t.probe.at(1).NcToPlc.SetPos == t.probe.at(1).NcToPlc.ActPos);  // set follows actual
  CHECK(t.probe.at(1).NcToPlc.ErrorCode == 0U);
  // The enable back: the push ends.
  kt::set_enables(t.probe.at(1), true);
  t.probe.cycles(10);
  CHECK(t.probe.at(1).NcToPlc.ActVelo == 0.0);
  kt::set_enables(t.probe.at(1), false);
  t.probe.cycles(10);
  CHECK(t.probe.at(1).NcToPlc.ActPos == Approx(-1100.0).margin(1e-4));
}
