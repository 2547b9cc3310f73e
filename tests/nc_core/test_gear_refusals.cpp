// SPEC C1, C3 and NC_ERROR_CODES.md: every refused coupling command, and every command a coupled
// slave refuses, is answered kError with its specific code, and the NC→PLC images of ALL axes stay
// bit-identical to a twin kernel that never saw the command (for 50 cycles after it).
// Axes: 0 master at rest, 1 slave candidate, 2 moving at 1000 mm/s, 3 encoder axis, 4 → 5 coupled
// (4 follows 5, factor 0.5), 6 → 4 coupled (a cascade 5 → 4 → 6), 7 controller disabled.
#include <catch2/catch.hpp>

#include <string>

#include "gear_rig.hpp"
#include "refusal_check.hpp"

namespace {

struct Case {
  std::string what;
  std::size_t axis;
  plc::Command command;
  plc::ErrorCode expected;
};

gr::TwinRigs make_twins() {
  gr::TwinRigs t(8, {3});
  kt::set_enables(t.probe.at(7), false);
  kt::set_enables(t.reference.at(7), false);
  t.both(4, gr::gear_in(5, 0.5));
  t.both(6, gr::gear_in(4, -2.0));
  t.cycles(1);
  t.both(2, kt::move_velocity(1000.0, 1));
  t.cycles(400);  // axis 2 at its level
  return t;
}

void expect_refused(gr::TwinRigs& t, const Case& c) {
  INFO(c.what);
  REQUIRE(t.same());
  const uint16_t n = t.probe.post(c.axis, c.command);
  t.cycles(1);
  const plc::CommandAnswer a = t.probe.answer(c.axis, n);
  CHECK(a.state == plc::CommandState::kError);
  CHECK(a.error_code == plc::to_id(c.expected));
  for (int i = 0; i < 50; ++i) {
    REQUIRE(t.same());
    t.cycles(1);
  }
  REQUIRE(t.same());
}

}  // namespace

TEST_CASE("refused couplings change nothing and carry their codes", "[gear][refusal]") {
  using E = plc::ErrorCode;
  gr::TwinRigs t = make_twins();
  REQUIRE(t.probe.at(4).NcToPlc.CoupleState == 2U);
  CHECK(plc::to_id(E::kCouplingLoop) == 0x4F0DU);  // ncsdk's own code (NC_ERROR_CODES.md style)
  const Case cases[] = {
      {"factor NaN", 1, gr::gear_in(0, kt::kNaN), E::kParameterNotFinite},
      {"factor inf", 1, gr::gear_in(0, kt::kInf), E::kParameterNotFinite},
      {"factor -inf", 1, gr::gear_in(0, -kt::kInf), E::kParameterNotFinite},
      {"factor 0", 1, gr::gear_in(0, 0.0), E::kCouplingFactorZero},
      {"factor 1.01e6", 1, gr::gear_in(0, 1.01e6), E::kGearRatioOutOfRange},
      {"factor -8.4e301 (fuzz K6)", 1, gr::gear_in(0, -8.4e301), E::kGearRatioOutOfRange},
      {"coupled slave: factor change to 2e6", 4, gr::gear_in(5, 2e6), E::kGearRatioOutOfRange},
      {"master index -1", 1, gr::gear_in(static_cast<std::size_t>(-1), 1.0),
       E::kInvalidAxisReference},
      {"master index 8 (unknown)", 1, gr::gear_in(8, 1.0), E::kInvalidAxisReference},
      {"master = slave", 1, gr::gear_in(1, 1.0), E::kCouplingLoop},
      {"encoder axis as slave", 3, gr::gear_in(0, 1.0), E::kAxisKindNotAllowed},
      {"loop of two: 5 to its slave 4", 5, gr::gear_in(4, 1.0), E::kCouplingLoop},
      {"loop of three: 5 to the end of its cascade 6", 5, gr::gear_in(6, 1.0), E::kCouplingLoop},
      {"master moving", 1, gr::gear_in(2, 1.0), E::kBusyWhileCoupling},
      {"slave moving", 2, gr::gear_in(0, 1.0), E::kBusyWhileCoupling},
      {"slave without controller enable", 7, gr::gear_in(0, 1.0),
       E::kSlaveNoControllerOrFeedEnable},
      {"coupled slave to another master", 4, gr::gear_in(0, 1.0), E::kFunctionNotAllowed},
      {"MC_GearOut on an uncoupled axis", 1, gr::gear_out(), E::kDecouplingNotAllowed},
      {"MC_GearOut on the head of a cascade", 5, gr::gear_out(), E::kDecouplingNotAllowed},
  };
  for (const Case& c : cases)
    expect_refused(t, c);
}

TEST_CASE(
    "a coupled slave refuses starts, stops, new positions and external setpoints with 0x424E, "
    "and a compensation while its master stands",
    "[gear][refusal]") {
  using E = plc::ErrorCode;
  using T = plc::CommandType;
  gr::TwinRigs t = make_twins();
  const Case cases[] = {
      {"MoveAbsolute", 4, kt::move_absolute(100.0, 1000.0), E::kFunctionNotAllowed},
      {"MoveRelative", 4, kt::move_relative(100.0, 1000.0), E::kFunctionNotAllowed},
      {"MoveModulo", 4, kt::move_modulo(100.0, 1000.0, 1), E::kFunctionNotAllowed},
      {"MoveVelocity", 6, kt::move_velocity(100.0, 1), E::kFunctionNotAllowed},
      {"Halt", 4, kt::simple(T::kHalt), E::kFunctionNotAllowed},
      {"Stop", 6, kt::simple(T::kStop), E::kFunctionNotAllowed},
      {"NewPos", 4, kt::new_pos(100.0), E::kFunctionNotAllowed},
      {"NewPosAndVelo", 4, kt::new_pos_and_velo(100.0, 500.0, 50.0), E::kFunctionNotAllowed},
      {"MoveSuperImposed, master at rest", 6,
       kt::move_superimposed(10.0, 100.0, 500.0, 500.0, 1000.0, 500.0), E::kFunctionNotAllowed},
      {"ExtSetPointGenEnable", 4, kt::ext_enable(0.0, 1), E::kFunctionNotAllowed},
  };
  for (const Case& c : cases)
    expect_refused(t, c);
}
