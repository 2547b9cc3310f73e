// The compensation trapezoid (nc_core/trapezoid.hpp; seed 000 §2.5, SPEC B7): extra distance D
// over the whole time T = L / VP with a 3-phase velocity trapezoid (ramp AK+, hold at most VK,
// ramp AK-; mirrored for D < 0), the largest feasible D when D does not fit, compensation stop.
// Numbers from the seed's three figures: base move 0 → 10000 mm at V = VP = 2000 mm/s,
// AK+ 500, AK- 1000 mm/s².
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "nc_core/trapezoid.hpp"
#include "profile_problems.hpp"

namespace {

using nc::ErrorCode;
using nc::KinematicState;
using nc::Trapezoid;

constexpr double kVp = 2000.0;
constexpr double kAkPlus = 500.0;
constexpr double kAkMinus = 1000.0;

// The largest |D| a trapezoid can add over T, written independently of the implementation: the
// triangle with slopes r1, r2 peaks at T·r1·r2/(r1 + r2) and covers half its peak times T; a
// lower peak VK is held for T - VK/r1 - VK/r2 and covers VK·(T - VK/(2 r1) - VK/(2 r2)).
double largest_distance(double T, double vk, double r1, double r2) {
  const double triangle_peak = T * r1 * r2 / (r1 + r2);
  if (vk >= triangle_peak) return 0.5 * triangle_peak * T;
  return vk * (T - 0.5 * vk / r1 - 0.5 * vk / r2);
}

// Checks what every trapezoid must satisfy: spans T, ends at distance() at rest, the peak within
// VK, the slopes exactly AK+ / AK- in the right order, continuous at the phase boundaries.
void check_shape(const Trapezoid& z, double T, double vk, double ak_plus, double ak_minus) {
  REQUIRE(z.ok());
  if (z.distance() == 0.0) return;
  const double sign = z.distance() > 0.0 ? 1.0 : -1.0;
  const double open = sign > 0.0 ? ak_plus : ak_minus;
  const double close = sign > 0.0 ? ak_minus : ak_plus;
  CHECK(z.duration() == Approx(T).epsilon(1e-12));
  CHECK(std::fabs(z.peak_velocity()) <= vk * (1.0 + 1e-12));
  CHECK(sign * z.peak_velocity() > 0.0);
  CHECK(z.ramp_up_time() == Approx(std::fabs(z.peak_velocity()) / open).epsilon(1e-12));
  CHECK(z.ramp_down_time() == Approx(std::fabs(z.peak_velocity()) / close).epsilon(1e-12));
  // Phases: accelerations exactly the slopes, the hold at the peak.
  const double t1 = z.ramp_up_time();
  const double t2 = z.hold_time();
  const double t3 = z.ramp_down_time();
  CHECK(z.at(0.5 * t1).a == sign * open);
  CHECK(z.at(t1 + t2 + 0.5 * t3).a == -sign * close);
  if (t2 > 0.0) {
    CHECK(z.at(t1 + 0.5 * t2).v == z.peak_velocity());
    CHECK(z.at(t1 + 0.5 * t2).a == 0.0);
  }
  // The covered distance is the trapezoid's area.
  const double area = z.peak_velocity() * (0.5 * t1 + t2 + 0.5 * t3);
  CHECK(z.distance() == Approx(area).epsilon(1e-9));
  // End exact and at rest; before the start nothing.
  const KinematicState end = z.at(z.duration());
  CHECK(end.p == z.distance());
  CHECK(end.v == 0.0);
  CHECK(end.a == 0.0);
  CHECK(z.at(z.duration() + 10.0).p == z.distance());
  CHECK(z.at(-1.0).p == 0.0);
  CHECK(z.at(0.0).v == 0.0);
  // Continuity at the phase boundaries: p and v agree from both sides to rounding.
  const double eps = 1e-9 * T;
  for (double tb : {t1, t1 + t2}) {
    if (tb <= eps || tb >= T - eps) continue;
    const KinematicState before = z.at(tb - eps);
    const KinematicState after = z.at(tb + eps);
    CHECK(after.p - before.p == Approx(2.0 * eps * z.peak_velocity()).margin(1e-9 * vk * T));
    CHECK(after.v == Approx(before.v).margin(2.0 * eps * std::max(open, close) + 1e-12 * vk));
  }
  // The velocity never has the wrong sign (no motion reversal of the extra motion itself).
  for (int k = 0; k <= 100; ++k)
    CHECK(sign * z.at(T * k / 100.0).v >= 0.0);
}

}  // namespace

