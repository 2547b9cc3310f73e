// What the kernel refuses around HLI coupling, each with its code and nothing disturbed:
// MC_ExtSetPointGenEnable on a coupled target (0x424E); a new list on an axis with external
// setpoint generation enabled (0x424E), in axis error (0x4F06) or without controller enable
// (0x4223). And how HLI-coupled axes publish NcToPlc.CoupleState, StateDWord bit 15 and
// AxisState, as slave axes do.
#include <catch2/catch.hpp>

#include "hli_kernel_rig.hpp"

using namespace hlik;

namespace {

const h::HLI_AX_COUPLING_STATE& state_of(Rig& rig, std::size_t i) {
  return rig.kernel.gpAx()[i]->lr_mc_control.axis_coupling.state_r;
}

// Posts `command` on axis i and ticks until it is answered.
plc::CommandAnswer answer_to(Rig& rig, std::size_t i, const plc::Command& command) {
  const uint16_t number = rig.axes[i]->Mailbox.post(command);
  for (int n = 0; n < 5; ++n) {
    rig.tick();
    const plc::CommandAnswer a = rig.axes[i]->Mailbox.answer(number);
    if (a.state != plc::CommandState::kPosted && a.state != plc::CommandState::kFree) return a;
  }
  return rig.axes[i]->Mailbox.answer(number);
}

uint32_t couple_state(const Rig& rig, std::size_t i) {
  return rig.axes[i]->NcToPlc.CoupleState;
}

}  // namespace

