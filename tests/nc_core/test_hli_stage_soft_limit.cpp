// SPEC D4, 70195: a FRACT coupling on a referenced axis with software limits: when the drive
// could no longer stop before P-AXIS-00178 (00177) at the emergency deceleration P-AXIS-00003,
// the target gets 70195, its list goes off and the drive brakes — it comes to rest before the
// limit.
#include <catch2/catch.hpp>

#include "hli_stage_rig.hpp"

using namespace hlitest;

namespace {

constexpr double kDecel = 1000.0;  // mm/s²
constexpr double kLimit = 100.0;   // mm

Rig limited_rig(h::HLI_AX_COUPLING_DESC coupling, bool referenced) {
  nc::hli::AxisSetup s;
  s.emergency_deceleration = kDecel;
  s.sw_limit_min_enabled = true;
  s.sw_limit_max_enabled = true;
  s.sw_limit_min = -kLimit;
  s.sw_limit_max = kLimit;
  Rig rig({1, 8}, s);
  rig.referenced[1] = referenced;
  rig.command(1, {coupling, inactive()});
  rig.cycle();
  REQUIRE(rig.unit(1).state_r.error_r == 0);
  return rig;
}

struct Run {
  int errors = 0;
  double d_at_error = 0.0;
  double v_at_error = 0.0;
};

// Axis 1 runs at `v` for 2 s; counts the 70195 stops of the target.
Run drive(Rig& rig, double v) {
  Run r;
  for (int i = 0; i < 2000; ++i) {
    rig.q[0] += v * kT;
    rig.qv[0] = v;
    rig.cycle();
    if (rig.stop[1] == plc::ErrorCode::kHliFractOnReferencedAxis) {
      if (r.errors++ == 0) {
        r.d_at_error = rig.d[1];
        r.v_at_error = rig.dv[1];
      }
    }
  }
  return r;
}

}  // namespace

TEST_CASE("70195: FRACT 3/2 toward P-AXIS-00178 stops the drive before the limit", "[hli]") {
  Rig rig = limited_rig(fract(1, 3, 2), true);
  const Run r = drive(rig, 200.0);  // drive at 300 mm/s: 45 mm to stop
  REQUIRE(r.errors == 1);
  CHECK(r.v_at_error == Approx(300.0));
  CHECK(r.d_at_error + 45.0 <= kLimit);
  CHECK(r.d_at_error + 45.0 + 300.0 * kT > kLimit);  // not a cycle earlier than needed
  CHECK(rig.unit(1).state_r.error_r == 70195);
  CHECK_FALSE(rig.unit(1).state_r.active_r);
  CHECK(rig.dv[1] == 0.0);
  CHECK(rig.d[1] == Approx(r.d_at_error + 45.0).margin(1e-9));
  CHECK(rig.d[1] <= kLimit);
}

TEST_CASE("70195: MIRROR-like FRACT -1/1 toward P-AXIS-00177 stops before the limit", "[hli]") {
  Rig rig = limited_rig(fract(1, -1, 1), true);
  const Run r = drive(rig, 250.0);  // drive at -250 mm/s: 31.25 mm to stop
  REQUIRE(r.errors == 1);
  CHECK(rig.d[1] == Approx(r.d_at_error - 31.25).margin(1e-9));
  CHECK(rig.d[1] >= -kLimit);
}

TEST_CASE("no 70195 on an axis not referenced, nor for a DIRECT coupling", "[hli]") {
  {
    Rig rig = limited_rig(fract(1, 3, 2), false);
    CHECK(drive(rig, 200.0).errors == 0);
    CHECK(rig.d[1] == Approx(600.0).margin(1e-6));
  }
  Rig rig = limited_rig(direct(1), true);
  CHECK(drive(rig, 200.0).errors == 0);
}
