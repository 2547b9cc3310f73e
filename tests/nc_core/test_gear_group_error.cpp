// Monitors of a coupled slave and the group reaction (SPEC C7 INSTANTANEOUS, seed 000 §3.1; the
// default error propagation): a slave's feed enable removed in its direction of travel (0x4358)
// or a software limit passed while it follows (0x4463) is an error of the slave, and an error
// on any axis of a master/slave group reaches every axis of the group in the same cycle with the
// faulty axis's code; the head master stops on its emergency ramp and the slaves follow it down
// (factor × master + offset to the end); each axis needs its own MC_Reset. An uncoupled axis
// beside the group is not touched. Also the slave's TargetVelo (seed 000 §3.2.2: slave target
// velocity = factor × master target velocity) and TargetPos, down a cascade.
#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "gear_rig.hpp"

namespace {

using plc::CommandState;

// Cascade 0 -> 1 -> 2 (factors 0.5, -2 from axis 1) and axis 3 alone, the master moving 0 ->
// 20000 at V 1000 and cruising.
struct Cascade {
  nc::Kernel kernel;
  std::vector<plc::AXIS_REF*> axes;

  explicit Cascade(double slave_limit_max = 0.0) {
    for (std::size_t i = 0; i < 4; ++i) {
      std::string name(1, 'A');
      name += std::to_string(i);
      nc::AxisConfig c = kt::seed_axis(name);
      if (i == 1 && slave_limit_max > 0.0) {
        c.sw_limit_max_enabled = true;
        c.sw_limit_max = slave_limit_max;
      }
      axes.push_back(&kernel.add_axis(c));
      kt::set_enables(*axes.back(), true);
    }
    kernel.cycle();
    axes[1]->Mailbox.post(gr::gear_in(0, 0.5));
    axes[2]->Mailbox.post(gr::gear_in(1, -2.0));
    kernel.cycle();
    REQUIRE(axes[2]->NcToPlc.CoupleState == 3U);
    axes[0]->Mailbox.post(kt::move_absolute(20000.0, 1000.0));
    axes[3]->Mailbox.post(kt::move_absolute(20000.0, 1000.0));
  }
  plc::AXIS_REF& at(std::size_t i) { return *axes[i]; }
  void cycles(int n) {
    for (int i = 0; i < n; ++i)
      kernel.cycle();
  }
  bool errors_are(uint32_t code) {
    for (std::size_t i = 0; i < 3; ++i) {
      if (at(i).NcToPlc.ErrorCode != code) return false;
      if (kt::axis_state(at(i)) != plc::AxisState::kErrorStop) return false;
    }
    return true;
  }
  // Until the master stands; the slaves follow it to the end.
  void check_stopping_group() {
    const double offset1 = at(1).NcToPlc.SetPos - 0.5 * at(0).NcToPlc.SetPos;
    const double offset2 = at(2).NcToPlc.SetPos + 2.0 * at(1).NcToPlc.SetPos;
    int cycles = 0;
    while (at(0).NcToPlc.SetVelo != 0.0 && cycles < 5000) {
      kernel.cycle();
      ++cycles;
      REQUIRE(at(1).NcToPlc.SetPos == Approx(0.5 * at(0).NcToPlc.SetPos + offset1).margin(1e-9));
      REQUIRE(at(2).NcToPlc.SetPos == Approx(-2.0 * at(1).NcToPlc.SetPos + offset2).margin(1e-9));
    }
    CHECK(at(0).NcToPlc.SetVelo == 0.0);
    CHECK(at(1).NcToPlc.SetVelo == 0.0);
    CHECK(at(2).NcToPlc.SetVelo == 0.0);
    CHECK(at(2).NcToPlc.CoupleState == 3U);  // the coupling stays
    // The uncoupled axis went on.
    CHECK(at(3).NcToPlc.ErrorCode == 0U);
    CHECK(at(3).NcToPlc.SetVelo == 1000.0);
  }
};

}  // namespace

