// SPEC C1, C3, C4 at rest (seed 000 §3.2.1, API.md "Slave axes"): NcToPlc.CoupleState (0 single,
// 1 master, 2 master and slave, 3 slave), the coupling flag (StateDWord bit 15), GearRatio and
// AxisState SynchronizedMotion (8) for the slave also while its master stands still, through
// coupling a cascade and a star and uncoupling them in every order; after MC_GearOut the slave
// is a PTP master at rest that starts on its own.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>

#include "gear_rig.hpp"

namespace {

std::array<uint32_t, 4> couple_states(gr::Rig& rig) {
  return {rig.at(0).NcToPlc.CoupleState, rig.at(1).NcToPlc.CoupleState,
          rig.at(2).NcToPlc.CoupleState, rig.at(3).NcToPlc.CoupleState};
}

}  // namespace

TEST_CASE("CoupleState, the coupling flag, GearRatio and AxisState of a cascade 0 -> 1 -> 2",
          "[gear]") {
  gr::Rig rig(4);
  REQUIRE(rig.couple(1, 0, 0.75).state == plc::CommandState::kReached);
  REQUIRE(rig.couple(2, 1, -0.5).state == plc::CommandState::kReached);
  CHECK(couple_states(rig) == std::array<uint32_t, 4>{1, 2, 3, 0});
  CHECK(kt::bit(rig.at(1), plc::kStateCoupled));
  CHECK(kt::bit(rig.at(2), plc::kStateCoupled));
  CHECK_FALSE(kt::bit(rig.at(0), plc::kStateCoupled));
  CHECK(rig.at(1).NcToPlc.GearRatio == 0.75);
  CHECK(rig.at(2).NcToPlc.GearRatio == -0.5);
  CHECK(rig.at(0).NcToPlc.GearRatio == 0.0);
  CHECK(kt::axis_state(rig.at(1)) == plc::AxisState::kSynchronizedMotion);  // master at rest
  CHECK(kt::axis_state(rig.at(2)) == plc::AxisState::kSynchronizedMotion);
  CHECK(kt::axis_state(rig.at(0)) == plc::AxisState::kStandstill);
  CHECK(kt::axis_state(rig.at(3)) == plc::AxisState::kStandstill);
}

TEST_CASE("uncoupling a cascade and a star in every order", "[gear]") {
  for (const bool star : {false, true}) {
    std::array<std::size_t, 3> slaves{1, 2, 3};
    int orders = 0;
    do {
      INFO((star ? "star" : "cascade") << ", out " << slaves[0] << slaves[1] << slaves[2]);
      gr::Rig rig(4);
      // Cascade 0 -> 1 -> 2 -> 3, or star 0 -> {1, 2, 3}.
      for (std::size_t s = 1; s <= 3; ++s)
        REQUIRE(rig.couple(s, star ? 0 : s - 1, 0.5).state == plc::CommandState::kReached);
      CHECK(couple_states(rig) ==
            (star ? std::array<uint32_t, 4>{1, 3, 3, 3} : std::array<uint32_t, 4>{1, 2, 2, 3}));
      for (std::size_t s : slaves) {
        const plc::CommandAnswer a = rig.decouple(s);
        REQUIRE(a.state == plc::CommandState::kDone);
        CHECK(rig.at(s).NcToPlc.CoupleState <= 1U);  // no longer a slave: single or master
        CHECK_FALSE(kt::bit(rig.at(s), plc::kStateCoupled));
        CHECK(rig.at(s).NcToPlc.GearRatio == 0.0);
      }
      CHECK(couple_states(rig) == std::array<uint32_t, 4>{0, 0, 0, 0});
      CHECK_FALSE(rig.kernel.couplings().has_couplings());
      for (std::size_t i = 0; i < 4; ++i)
        CHECK(kt::axis_state(rig.at(i)) == plc::AxisState::kStandstill);
      ++orders;
    } while (std::next_permutation(slaves.begin(), slaves.end()));
    CHECK(orders == 6);
  }
}

TEST_CASE("after MC_GearOut at rest the former slave holds and starts as a PTP master", "[gear]") {
  gr::Rig rig(2);
  const uint16_t gear = rig.post(1, gr::gear_in(0, 0.75));
  rig.cycles(1);
  REQUIRE(rig.at(1).NcToPlc.CmdNo == gear);
  rig.move_to(0, 400.0);  // the slave follows to 300
  CHECK(rig.at(1).NcToPlc.SetPos == Approx(300.0).margin(1e-9));
  REQUIRE(rig.decouple(1).state == plc::CommandState::kDone);
  CHECK(rig.answer(1, gear).state == plc::CommandState::kDone);  // the coupling has ended
  const double held = rig.at(1).NcToPlc.SetPos;
  rig.move_to(0, 0.0);  // the former master moves; the former slave does not
  CHECK(rig.at(1).NcToPlc.SetPos == held);
  rig.move_to(1, 500.0);
  CHECK(rig.at(1).NcToPlc.SetPos == 500.0);
  // Coupled again at the new positions: the offset is taken anew.
  REQUIRE(rig.couple(1, 0, 2.0).state == plc::CommandState::kReached);
  rig.move_to(0, 100.0);
  CHECK(rig.at(1).NcToPlc.SetPos == Approx(700.0).margin(1e-9));
}

TEST_CASE("MC_GearIn again for the same master changes the factor with the position continuous",
          "[gear]") {
  gr::Rig rig(2);
  const uint16_t first = rig.post(1, gr::gear_in(0, -0.7));
  rig.cycles(1);
  const uint16_t move = rig.post(0, kt::move_absolute(2000.0, 2000.0));
  rig.cycles(500);
  const double before = rig.at(1).NcToPlc.SetPos;
  const double master_before = rig.at(0).NcToPlc.SetPos;
  const uint16_t second = rig.post(1, gr::gear_in(0, -0.8));
  rig.kernel.cycle();
  CHECK(rig.answer(1, first).state == plc::CommandState::kAborted);
  CHECK(rig.answer(1, second).state == plc::CommandState::kReached);
  CHECK(rig.at(1).NcToPlc.GearRatio == -0.8);
  // The new offset keeps the position of the change: p = -0.8 · (m - m_before) + before.
  const double offset = before - (-0.8) * master_before;
  CHECK(rig.at(1).NcToPlc.SetPos == -0.8 * rig.at(0).NcToPlc.SetPos + offset);
  while (rig.answer(0, move).state != plc::CommandState::kDone)
    rig.kernel.cycle();
  CHECK(rig.at(1).NcToPlc.SetPos == Approx(before - 0.8 * (2000.0 - master_before)).epsilon(1e-12));
}
