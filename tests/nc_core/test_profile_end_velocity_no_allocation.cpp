// No allocation in plan_position's end-velocity call on the paths branch `planner` added (brief:
// real-time discipline): the first-switch scan, the hold at v_end after a rounding jump, the
// power-law first point on a long piece, the search past a flat stretch of E on a push hold, and
// the refusal of a start far above the bound its ramp ends at (fuzz findings P9, P10, P12, P14,
// P17; issue 14 item 1), and 2 000 random problems with v_end. A counting global operator new
// counts 0. Runs only in the plain build.
#include <catch2/catch.hpp>

#include <vector>

#include "counting_allocator.hpp"
#include "nc_core/profile.hpp"
#include "profile_problems.hpp"

namespace {

struct Case {
  nc::KinematicState start;
  double target = 0.0;
  double v_end = 0.0;
  nc::Limits limits;
};

}  // namespace

TEST_CASE("plan_position with an end velocity allocates nothing on its new paths",
          "[no_allocation][profile][end_velocity]") {
  std::vector<Case> cases = {
      // P10: a hold at v_end after the rounding jump.
      {{0.0, 0.0, -4.5777065690089267e-06},
       0.010588235294117647,
       0.010588235294117647,
       {0.010841535057602809, 0.065687037460898767, 0.010588235294117647, 0.010588235294117647}},
      // P12: the same with A- = 6.1e-6.
      {{0.0, 500.00762951094833, 0.0},
       1000.0,
       2876.0204470893414,
       {200000.0, 5000.076295109483, 6.1036087586785692e-06, 50212.863355458911}},
      // P14: a root far below the end of a hold of 1.3e8 s.
      {{0.0, 0.0, 9.0626382848859386},
       0.0,
       3.4331812393645485e-44,
       {1000.0, 7.6295109483482109e-06, 5312.5810635538264, 227389.94430457009}},
      // Bellman seed 3: the first-switch scan.
      {{0.0, -3.2898764527582767, 4.7973199386656624},
       0.071945387924975804,
       2.033291143442896,
       {3.2898764527582767, 6546.635221418459, 20454.983581909062, 3.3288370245999088}},
      // P17: the search past a flat stretch of E on a push hold.
      {{6.5715143469463669e-110, 7.041529113169559e-09, 9.9741677046594516e-43},
       7.0415291131643709e-09,
       1.1061837756334599e-08,
       {1982014.243136033, 7.0415291132253573e-09, 7.0415291131581728e-09, 1392190.2470443724}},
      // P9: refused (0x4F70).
      {{0.0, 0.12012095731847509, -0.6952196903821245},
       0.00047679222188957981,
       1e-3,
       {9074.0000000791624, 7.2752683738651311e-09, 0.00046147382817898422, 2.0004863739013672}},
  };
  profile_problems::Rng rng(0xA110CULL);
  for (int k = 0; k < 2000; ++k) {
    const profile_problems::Problem pr = profile_problems::random_position_problem(rng, 0.3);
    cases.push_back(
        {pr.start, pr.target, profile_problems::random_end_velocity(rng, pr.limits), pr.limits});
  }
  long planned = 0;
  ca::g_allocations = 0;
  ca::g_counting = true;
  for (const Case& c : cases) {
    const nc::Profile prof = nc::plan_position(c.start, c.target, c.v_end, c.limits);
    planned += prof.ok() ? 1 : 0;
  }
  ca::g_counting = false;
  CHECK(ca::g_allocations == 0);
  CHECK(planned == static_cast<long>(cases.size()) - 1);  // every case but P9's
}
