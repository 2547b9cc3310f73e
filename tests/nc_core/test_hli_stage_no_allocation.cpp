// No allocation per cycle with couplings in force (brief: real-time discipline): 64 axes, each a
// target of 8 sources, moving, with lists taken, refused (70397, 70410 with its loop search),
// stopped (70200) and braking, over 10 000 cycles — 0 allocations. Also: two stages fed the same
// inputs give bit-identical outputs.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "counting_allocator.hpp"
#include "hli_stage_rig.hpp"

using namespace hlitest;

namespace {

constexpr int kAxes = 64;

Rig make_rig() {
  std::vector<nc::hli::AxisSetup> s(kAxes);
  for (int i = 0; i < kAxes; ++i) {
    auto& a = s[static_cast<std::size_t>(i)];
    a.ax_nr = i + 1;
    a.emergency_deceleration = 5000.0;
    a.sw_limit_max_enabled = true;
    a.sw_limit_max = 1e6;
  }
  s[0].forward_mapping = true;  // lists naming axis 1 run the loop search
  Rig rig(s);
  for (int i = 0; i < kAxes; ++i)
    rig.referenced[static_cast<std::size_t>(i)] = true;
  return rig;
}

// Target i: itself DIRECT, then i+1 … i+7 (mod 64) in all modes.
void ring_list(Rig& rig, std::size_t i, int16_t num) {
  auto nr = [&](std::size_t k) { return static_cast<int>((i + k) % kAxes) + 1; };
  rig.command(i, {direct(nr(0)), mirror(nr(1)), fract(nr(2), num, 7), zero(nr(3)), direct(nr(4)),
                  fract(nr(5), -3, 2), mirror(nr(6)), direct(nr(7))});
}

void phase(Rig& rig, int round) {
  // Lists at rest: all taken except where axis 1 makes a loop with P-AXIS-00436 (70410).
  for (std::size_t i = 1; i < kAxes; ++i)
    ring_list(rig, i, static_cast<int16_t>(round + 1));
  rig.cycle();
  rig.command(5, {fract(1, 20000, 3)});  // 70397
  rig.cycle();
  // Motion.
  for (int k = 0; k < 900; ++k) {
    for (std::size_t i = 0; i < kAxes; ++i) {
      rig.qv[i] = 0.01 * static_cast<double>((i * 7 + static_cast<std::size_t>(round)) % 13);
      rig.q[i] += rig.qv[i] * kT;
    }
    if (k == 100) rig.command(9, {direct(10)});  // 70200: stops and brakes axis 10
    rig.cycle();
  }
  // Rest.
  for (std::size_t i = 0; i < kAxes; ++i)
    rig.qv[i] = 0.0;
  for (int k = 0; k < 98; ++k)
    rig.cycle();
}

}  // namespace

TEST_CASE("the HLI stage allocates nothing per cycle with 64 targets x 8 sources", "[hli]") {
  Rig rig = make_rig();
  phase(rig, 0);  // warm-up outside the counted region
  ca::g_allocations = 0;
  ca::g_counting = true;
  for (int round = 1; round <= 10; ++round)
    phase(rig, round);
  ca::g_counting = false;
  CHECK(ca::g_allocations == 0);
  CHECK(rig.unit(5).state_r.error_r == 70397);
  CHECK(rig.unit(9).state_r.error_r == 70200);
  CHECK(rig.unit(1).state_r.active_r);
  CHECK(rig.unit(60).state_r.error_r == 70410);  // its list names axis 1, which reaches back
  CHECK_FALSE(rig.unit(60).state_r.active_r);
}

TEST_CASE("two stages fed the same inputs give bit-identical drive values", "[hli]") {
  Rig a = make_rig();
  Rig b = make_rig();
  for (int round = 0; round < 3; ++round) {
    phase(a, round);
    phase(b, round);
    REQUIRE(std::memcmp(a.d.data(), b.d.data(), a.d.size() * sizeof(double)) == 0);
    REQUIRE(std::memcmp(a.dv.data(), b.dv.data(), a.dv.size() * sizeof(double)) == 0);
  }
}