TEST_CASE("MC_ExtSetPointGenEnable on an HLI-coupled target is refused with 0x424E",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2")});
  REQUIRE(rig.couple(
      1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}, {8, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  const plc::NCTOPLC_AXIS_REF before = rig.axes[1]->NcToPlc;
  const plc::CommandAnswer a = answer_to(rig, 1, kt::ext_enable(0.0, 1));
  CHECK(a.state == plc::CommandState::kError);
  CHECK(a.error_code == 0x424E);
  CHECK(rig.error(1) == 0);  // a refused command is no axis error
  CHECK_FALSE(kt::bit(*rig.axes[1], plc::kStateExtSetPointGenEnabled));
  CHECK(state_of(rig, 1).active_r);
  CHECK(rig.set_pos(1) == before.SetPos);
  // The coupling still works: axis 1 by 200 moves Y2's drive by 200.
  REQUIRE(rig.move_to(0, 200.0));
  CHECK(rig.set_pos(1) == Approx(before.SetPos + 200.0).margin(1e-9));

  // Relative external setpoints are refused alike; after the list is off they are taken.
  const plc::CommandAnswer relative = answer_to(rig, 1, kt::ext_enable(0.0, 2));
  CHECK(relative.error_code == 0x424E);
  REQUIRE(rig.couple(1, {}));
  const plc::CommandAnswer free = answer_to(rig, 1, kt::ext_enable(0.0, 2));
  CHECK(free.state != plc::CommandState::kError);
  CHECK(kt::bit(*rig.axes[1], plc::kStateExtSetPointGenEnabled));
}

TEST_CASE("A new list is refused on an axis with external setpoints, in error, or disabled",
          "[hli][kernel]") {
  Rig rig({axis(1, "X"), axis(8, "Y2"), axis(9, "Z")});

  SECTION("external setpoint generation enabled: 0x424E, the generation stays") {
    REQUIRE(answer_to(rig, 1, kt::ext_enable(0.0, 2)).state != plc::CommandState::kError);
    CHECK_FALSE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
    CHECK(rig.last_coupling_error == 0x424E);
    CHECK(state_of(rig, 1).error_r == 0x424E);
    CHECK(kt::bit(*rig.axes[1], plc::kStateExtSetPointGenEnabled));
  }
  SECTION("in axis error: 0x4F06 until MC_Reset") {
    rig.start_move(1, 50.0, 100.0);
    rig.ticks(20);
    rig.power[1].Enable_Positive = false;  // feed enable removed while moving positive
    rig.tick();
    REQUIRE(rig.error(1) == 0x4358);
    rig.power[1].Enable_Positive = true;
    CHECK_FALSE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
    CHECK(rig.last_coupling_error == 0x4F06);
    CHECK(rig.error(1) == 0x4358);  // the axis error stays what it was
    rig.move[1].Execute = false;
    rig.ticks(1000);
    REQUIRE(rig.reset_axis(1));
    CHECK(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
    CHECK(rig.couple(1, {}));  // and off again
  }
  SECTION("without controller enable: 0x4223") {
    rig.power[1].Enable = false;
    rig.tick();
    CHECK_FALSE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
    CHECK(rig.last_coupling_error == 0x4223);
    CHECK(rig.error(1) == 0);
  }
  CHECK_FALSE(state_of(rig, 1).active_r);
  CHECK(couple_state(rig, 0) == 0);
  CHECK(rig.error(0) == 0);
}

TEST_CASE("CoupleState of HLI axes: target 3, source 1, both 2; bit 15 and AxisState",
          "[hli][kernel]") {
  // Y2 (8) follows X (1); Z (9) follows Y2's program: Y2 is target and source.
  Rig rig({axis(1, "X"), axis(8, "Y2"), axis(9, "Z")});
  for (std::size_t i = 0; i < 3; ++i)
    CHECK(couple_state(rig, i) == 0);
  REQUIRE(rig.couple(1, {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  CHECK(couple_state(rig, 0) == static_cast<uint32_t>(plc::CoupleState::kMaster));
  CHECK(couple_state(rig, 1) == static_cast<uint32_t>(plc::CoupleState::kSlave));
  CHECK(couple_state(rig, 2) == 0);
  CHECK(kt::bit(*rig.axes[1], plc::kStateCoupled));
  CHECK_FALSE(kt::bit(*rig.axes[0], plc::kStateCoupled));
  CHECK(rig.axes[1]->NcToPlc.AxisState ==
        static_cast<uint32_t>(plc::AxisState::kSynchronizedMotion));
  CHECK(rig.axes[1]->NcToPlc.GearRatio == 0.0);  // no gear factor: HLI factors are in state_r

  REQUIRE(rig.couple(
      2, {{8, h::HLI_AXIS_COUPLING_FRACT, 1, 2}, {9, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}}));
  CHECK(couple_state(rig, 1) == static_cast<uint32_t>(plc::CoupleState::kMasterAndSlave));
  CHECK(couple_state(rig, 2) ==
        static_cast<uint32_t>(plc::CoupleState::kSlave));  // self: no master

  // A move of the target's own program shows as DiscreteMotion while it runs.
  rig.start_move(1, 40.0, 200.0);
  rig.ticks(20);
  CHECK(rig.axes[1]->NcToPlc.AxisState == static_cast<uint32_t>(plc::AxisState::kDiscreteMotion));
  REQUIRE(rig.finish_move(1));
  CHECK(rig.axes[1]->NcToPlc.AxisState ==
        static_cast<uint32_t>(plc::AxisState::kSynchronizedMotion));
  CHECK(rig.set_pos(2) == Approx(20.0).margin(1e-9));  // Z: ½ of Y2's program movement

  REQUIRE(rig.couple(1, {}));  // Y2 off: it stays Z's source
  CHECK(couple_state(rig, 0) == 0);
  CHECK(couple_state(rig, 1) == static_cast<uint32_t>(plc::CoupleState::kMaster));
  CHECK(rig.axes[1]->NcToPlc.AxisState == static_cast<uint32_t>(plc::AxisState::kStandstill));
  REQUIRE(rig.couple(2, {}));
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(couple_state(rig, i) == 0);
    CHECK_FALSE(kt::bit(*rig.axes[i], plc::kStateCoupled));
  }
}