TEST_CASE("full compensation: D 250 over L 5000 at VP 2000 is reached exactly (end 10250 mm)",
          "[trapezoid]") {
  // T = 5000 / 2000 = 2.5 s; D(vp) = vp·T - vp²·(1/500 + 1/1000)/2 = 250 at
  // vp = 106.85017607655433 < VK 300.
  const double T = 5000.0 / kVp;
  const Trapezoid z = Trapezoid::plan(250.0, T, 300.0, kAkPlus, kAkMinus);
  check_shape(z, T, 300.0, kAkPlus, kAkMinus);
  CHECK(z.complete());
  CHECK(z.distance() == 250.0);
  CHECK(10000.0 + z.at(T).p == 10250.0);
  CHECK(z.peak_velocity() == Approx(106.85017607655433).epsilon(1e-12));
  CHECK(z.ramp_up_time() == Approx(0.21370035215310867).epsilon(1e-12));
  CHECK(z.ramp_down_time() == Approx(0.10685017607655434).epsilon(1e-12));
}

TEST_CASE("partial compensation: D 500 over L 2000 gives the largest feasible D (near 10165 mm)",
          "[trapezoid]") {
  // T = 1 s: even the triangle (peak T/(1/500 + 1/1000) = 333.3 < VK 500) covers only
  // 333.3·1/2 = 166.67 mm. The seed's figure shows 10165 mm (its ramps run in whole cycles).
  const double T = 2000.0 / kVp;
  const Trapezoid z = Trapezoid::plan(500.0, T, 500.0, kAkPlus, kAkMinus);
  check_shape(z, T, 500.0, kAkPlus, kAkMinus);
  CHECK_FALSE(z.complete());
  CHECK(z.requested_distance() == 500.0);
  CHECK(z.distance() == Approx(166.66666666666666).epsilon(1e-12));
  CHECK(z.distance() == Approx(largest_distance(T, 500.0, kAkPlus, kAkMinus)).epsilon(1e-12));
  CHECK(std::fabs(10000.0 + z.distance() - 10165.0) < 2.0);
  CHECK(z.hold_time() == Approx(0.0).margin(1e-12));
  CHECK(z.peak_velocity() == Approx(1000.0 / 3.0).epsilon(1e-12));
}

TEST_CASE("a D that needs more than VK is cut to what VK allows over T", "[trapezoid]") {
  // T 2.5 s, VK 300: at most 300·(2.5 - 0.3 - 0.15) = 615 mm.
  const Trapezoid z = Trapezoid::plan(1000.0, 2.5, 300.0, kAkPlus, kAkMinus);
  check_shape(z, 2.5, 300.0, kAkPlus, kAkMinus);
  CHECK_FALSE(z.complete());
  CHECK(z.distance() == Approx(615.0).epsilon(1e-12));
  CHECK(z.peak_velocity() == Approx(300.0).epsilon(1e-12));
  CHECK(z.hold_time() == Approx(2.5 - 0.6 - 0.3).epsilon(1e-12));
}

