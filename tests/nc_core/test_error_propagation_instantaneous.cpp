// SPEC C7 INSTANTANEOUS (seed 000 §3.1, the default; issue 10): a following error on the last
// slave of a 3-axis cascade stops all three in the same cycle, each in ErrorStop with the faulty
// axis's code 0x4550; the head master runs down its emergency ramp and the slaves follow it down
// (factor × master + offset to the end), each needing its own MC_Reset. The faulty axis's own
// mode decides: a DELAYED master does not delay an INSTANTANEOUS slave's error.
#include <catch2/catch.hpp>

#include "propagation_rig.hpp"

using plc::AxisState;
using plc::CommandType;
using plc::ErrorCode;

namespace {

// Cascade 0 -> 1 (factor 1) -> 2 (factor 1), the last slave's drive saturated at 900 mm/s; the
// master starts to 20000 at 1000 mm/s. `master_delayed`: the head master is DELAYED (0.5 s).
struct Cascade : pr::Group {
  explicit Cascade(bool master_delayed = false)
      : pr::Group(3, [&](std::size_t i, nc::AxisConfig& c) {
          if (i == 2) pr::slow_drive(c);
          if (i == 0 && master_delayed) pr::delayed(c, 0.5);
        }) {
    REQUIRE(couple(1, 0, 1.0));
    REQUIRE(couple(2, 1, 1.0));
    post(0, kt::move_absolute(20000.0, 1000.0));
  }
};

void check_same_cycle_stop(Cascade& c) {
  const int k = c.until_error(2);
  REQUIRE(k > 0);
  const uint32_t code = kt::id(ErrorCode::kFollowingErrorPosition);
  for (std::size_t i = 0; i < 3; ++i) {
    INFO("axis " << i);
    CHECK(c.error(i) == code);
    CHECK(c.error_bit(i));
    CHECK_FALSE(c.delayed_bit(i));
    CHECK(kt::axis_state(c.at(i)) == AxisState::kErrorStop);
  }
  // The master is on its emergency ramp (D = 10000 mm/s²) from the cycle of the error on.
  const double v0 = c.at(0).NcToPlc.SetVelo;
  c.cycles(1);
  CHECK(c.at(0).NcToPlc.SetVelo < v0);
  const double offset1 = c.at(1).NcToPlc.SetPos - c.at(0).NcToPlc.SetPos;
  const double offset2 = c.at(2).NcToPlc.SetPos - c.at(1).NcToPlc.SetPos;
  int cycles = 0;
  while (c.at(0).NcToPlc.SetVelo != 0.0 && cycles < 5000) {
    c.cycles(1);
    ++cycles;
    REQUIRE(c.at(0).NcToPlc.SetAcc >= -10000.0 * (1 + 1e-9));
    REQUIRE(c.at(1).NcToPlc.SetPos == Approx(c.at(0).NcToPlc.SetPos + offset1).margin(1e-9));
    REQUIRE(c.at(2).NcToPlc.SetPos == Approx(c.at(1).NcToPlc.SetPos + offset2).margin(1e-9));
  }
  CHECK(cycles < 200);  // 1000 mm/s down at 10000 mm/s² and J 100000: about 0.11 s
  CHECK(c.at(2).NcToPlc.SetVelo == 0.0);
  CHECK(c.at(2).NcToPlc.CoupleState == 3U);  // the couplings stay
  // Each axis needs its own reset.
  c.post(0, kt::simple(CommandType::kReset));
  c.cycles(1);
  CHECK(c.error(0) == 0U);
  CHECK(c.error(1) == code);
  CHECK(c.error(2) == code);
}

}  // namespace

TEST_CASE("INSTANTANEOUS: a following error on the cascade's last slave stops all three at once",
          "[propagation][instantaneous]") {
  Cascade c;
  check_same_cycle_stop(c);
}

TEST_CASE("the faulty axis's own mode decides: an INSTANTANEOUS slave under a DELAYED master",
          "[propagation][instantaneous]") {
  Cascade c(true);
  check_same_cycle_stop(c);
}
