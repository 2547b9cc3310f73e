// The rest-to-rest fast path of plan_position in closed form (internal). Accelerating to a peak vp
// with bound A and jerk J takes t(vp) = vp/A + A/J when vp >= A^2/J (the bound is reached) and 2
// sqrt(vp/J) otherwise; both halves are point-symmetric in velocity, so the distance up to vp and
// back is D(vp) = vp/2 (t+(vp) + t-(vp)), increasing in vp. If D(V) is not more than the distance
// the profile cruises at V; otherwise vp solves D(vp) = distance: a cube root when neither bound is
// reached, a quadratic when both are, and a quartic in sqrt(vp) (by Newton) in between.
//
// Header-only (issue 17): plan_position inlines it (rest to rest 704.7 -> 645.5 instructions per
// plan; the same operations, the same profiles bit for bit).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "profile/kinematics.hpp"

namespace nc::detail {
namespace rest_parts {

// The cube root of x > 0 within a few ulp, without libm's cbrt (issue 17: with its frexp and
// ldexp about 70 instructions of a rest-to-rest plan): the exponent divided by 3 in the bits gives
// a start within 3.2 %, three Halley steps y - y (y^3 - x) / (2y^3 + x) (cubic convergence; the
// ratio first, so that the correction does not underflow) the result: at most 4 ulp from
// std::cbrt over 2e7 values of x in [1e-300, 1e300]. Outside that range, std::cbrt.
inline double cube_root(double x) noexcept {
  if (!(x >= 1e-300 && x <= 1e300)) return std::cbrt(x);
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits = bits / 3 + 0x2A9F7893782DA1CEull;
  double y;
  std::memcpy(&y, &bits, sizeof y);
  for (int i = 0; i < 3; ++i) {
    const double y3 = y * y * y;
    y -= y * ((y3 - x) / (2.0 * y3 + x));
  }
  return y;
}

inline double ramp_time(double vp, double bound, double jerk) noexcept {
  return vp * jerk >= bound * bound ? vp / bound + bound / jerk : 2.0 * std::sqrt(vp / jerk);
}

inline double there_and_back(double vp, const Bounds& b) noexcept {
  return 0.5 * vp * (ramp_time(vp, b.ap, b.j) + ramp_time(vp, b.am, b.j));
}

inline double peak_velocity(double distance, const Bounds& b) noexcept {
  const double jerk = b.j;
  const double low = std::min(b.ap, b.am);
  const double high = std::max(b.ap, b.am);
  const double v_low = low * low / jerk;     // below it, neither bound is reached
  const double v_high = high * high / jerk;  // above it, both are
  if (distance <= there_and_back(v_low, b)) {
    return cube_root(0.25 * distance * distance * jerk);  // D = 2 vp^1.5 / sqrt(J)
  }
  if (distance >= there_and_back(v_high, b)) {
    // D = vp^2 (1/A+ + 1/A-) / 2 + vp (A+ + A-) / (2J)
    const double k = 1.0 / b.ap + 1.0 / b.am;
    const double h = 0.5 * (b.ap + b.am) / jerk;
    return 2.0 * distance / (h + std::sqrt(h * h + 2.0 * k * distance));
  }
  // Only the lower bound is reached: with u = sqrt(vp),
  // f(u) = u^4 / (2 low) + u^3 / sqrt(J) + u^2 low / (2J) - distance, increasing and convex for
  // u > 0, so Newton from the right of the root converges monotonically.
  const double c4 = 0.5 / low, c3 = 1.0 / std::sqrt(jerk), c2 = 0.5 * low / jerk;
  // Each term alone bounds the root from above; the smallest bound is within a small factor.
  double u = std::min({std::sqrt(v_high), std::sqrt(std::sqrt(2.0 * low * distance)),
                       cube_root(distance * std::sqrt(jerk)), std::sqrt(distance / c2)});
  for (int i = 0; i < 60; ++i) {
    const double u2 = u * u;
    const double f = u2 * (u * (c4 * u + c3) + c2) - distance;
    const double df = u * (u * (4.0 * c4 * u + 3.0 * c3) + 2.0 * c2);
    const double next = u - f / df;
    if (!(next < u)) break;
    u = next;
  }
  return u * u;
}

// The pieces of a velocity ramp 0 -> vp (sign +1) or vp -> 0 (sign -1) with bound A, handed to
// `put` in order.
template <class Put>
inline void ramp(double vp, double bound, double jerk, double sign, bool up,
                 const Put& put) noexcept {
  const double v_start = up ? 0.0 : vp;
  const double v_end = up ? vp : 0.0;
  const double dir = up ? 1.0 : -1.0;  // sign of a during the ramp
  if (vp * jerk >= bound * bound) {
    const double t = bound / jerk;
    put(Piece{t, sign * dir * jerk, sign * dir * bound, NAN});
    put(Piece{(vp - bound * bound / jerk) / bound, 0.0, sign * dir * bound, NAN});
    put(Piece{t, -sign * dir * jerk, 0.0, sign * v_end});
  } else {
    const double t = std::sqrt(vp / jerk);
    put(Piece{t, sign * dir * jerk, sign * dir * jerk * t, sign * 0.5 * (v_start + v_end)});
    put(Piece{t, -sign * dir * jerk, 0.0, sign * v_end});
  }
}

}  // namespace rest_parts

// The time-optimal motion over `distance` from rest to rest (seed 000 §2.1's 7 phases): its peak
// velocity, then its pieces (at most 7) from up() and down(). The same profile as the general
// push-then-stop path.
class RestToRest {
 public:
  RestToRest(double distance, double velocity, const Bounds& bounds) noexcept
      : velocity_(velocity),
        bounds_(bounds),
        sign_(distance < 0.0 ? -1.0 : 1.0),
        d_(std::abs(distance)),
        d_max_(rest_parts::there_and_back(velocity, bounds)),
        vp_(d_ >= d_max_ ? velocity : std::min(rest_parts::peak_velocity(d_, bounds), velocity)) {}

  // The acceleration pieces, to `put` in order (issue 17: straight into the profile, not to an
  // array first).
  template <class Put>
  void up(const Put& put) const noexcept {
    rest_parts::ramp(vp_, bounds_.ap, bounds_.j, sign_, true, put);
  }
  // The cruise (where there is one) and the deceleration pieces.
  template <class Put>
  void down(const Put& put) const noexcept {
    if (d_ > d_max_) put(Piece{(d_ - d_max_) / velocity_, 0.0, 0.0, sign_ * velocity_});
    rest_parts::ramp(vp_, bounds_.am, bounds_.j, sign_, false, put);
  }

 private:
  double velocity_;
  Bounds bounds_;
  double sign_;
  double d_;
  double d_max_;
  double vp_;
};

}  // namespace nc::detail
