// MC_GearInDyn on the NC (SPEC C6, issue 10): every refused cyclic coupling is answered kError
// with its code and the NC→PLC images of all axes stay bit-identical to a twin kernel that never
// saw it (50 cycles); an AccBound below the stability bound max|factor| × max(A+, A-) of the
// master (through a cascade: |factor| × its master's) is accepted with warning 0x4F80, also for a
// later factor; a GearRatio1 of 0, NaN, inf or above 1e6 while coupled is not taken (the factor
// stays) and shows warning 0x4F81; MC_Reset clears the warnings.
#include <catch2/catch.hpp>

#include <string>

#include "gear_dyn_rig.hpp"
#include "refusal_check.hpp"

namespace {

using E = plc::ErrorCode;

struct Case {
  std::string what;
  std::size_t axis;
  plc::Command command;
  E expected;
};

}  // namespace

TEST_CASE("refused cyclic couplings change nothing and carry their codes", "[gear][cyclic]") {
  // Axes: 0 master at rest, 1 slave candidate, 2 moving, 3 encoder, 4 follows 5 (linear).
  gr::TwinRigs t(6, {3});
  t.both(4, gr::gear_in(5, 0.5));
  t.cycles(1);
  t.both(2, kt::move_velocity(1000.0, 1));
  t.cycles(400);
  const Case cases[] = {
      {"factor 0", 1, gd::gear_in_dyn(0, 0.0, 8000.0), E::kCouplingFactorZero},
      {"factor NaN", 1, gd::gear_in_dyn(0, kt::kNaN, 8000.0), E::kParameterNotFinite},
      {"factor inf", 1, gd::gear_in_dyn(0, kt::kInf, 8000.0), E::kParameterNotFinite},
      {"factor 2e6", 1, gd::gear_in_dyn(0, 2e6, 8000.0), E::kGearRatioOutOfRange},
      {"AccBound 0", 1, gd::gear_in_dyn(0, 1.0, 0.0), E::kAccelerationNotAllowed},
      {"AccBound -1", 1, gd::gear_in_dyn(0, 1.0, -1.0), E::kAccelerationNotAllowed},
      {"AccBound NaN", 1, gd::gear_in_dyn(0, 1.0, kt::kNaN), E::kParameterNotFinite},
      {"AccBound inf", 1, gd::gear_in_dyn(0, 1.0, kt::kInf), E::kParameterNotFinite},
      {"master unknown", 1, gd::gear_in_dyn(6, 1.0, 8000.0), E::kInvalidAxisReference},
      {"master = slave", 1, gd::gear_in_dyn(1, 1.0, 8000.0), E::kCouplingLoop},
      {"encoder axis as slave", 3, gd::gear_in_dyn(0, 1.0, 8000.0), E::kAxisKindNotAllowed},
      {"master moving", 1, gd::gear_in_dyn(2, 1.0, 8000.0), E::kBusyWhileCoupling},
      {"loop: 5 to its slave 4", 5, gd::gear_in_dyn(4, 1.0, 8000.0), E::kCouplingLoop},
      {"slave already coupled", 4, gd::gear_in_dyn(0, 1.0, 8000.0), E::kFunctionNotAllowed},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    REQUIRE(t.same());
    t.probe.at(c.axis).PlcToNc.GearRatio1 = c.command.ratio;  // as the block writes it
    t.reference.at(c.axis).PlcToNc.GearRatio1 = c.command.ratio;
    const uint16_t n = t.probe.post(c.axis, c.command);
    t.cycles(1);
    const plc::CommandAnswer a = t.probe.answer(c.axis, n);
    CHECK(a.state == plc::CommandState::kError);
    CHECK(a.error_code == plc::to_id(c.expected));
    for (int i = 0; i < 50; ++i) {
      REQUIRE(t.same());
      t.cycles(1);
    }
    t.probe.at(c.axis).PlcToNc.GearRatio1 = 1.0;
    t.reference.at(c.axis).PlcToNc.GearRatio1 = 1.0;
  }
  CHECK(t.probe.at(1).NcToPlc.CoupleState == 0U);
}

