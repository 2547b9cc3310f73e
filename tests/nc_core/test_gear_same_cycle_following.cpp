// SPEC C1, C3 (seed 000 §3.2.2): a coupled slave's set values are factor × its master's set
// values of the SAME cycle + offset, bit for bit against the formula at every cycle of a master
// move 0 → 2000 mm at V 2000 — for factors 0.75, -0.5 and 1/3, for the slave added before or
// after its master, down a cascade (factors 2, -0.5, 0.75: the product, no lag) built top-down or
// bottom-up with the axes added in every order, and in a star. Offsets come from the coupling
// positions (slaves standing at 10, 20, 30 mm).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "gear_rig.hpp"

namespace {

struct Link {
  std::size_t slave;
  std::size_t master;
  double factor;
  double offset = 0.0;
};

// Couples every link (in the given order) at rest, taking the offsets from the published set
// positions, then moves `head` 0 → 2000 at V 2000 and checks every link at every cycle; returns
// the cycles checked.
int run_and_check(gr::Rig& rig, std::size_t head, std::vector<Link>& links) {
  for (Link& l : links) {
    const plc::CommandAnswer a = rig.couple(l.slave, l.master, l.factor);
    REQUIRE(a.state == plc::CommandState::kReached);
    l.offset = rig.at(l.slave).NcToPlc.SetPos - l.factor * rig.at(l.master).NcToPlc.SetPos;
  }
  const uint64_t revision = rig.kernel.couplings().revision();
  const uint16_t n = rig.post(head, kt::move_absolute(2000.0, 2000.0));
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    rig.kernel.cycle();
    for (const Link& l : links) {
      const auto& s = rig.at(l.slave).NcToPlc;
      const auto& m = rig.at(l.master).NcToPlc;
      REQUIRE(s.SetPos == l.factor * m.SetPos + l.offset);
      REQUIRE(s.SetVelo == l.factor * m.SetVelo);
      REQUIRE(s.SetAcc == l.factor * m.SetAcc);
    }
    ++checked;
  }
  REQUIRE(rig.answer(head, n).state == plc::CommandState::kDone);
  REQUIRE(rig.at(head).NcToPlc.SetPos == 2000.0);
  REQUIRE(rig.kernel.couplings().revision() == revision);  // no reordering in a steady cycle
  return checked;
}

}  // namespace

TEST_CASE("a slave follows its master in the same cycle for factors 0.75, -0.5 and 1/3", "[gear]") {
  for (const double factor : {0.75, -0.5, 1.0 / 3.0}) {
    for (const bool slave_first : {false, true}) {
      INFO("factor " << factor << (slave_first ? ", slave added first" : ", master added first"));
      gr::Rig rig(2);
      const std::size_t master = slave_first ? 1 : 0;
      const std::size_t slave = slave_first ? 0 : 1;
      rig.move_to(slave, 100.0);
      std::vector<Link> links{{slave, master, factor}};
      REQUIRE(run_and_check(rig, master, links) == 3000);
      // The slave ends at factor × 2000 + 100.
      CHECK(rig.at(slave).NcToPlc.SetPos == Approx(factor * 2000.0 + 100.0).margin(1e-9));
    }
  }
}

TEST_CASE(
    "a cascade of three slaves (2, -0.5, 0.75) has the product at every cycle in any "
    "order",
    "[gear]") {
  std::array<std::size_t, 4> roles{0, 1, 2, 3};  // index of head, S1, S2, S3
  int runs = 0;
  do {
    for (const bool top_down : {true, false}) {
      INFO("head " << roles[0] << " S1 " << roles[1] << " S2 " << roles[2] << " S3 " << roles[3]
                   << (top_down ? " top-down" : " bottom-up"));
      gr::Rig rig(4);
      rig.move_to(roles[1], 10.0);
      rig.move_to(roles[2], 20.0);
      rig.move_to(roles[3], 30.0);
      std::vector<Link> links{
          {roles[1], roles[0], 2.0}, {roles[2], roles[1], -0.5}, {roles[3], roles[2], 0.75}};
      if (!top_down) std::reverse(links.begin(), links.end());
      run_and_check(rig, roles[0], links);
      // Factors multiply: S3 moved 2 · -0.5 · 0.75 · 2000 = -1500 from its coupling position.
      CHECK(rig.at(roles[3]).NcToPlc.SetPos == Approx(30.0 - 1500.0).margin(1e-9));
      CHECK(rig.at(roles[3]).NcToPlc.CoupleState == 3U);
      CHECK(rig.at(roles[1]).NcToPlc.CoupleState == 2U);
      ++runs;
    }
  } while (std::next_permutation(roles.begin(), roles.end()));
  REQUIRE(runs == 48);
}

TEST_CASE("a star of three slaves follows one master in the same cycle", "[gear]") {
  std::array<std::size_t, 4> roles{0, 1, 2, 3};
  do {
    INFO("master " << roles[0]);
    gr::Rig rig(4);
    rig.move_to(roles[1], 10.0);
    rig.move_to(roles[2], 20.0);
    std::vector<Link> links{
        {roles[1], roles[0], 0.75}, {roles[2], roles[0], -0.5}, {roles[3], roles[0], 1.0 / 3.0}};
    run_and_check(rig, roles[0], links);
    CHECK(rig.at(roles[0]).NcToPlc.CoupleState == 1U);
    CHECK(rig.at(roles[1]).NcToPlc.SetPos == Approx(10.0 + 1500.0).margin(1e-9));
    CHECK(rig.at(roles[2]).NcToPlc.SetPos == Approx(20.0 - 1000.0).margin(1e-9));
  } while (std::next_permutation(roles.begin(), roles.end()));
}
