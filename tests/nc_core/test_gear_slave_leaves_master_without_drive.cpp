// K26 (docs/reliability.md, docs/behaviour.md "Slave axes"): a coupled slave whose master's drive
// goes off under it — the master loses its controller enable while its set values move, and
// does not drive its slaves by filtered actual values (SPEC C8) — leaves the coupling and stops
// on its own emergency ramp from its set state, with 0x4260, instead of following the master's
// set position, which from then on follows its actual one (before: a slave at 600 mm/s stopped
// in one cycle behind an ideal drive, and behind a lagging one its actual velocity went to
// -1437.8 mm/s as its set position jumped back by twice the master's following error).
#include <catch2/catch.hpp>

#include "brake_watch.hpp"
#include "gear_rig.hpp"

namespace {

using plc::CommandState;

// A rig of two axes: axis 1 follows axis 0 at factor 2, axis 0 runs towards 20000 mm at
// 300 mm/s for 500 cycles (the slave cruises at 600 mm/s). `lag`: axis 0's drive is a
// first-order lag of 5 ms (its actual position trails its set position).
gr::Rig cruising_pair(bool lag) {
  gr::Rig rig(2, [lag](std::size_t i, nc::AxisConfig& c) {
    if (i == 0 && lag) {
      c.drive_model = nc::DriveModel::kFirstOrderLag;
      c.drive_time_constant = 0.005;
    }
  });
  REQUIRE(rig.couple(1, 0, 2.0).state == CommandState::kReached);
  rig.post(0, kt::move_absolute(20000.0, 300.0));
  rig.cycles(500);
  REQUIRE(rig.at(1).NcToPlc.SetVelo == Approx(600.0));
  return rig;
}

// The slave (axis 1) over `cycles` cycles after its master's enable went.
kt::BrakeWatch watch_slave(gr::Rig& rig, int cycles) {
  return kt::watch_brake(rig.at(1), cycles, [&rig] { rig.cycles(1); });
}

}  // namespace

TEST_CASE("a slave behind an ideal drive whose enable goes brakes on its own emergency ramp",
          "[gear][enables][k26]") {
  gr::Rig rig = cruising_pair(false);
  kt::set_enables(rig.at(0), false);
  rig.cycles(1);
  CHECK(rig.at(0).NcToPlc.ErrorCode == 0x4260U);
  CHECK(rig.at(1).NcToPlc.ErrorCode == 0x4260U);
  // The slave has left the coupling: its set velocity is its own ramp's (emergency deceleration
  // 10000 mm/s², jerk 1e5 mm/s³), one cycle in: 600 - 1e5 * 0.001² / 2 = 599.95 mm/s.
  CHECK(rig.at(1).NcToPlc.SetVelo == Approx(599.95).margin(1e-9));
  CHECK(rig.at(1).NcToPlc.GearRatio == 0.0);
  const kt::BrakeWatch b = watch_slave(rig, 300);
  // No step: from 600 mm/s the ramp's deceleration peaks at sqrt(600 * 1e5) = 7746 mm/s² (below
  // 10000), so at most 7.75 mm/s per cycle; down to rest without reversing.
  CHECK(b.largest_step <= 7.75);
  CHECK(b.lowest_set >= 0.0);
  CHECK(b.lowest_actual >= -1e-3);
  CHECK(b.last_set == 0.0);
  // The ramp 600 mm/s -> 0 with jerk 1e5 mm/s³: 2 sqrt(600 / 1e5) = 0.1549 s, 155 cycles with
  // the one above.
  CHECK(b.cycles_to_rest >= 153);
  CHECK(b.cycles_to_rest <= 155);
}

