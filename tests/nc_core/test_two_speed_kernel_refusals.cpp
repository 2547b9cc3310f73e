// What a two-speed axis in the kernel refuses (SPEC E2, E3; issue 12), each with its code and
// with the NC→PLC image and the drive image bit-identical to a twin kernel that never saw the
// command: start velocity <= 0 (0x4231), a distance not larger than the braking distance of its
// direction (0x4F0C), a position NaN (0x4F01), a start while a positioning runs (0x424E), the
// commands a two-speed axis does not know (0x4040); MC_GearIn with a two-speed master or slave
// (0x4040) and an HLI list with a two-speed source or target (error_r 0x4040).
#include <catch2/catch.hpp>

#include <cstring>
#include <limits>
#include <string>

#include "gear_rig.hpp"
#include "kernel_harness.hpp"
#include "two_speed_kernel_rig.hpp"

namespace {

using E = plc::ErrorCode;

struct Twins {
  tsk::Rig probe;
  tsk::Rig reference;

  bool same() const {
    return kt::same_image(probe.axis.NcToPlc, reference.axis.NcToPlc) &&
           probe.image() == reference.image();
  }
  void cycles(int n) {
    for (int i = 0; i < n; ++i) {
      probe.cycle();
      reference.cycle();
    }
  }
};

void expect_refused(Twins& t, const std::string& what, const plc::Command& command, E expected) {
  INFO(what);
  REQUIRE(t.same());
  const uint16_t n = t.probe.axis.Mailbox.post(command);
  t.cycles(1);
  const plc::CommandAnswer a = t.probe.axis.Mailbox.answer(n);
  CHECK(a.state == plc::CommandState::kError);
  CHECK(a.error_code == plc::to_id(expected));
  for (int i = 0; i < 50; ++i) {
    REQUIRE(t.same());
    t.cycles(1);
  }
}

plc::Command typed(plc::CommandType type) {
  plc::Command c;
  c.type = type;
  return c;
}

}  // namespace

TEST_CASE("refused two-speed commands carry their codes and change nothing",
          "[two_speed][kernel][refusal]") {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  CHECK(plc::to_id(E::kTwoSpeedDistanceTooShort) == 0x4F0CU);
  Twins t;
  // At rest (nAxisState 0): the refusals of a start.
  expect_refused(t, "velocity 0", kt::move_absolute(1000.0, 0.0), E::kVelocityNotPositive);
  expect_refused(t, "velocity -10", kt::move_absolute(1000.0, -10.0), E::kVelocityNotPositive);
  expect_refused(t, "velocity NaN", kt::move_absolute(1000.0, kNaN), E::kParameterNotFinite);
  expect_refused(t, "position NaN", kt::move_absolute(kNaN, 2000.0), E::kPositionNotFinite);
  expect_refused(t, "distance 5 = braking distance +", kt::move_absolute(5.0, 2000.0),
                 E::kTwoSpeedDistanceTooShort);
  expect_refused(t, "distance -6 = braking distance -", kt::move_relative(-6.0, 2000.0),
                 E::kTwoSpeedDistanceTooShort);
  expect_refused(t, "distance 0", kt::move_relative(0.0, 2000.0), E::kTwoSpeedDistanceTooShort);
  plc::Command buffered = kt::move_absolute(1000.0, 2000.0);
  buffered.buffer_mode = plc::MC_Buffered;
  expect_refused(t, "buffered", buffered, E::kBufferModeNotSupported);
  expect_refused(t, "MC_MoveVelocity", kt::move_velocity(100.0, 1), E::kAxisKindNotAllowed);
  expect_refused(t, "MC_MoveModulo", kt::move_modulo(10.0, 100.0, 1), E::kAxisKindNotAllowed);
  expect_refused(t, "MC_MoveSuperImposed", kt::move_superimposed(1, 1, 1, 1, 1, 1),
                 E::kAxisKindNotAllowed);
  expect_refused(t, "MC_ExtSetPointGenEnable", kt::ext_enable(0.0, 1), E::kAxisKindNotAllowed);
  expect_refused(t, "MC_GearOut", gr::gear_out(), E::kAxisKindNotAllowed);
  expect_refused(t, "MC_Halt deceleration NaN", kt::simple(plc::CommandType::kHalt, kNaN),
                 E::kParameterNotFinite);
  expect_refused(t, "MC_Home", typed(plc::CommandType::kHome), E::kUnknownCommand);
}