TEST_CASE("negative compensation opens with AK- and closes with AK+ (end 9750 mm)", "[trapezoid]") {
  // Seed 000 §2.5 note 4: D < 0 starts with the deceleration increase. Same k, same |vp|.
  const double T = 5000.0 / kVp;
  const Trapezoid z = Trapezoid::plan(-250.0, T, 300.0, kAkPlus, kAkMinus);
  check_shape(z, T, 300.0, kAkPlus, kAkMinus);
  CHECK(z.complete());
  CHECK(z.distance() == -250.0);
  CHECK(10000.0 + z.at(T).p == 9750.0);
  CHECK(z.at(0.05).a == -kAkMinus);
  CHECK(z.at(T - 0.05).a == kAkPlus);
  CHECK(z.peak_velocity() == Approx(-106.85017607655433).epsilon(1e-12));
  // Infeasible the other way: cut to -615.
  const Trapezoid cut = Trapezoid::plan(-1000.0, 2.5, 300.0, kAkPlus, kAkMinus);
  check_shape(cut, 2.5, 300.0, kAkPlus, kAkMinus);
  CHECK(cut.distance() == Approx(-615.0).epsilon(1e-12));
}

TEST_CASE("D = 0 gives an empty compensation", "[trapezoid]") {
  const Trapezoid z = Trapezoid::plan(0.0, 2.5, 300.0, kAkPlus, kAkMinus);
  REQUIRE(z.ok());
  CHECK(z.complete());
  CHECK(z.distance() == 0.0);
  CHECK(z.at(1.0).p == 0.0);
  CHECK(z.at(1.0).v == 0.0);
}

TEST_CASE("random trapezoids span T, reach D or the largest feasible D, within VK and the slopes",
          "[trapezoid]") {
  profile_problems::Rng rng(0x7AAB5ull);
  long wrong = 0;
  for (int k = 0; k < 20000; ++k) {
    const double T = rng.log_uniform(1e-3, 1e3);
    const double vk = rng.log_uniform(1e-2, 1e5);
    const double ap = rng.log_uniform(1e-1, 1e7);
    const double am = rng.chance(0.3) ? ap : rng.log_uniform(1e-1, 1e7);
    const double d = rng.sign() * rng.log_uniform(1e-6, 1e5);
    const Trapezoid z = Trapezoid::plan(d, T, vk, ap, am);
    const double r1 = d > 0.0 ? ap : am;
    const double r2 = d > 0.0 ? am : ap;
    const double d_max = largest_distance(T, vk, r1, r2);
    const double expected = std::fabs(d) <= d_max ? d : std::copysign(d_max, d);
    const double t1 = z.ramp_up_time();
    const double t2 = z.hold_time();
    const double t3 = z.ramp_down_time();
    const double area = z.peak_velocity() * (0.5 * t1 + t2 + 0.5 * t3);
    const char* failed = nullptr;
    const double peak = std::fabs(z.peak_velocity());
    if (!z.ok()) {
      failed = "not ok";
    } else if (std::fabs(z.distance() - expected) > 1e-9 * std::fabs(expected)) {
      failed = "distance";
    } else if (std::fabs(area - z.distance()) > 1e-9 * std::fabs(z.distance())) {
      failed = "area";
    } else if (std::fabs(z.duration() - T) > 1e-12 * T) {
      failed = "duration";
    } else if (peak > vk * (1.0 + 1e-12)) {
      failed = "peak above VK";
    } else if (std::fabs(t1 * r1 - peak) > 1e-12 * peak ||
               std::fabs(t3 * r2 - peak) > 1e-12 * peak) {
      failed = "slopes";
    } else if (z.at(z.duration()).p != z.distance() || z.at(z.duration()).v != 0.0) {
      failed = "end state";
    } else if (std::fabs(std::fabs(d) - d_max) > 1e-9 * d_max &&
               z.complete() != (std::fabs(d) < d_max)) {
      failed = "complete()";
    }
    if (failed != nullptr && wrong++ < 5) {
      char buf[320];
      std::snprintf(buf, sizeof buf,
                    "%s: D=%.17g T=%.17g VK=%.17g AK+=%.17g AK-=%.17g: planned %.17g, expected "
                    "%.17g",
                    failed, d, T, vk, ap, am, z.distance(), expected);
      FAIL_CHECK(buf);
    }
  }
  CHECK(wrong == 0);
}