TEST_CASE(
    "a slave behind a lagging drive whose enable goes does not jump back by the master's "
    "following error",
    "[gear][enables][k26]") {
  gr::Rig rig = cruising_pair(true);
  // The master's actual position trails its set position: what the slave would have jumped by.
  REQUIRE(rig.at(0).NcToPlc.PosDiff > 0.9);
  kt::set_enables(rig.at(0), false);
  const kt::BrakeWatch b = watch_slave(rig, 300);
  CHECK(rig.at(1).NcToPlc.ErrorCode == 0x4260U);
  CHECK(b.largest_step <= 7.75);
  CHECK(b.lowest_actual >= -1e-3);  // before: -1437.8 mm/s
  CHECK(b.last_set == 0.0);
}

TEST_CASE("a slave stays coupled to a master at rest whose enable goes", "[gear][enables][k26]") {
  gr::Rig rig(2);
  REQUIRE(rig.couple(1, 0, 2.0).state == CommandState::kReached);
  kt::set_enables(rig.at(0), false);
  rig.cycles(5);
  CHECK(rig.at(0).NcToPlc.ErrorCode == 0U);  // no command ran: no error
  CHECK(rig.at(1).NcToPlc.ErrorCode == 0U);
  CHECK(rig.at(1).NcToPlc.GearRatio == 2.0);
  // The enable back: the master moves, the slave follows at factor 2.
  kt::set_enables(rig.at(0), true);
  rig.post(0, kt::move_absolute(100.0, 300.0));
  rig.cycles(100);
  CHECK(rig.at(1).NcToPlc.SetVelo == Approx(2.0 * rig.at(0).NcToPlc.SetVelo));
  CHECK(rig.at(1).NcToPlc.SetVelo > 0.0);
}

TEST_CASE(
    "a slave on its master's error ramp leaves it when the master's enable goes, from where "
    "it is",
    "[gear][enables][k26]") {
  gr::Rig rig = cruising_pair(false);
  // The master's error (its feed enable in the direction of travel removed): its emergency ramp
  // brings the group down, the slave following it.
  kt::set_enables(rig.at(0), true, false, true);
  rig.cycles(1);
  REQUIRE(rig.at(0).NcToPlc.ErrorCode == 0x4358U);
  REQUIRE(rig.at(1).NcToPlc.ErrorCode == 0x4358U);
  rig.cycles(20);
  const double following = rig.at(1).NcToPlc.SetVelo;
  REQUIRE(following == Approx(2.0 * rig.at(0).NcToPlc.SetVelo));
  REQUIRE(following > 100.0);
  kt::set_enables(rig.at(0), false);
  const kt::BrakeWatch b = watch_slave(rig, 300);
  CHECK(rig.at(1).NcToPlc.ErrorCode == 0x4358U);  // the first error stays
  CHECK(b.largest_step <= 20.0);
  CHECK(b.lowest_actual >= -1e-3);
  CHECK(b.last_set == 0.0);
}

TEST_CASE(
    "DELAYED propagation: the slave leaves with its own 0x4260, bit 6 for the delay, and "
    "brakes without a step",
    "[gear][enables][k26]") {
  gr::Rig rig(2, [](std::size_t, nc::AxisConfig& c) {
    c.error_propagation_mode = nc::ErrorPropagation::kDelayed;
    c.error_propagation_delay = 0.05;  // 50 cycles
  });
  REQUIRE(rig.couple(1, 0, 2.0).state == CommandState::kReached);
  rig.post(0, kt::move_absolute(20000.0, 300.0));
  rig.cycles(500);
  kt::set_enables(rig.at(0), false);
  rig.cycles(1);
  CHECK(rig.at(1).NcToPlc.ErrorCode == 0x4260U);
  CHECK(kt::bit(rig.at(1), plc::kStateErrorPropagationDelayed));
  CHECK(rig.at(1).NcToPlc.SetVelo == Approx(599.95).margin(1e-9));
  const kt::BrakeWatch b = watch_slave(rig, 300);
  CHECK_FALSE(kt::bit(rig.at(1), plc::kStateErrorPropagationDelayed));  // the delay ran out
  CHECK(b.largest_step <= 7.75);
  CHECK(b.lowest_actual >= -1e-3);
  CHECK(b.last_set == 0.0);
}
