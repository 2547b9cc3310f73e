// docs/architecture.md "One tick": phase (a) of every axis runs before phase (b) of any axis, so a
// coupling command sees the other axes as the last cycle left them. While nothing is coupled the
// kernel runs each axis's phases (a) to (f) before the next axis; it must not do so in a cycle in
// which an MC_GearIn waits, or a master with a lower index would already have run this cycle's
// phases when its slave's MC_GearIn looks at it.
//
// The master's positioning ends (Done, job cleared) in phase (e) of cycle K. An MC_GearIn handled
// in phase (a) of cycle K still sees the master's job: refused with 0x425A (SPEC C1, both at
// rest); handled in cycle K + 1 it couples. Both index orders of master and slave.
#include <catch2/catch.hpp>

#include <cstddef>

#include "gear_rig.hpp"

namespace {

constexpr double kTarget = 10.0;
constexpr double kVelocity = 2000.0;

// The number of cycles after which the master's positioning answers Done (0-based index of the
// cycle in which its job ends).
int cycle_of_done(std::size_t master) {
  gr::Rig rig(2);
  const uint16_t n = rig.post(master, kt::move_absolute(kTarget, kVelocity));
  for (int k = 0; k < 100000; ++k) {
    rig.kernel.cycle();
    if (rig.answer(master, n).state == plc::CommandState::kDone) return k;
  }
  return -1;
}

// A fresh rig: the master's positioning, `cycles` cycles, then MC_GearIn on the slave.
plc::CommandAnswer gear_in_after(std::size_t master, std::size_t slave, int cycles) {
  gr::Rig rig(2);
  rig.post(master, kt::move_absolute(kTarget, kVelocity));
  rig.cycles(cycles);
  return rig.couple(slave, master, 1.0);
}

}  // namespace

TEST_CASE("MC_GearIn sees its master as the last cycle left it, whatever the axis order",
          "[kernel][phases][gear]") {
  struct Pair {
    std::size_t master;
    std::size_t slave;
  };
  for (const Pair pair : {Pair{0, 1}, Pair{1, 0}}) {
    INFO("master " << pair.master << ", slave " << pair.slave);
    const int done = cycle_of_done(pair.master);
    REQUIRE(done > 10);  // a real positioning: 10 mm at up to 2000 mm/s on the seed axis

    // Handled in the cycle in which the master's job ends: the master was still positioning.
    const plc::CommandAnswer early = gear_in_after(pair.master, pair.slave, done);
    CHECK(early.state == plc::CommandState::kError);
    CHECK(early.error_code == plc::to_id(plc::ErrorCode::kBusyWhileCoupling));
    CHECK(early.error_code == 0x425AU);

    // One cycle later the master rests without a job: coupled, InGear at once.
    const plc::CommandAnswer late = gear_in_after(pair.master, pair.slave, done + 1);
    CHECK(late.state == plc::CommandState::kReached);
  }
}