TEST_CASE("compensation stop ramps down at once and replaces D by what was done", "[trapezoid]") {
  const double T = 2.5;
  const Trapezoid z = Trapezoid::plan(250.0, T, 300.0, kAkPlus, kAkMinus);
  REQUIRE(z.ok());
  const double vp = z.peak_velocity();

  SECTION("stop during the hold") {
    const Trapezoid s = z.stopped_at(1.0);
    REQUIRE(s.ok());
    // Ramp down from vp at AK- from t = 1: ends at 1 + vp/1000.
    CHECK(s.duration() == Approx(1.0 + vp / kAkMinus).epsilon(1e-12));
    const double done =
        0.5 * vp * (vp / kAkPlus) + vp * (1.0 - vp / kAkPlus) + 0.5 * vp * (vp / kAkMinus);
    CHECK(s.distance() == Approx(done).epsilon(1e-12));
    CHECK_FALSE(s.complete());
    CHECK(s.at(s.duration()).p == s.distance());
    // Identical to the original up to the stop, then braking at once.
    CHECK(s.at(0.5).p == Approx(z.at(0.5).p).epsilon(1e-12));
    CHECK(s.at(0.999).v == Approx(vp).epsilon(1e-12));
    CHECK(s.at(1.0 + 1e-6).a == -kAkMinus);
  }
  SECTION("stop during the opening ramp") {
    // At t = 0.1 the velocity is 50: ramp down 0.05 s; done 0.5·50·0.1 + 0.5·50·0.05 = 3.75 mm.
    const Trapezoid s = z.stopped_at(0.1);
    REQUIRE(s.ok());
    CHECK(s.peak_velocity() == Approx(50.0).epsilon(1e-12));
    CHECK(s.duration() == Approx(0.15).epsilon(1e-12));
    CHECK(s.distance() == Approx(3.75).epsilon(1e-12));
    CHECK(s.at(1.0).p == s.distance());
  }
  SECTION("no effect in the braking phase or before the start") {
    for (double t : {T - 0.5 * z.ramp_down_time(), 0.0, -1.0}) {
      const Trapezoid s = z.stopped_at(t);
      CHECK(s.distance() == z.distance());
      CHECK(s.duration() == z.duration());
      CHECK(s.complete());
    }
  }
}

TEST_CASE("invalid compensation parameters are refused with their own codes", "[trapezoid]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto refused = [](const Trapezoid& z, ErrorCode code) {
    CHECK_FALSE(z.ok());
    CHECK(z.error() == code);
    const KinematicState x = z.at(1.0);
    CHECK(std::isfinite(x.p));
    CHECK(std::isfinite(x.v));
    CHECK(std::isfinite(x.a));
  };
  for (double bad : {nan, inf, -inf}) {
    refused(Trapezoid::plan(bad, 2.5, 300.0, kAkPlus, kAkMinus), ErrorCode::kPositionNotFinite);
    refused(Trapezoid::plan(250.0, bad, 300.0, kAkPlus, kAkMinus), ErrorCode::kParameterNotFinite);
    refused(Trapezoid::plan(250.0, 2.5, bad, kAkPlus, kAkMinus), ErrorCode::kParameterNotFinite);
    refused(Trapezoid::plan(250.0, 2.5, 300.0, bad, kAkMinus), ErrorCode::kParameterNotFinite);
    refused(Trapezoid::plan(250.0, 2.5, 300.0, kAkPlus, bad), ErrorCode::kParameterNotFinite);
  }
  for (double bad : {0.0, -1.0}) {
    refused(Trapezoid::plan(250.0, bad, 300.0, kAkPlus, kAkMinus),
            ErrorCode::kCompensationLengthInvalid);
    refused(Trapezoid::plan(250.0, 2.5, bad, kAkPlus, kAkMinus),
            ErrorCode::kCompensationVelocityInvalid);
    refused(Trapezoid::plan(250.0, 2.5, 300.0, bad, kAkMinus),
            ErrorCode::kCompensationAccelerationInvalid);
    refused(Trapezoid::plan(250.0, 2.5, 300.0, kAkPlus, bad),
            ErrorCode::kCompensationAccelerationInvalid);
  }
}