TEST_CASE("a slave's feed enable removed while it follows stops the whole cascade at once",
          "[gear][group]") {
  for (const std::size_t faulty : {std::size_t{2}, std::size_t{1}, std::size_t{0}}) {
    INFO("faulty axis " << faulty);
    Cascade c;
    c.cycles(1000);
    // Axis 2 runs backwards (factor -2 × 0.5): its minus direction; the others plus.
    kt::set_enables(c.at(faulty), true, faulty == 2, faulty != 2);
    c.kernel.cycle();
    const uint32_t code = faulty == 2 ? kt::id(plc::ErrorCode::kFeedEnableMinusMissing)
                                      : kt::id(plc::ErrorCode::kFeedEnablePlusMissing);
    REQUIRE(c.errors_are(code));
    for (std::size_t i = 0; i < 3; ++i)
      CHECK(kt::bit(c.at(i), plc::kStateError));
    c.check_stopping_group();
    kt::set_enables(c.at(faulty), true);

    // Each axis of the group needs its own reset.
    const uint16_t r = c.at(1).Mailbox.post(kt::simple(plc::CommandType::kReset));
    c.kernel.cycle();
    CHECK(c.at(1).Mailbox.answer(r).state == CommandState::kDone);
    CHECK(c.at(1).NcToPlc.ErrorCode == 0U);
    CHECK(c.at(0).NcToPlc.ErrorCode == code);
    CHECK(c.at(2).NcToPlc.ErrorCode == code);
  }
}

TEST_CASE("a coupled slave passing its software limit (0x4463) stops its group", "[gear][group]") {
  Cascade c(3000.0);  // axis 1 runs 0 -> 10000 at 500 mm/s: past 3000 after about 6 s
  int cycles = 0;
  while (c.at(1).NcToPlc.ErrorCode == 0U && cycles < 10000) {
    c.kernel.cycle();
    ++cycles;
  }
  REQUIRE(c.errors_are(kt::id(plc::ErrorCode::kSoftLimitMaxDuringMotion)));
  CHECK(c.at(1).NcToPlc.SetPos > 3000.0);
  CHECK(c.at(1).NcToPlc.SetPos < 3000.0 + 0.5 * 1000.0 * 0.001 * 1.000001);
  c.check_stopping_group();
}

TEST_CASE("an error on the master reaches its slaves in the same cycle", "[gear][group]") {
  Cascade c;
  c.cycles(800);
  kt::set_enables(c.at(0), true, false, true);
  c.kernel.cycle();
  REQUIRE(c.errors_are(kt::id(plc::ErrorCode::kFeedEnablePlusMissing)));
  c.check_stopping_group();
}

TEST_CASE("a slave's TargetVelo is factor x its master's, TargetPos factor x target + offset",
          "[gear]") {
  gr::Rig rig(3);
  rig.move_to(1, 100.0);
  REQUIRE(rig.couple(1, 0, 0.75).state == CommandState::kReached);
  REQUIRE(rig.couple(2, 1, -2.0).state == CommandState::kReached);
  kt::set_override(rig.at(0), 30.0);
  rig.post(0, kt::move_absolute(20000.0, 2000.0));
  rig.cycles(10);
  CHECK(rig.at(0).NcToPlc.TargetVelo == 600.0);
  CHECK(rig.at(1).NcToPlc.TargetVelo == 450.0);
  CHECK(rig.at(2).NcToPlc.TargetVelo == -900.0);
  CHECK(rig.at(1).NcToPlc.TargetPos == 0.75 * 20000.0 + 100.0);
  CHECK(rig.at(2).NcToPlc.TargetPos == -2.0 * (0.75 * 20000.0 + 100.0) + 200.0);
  kt::set_override(rig.at(0), 100.0);
  rig.cycles(10);
  CHECK(rig.at(1).NcToPlc.TargetVelo == 1500.0);
  CHECK(rig.at(2).NcToPlc.TargetVelo == -3000.0);
}