TEST_CASE("AccBound below the stability bound: accepted with warning 0x4F80", "[gear][cyclic]") {
  gr::Rig rig(2);
  REQUIRE(gd::couple(rig, 1, 0, 1.0, 4000.0).state == plc::CommandState::kActive);
  CHECK(rig.at(1).NcToPlc.Warning == 0x4F80U);  // 4000 < 1.0 × 5000
  CHECK(rig.at(1).NcToPlc.ErrorCode == 0U);
  CHECK(rig.at(1).NcToPlc.CoupleState == 3U);
  // The master accelerates at 5000: the slave follows it at 1.0 × 5000, above the bound (the
  // user's choice); the factor still never moves away from the commanded one.
  rig.post(0, kt::move_velocity(1000.0, 1));
  rig.at(1).PlcToNc.GearRatio1 = 1.2;
  for (int i = 0; i < 1000; ++i) {
    const double f0 = rig.at(1).NcToPlc.GearRatio;
    rig.kernel.cycle();
    REQUIRE(rig.at(1).NcToPlc.GearRatio >= f0);
    REQUIRE(rig.at(1).NcToPlc.GearRatio <= 1.2);
  }
  CHECK(rig.at(1).NcToPlc.GearRatio == 1.2);

  // Reset clears it; a later factor above AccBound / 5000 raises it again.
  const uint16_t reset = rig.post(1, kt::simple(plc::CommandType::kReset));
  rig.cycles(1);
  REQUIRE(rig.answer(1, reset).state == plc::CommandState::kDone);
  CHECK(rig.at(1).NcToPlc.Warning == 0U);
  rig.at(1).PlcToNc.GearRatio1 = 0.5;
  rig.cycles(1);
  CHECK(rig.at(1).NcToPlc.Warning == 0U);  // 0.5 × 5000 <= 4000
  rig.at(1).PlcToNc.GearRatio1 = 0.9;
  rig.cycles(1);
  CHECK(rig.at(1).NcToPlc.Warning == 0x4F80U);
}

TEST_CASE("the stability bound through a cascade: |factor| × the master's own bound",
          "[gear][cyclic]") {
  gr::Rig rig(4);
  REQUIRE(rig.couple(1, 0, 2.0).state == plc::CommandState::kReached);  // 1 moves at 2 × A
  REQUIRE(gd::couple(rig, 2, 1, 1.0, 9999.0).state == plc::CommandState::kActive);
  CHECK(rig.at(2).NcToPlc.Warning == 0x4F80U);  // 9999 < 1 × 2 × 5000
  REQUIRE(gd::couple(rig, 3, 1, 1.0, 10000.0).state == plc::CommandState::kActive);
  CHECK(rig.at(3).NcToPlc.Warning == 0U);
  CHECK(rig.at(1).NcToPlc.CoupleState == 2U);
}

TEST_CASE("GearRatio1 0, NaN, inf or above 1e6 while coupled: not taken, warning 0x4F81",
          "[gear][cyclic]") {
  for (const double bad : {0.0, kt::kNaN, kt::kInf, -kt::kInf, 1.5e6}) {
    INFO("GearRatio1 " << bad);
    gr::Rig rig(2);
    REQUIRE(gd::couple(rig, 1, 0, 0.5, 8000.0).state == plc::CommandState::kActive);
    rig.post(0, kt::move_velocity(1000.0, 1));
    rig.cycles(400);
    rig.at(1).PlcToNc.GearRatio1 = bad;
    rig.cycles(100);
    CHECK(rig.at(1).NcToPlc.GearRatio == 0.5);
    CHECK(rig.at(1).NcToPlc.Warning == 0x4F81U);
    CHECK(rig.at(1).NcToPlc.ErrorCode == 0U);
    CHECK(rig.at(1).NcToPlc.SetVelo == 500.0);
    // A good one is taken again.
    rig.at(1).PlcToNc.GearRatio1 = 0.75;
    rig.cycles(100);
    CHECK(rig.at(1).NcToPlc.GearRatio == 0.75);
  }
}