TEST_CASE("a two-speed axis refuses a second start while it travels", "[two_speed][kernel]") {
  // A positioning runs in both twins: a second start and new positions are refused.
  Twins t;
  t.probe.axis.Mailbox.post(kt::move_absolute(1000.0, 2000.0));
  t.reference.axis.Mailbox.post(kt::move_absolute(1000.0, 2000.0));
  t.cycles(300);
  REQUIRE(t.probe.state() == tsk::State::kMainTravel);
  expect_refused(t, "start while moving", kt::move_absolute(500.0, 2000.0), E::kFunctionNotAllowed);
  expect_refused(t, "MC_NewPos", kt::new_pos(800.0), E::kAxisKindNotAllowed);
  expect_refused(
      t, "MC_Halt buffered",
      [] {
        plc::Command c = kt::simple(plc::CommandType::kHalt);
        c.buffer_mode = plc::MC_Buffered;
        return c;
      }(),
      E::kBufferModeNotSupported);
}

TEST_CASE("MC_GearIn with a two-speed master or slave is refused with 0x4040",
          "[two_speed][kernel][refusal][gear]") {
  nc::Kernel kernel;
  plc::AXIS_REF& servo = kernel.add_axis(kt::seed_axis("X"));
  plc::AXIS_REF& two_speed = kernel.add_axis(ts::issue_axis());
  kt::set_enables(servo, true);
  kt::set_enables(two_speed, true);
  kernel.cycle();

  fb::MC_GearIn two_speed_master;  // servo follows the two-speed axis
  two_speed_master.Execute = true;
  fb::MC_GearIn two_speed_slave;  // the two-speed axis follows the servo
  two_speed_slave.Execute = true;
  for (int i = 0; i < 3; ++i) {
    two_speed_master(two_speed, servo);
    two_speed_slave(servo, two_speed);
    kernel.cycle();
  }
  CHECK(two_speed_master.Error);
  CHECK(two_speed_master.ErrorID == 0x4040U);
  CHECK(two_speed_slave.Error);
  CHECK(two_speed_slave.ErrorID == 0x4040U);
  CHECK_FALSE(kernel.couplings().has_couplings());
  CHECK(servo.NcToPlc.CoupleState == 0U);
  CHECK(two_speed.NcToPlc.CoupleState == 0U);
}

TEST_CASE("an HLI list with a two-speed source or target is refused with 0x4040",
          "[two_speed][kernel][refusal][hli]") {
  nc::Kernel kernel;
  nc::AxisConfig x = kt::seed_axis("X");
  x.id = 1;
  nc::AxisConfig t = ts::issue_axis();
  t.id = 2;
  // X enabled, so that its list is refused for the two-speed source, not for X's own enable.
  kt::set_enables(kernel.add_axis(x), true);
  kernel.add_axis(t);
  kernel.cycle();
  const auto gpAx = kernel.gpAx();
  namespace h = plc::hli;
  // Target X, source the two-speed axis; then target the two-speed axis, source X.
  const std::pair<std::size_t, int32_t> lists[] = {{0, 2}, {1, 1}};
  for (const auto& [target, source] : lists) {
    fb::HLI_AxisCoupling block;
    block.desc[0] = h::HLI_AX_COUPLING_DESC{source, h::HLI_AXIS_COUPLING_DIRECT, 0, 0};
    block.Execute = true;
    for (int i = 0; i < 3; ++i) {
      block(gpAx[target]);
      kernel.cycle();
    }
    INFO("target " << target);
    CHECK(block.Error);
    CHECK(block.ErrorID == 0x4040U);
    CHECK(gpAx[target]->lr_mc_control.axis_coupling.state_r.error_r == 0x4040U);
    CHECK_FALSE(gpAx[target]->lr_mc_control.axis_coupling.state_r.active_r);
  }
}
