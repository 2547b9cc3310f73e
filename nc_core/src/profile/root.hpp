// The bracketed root finder for plan_position's switch time (internal).
#pragma once

#include <cfloat>
#include <cmath>

namespace nc::detail {

// A second-order root finder safeguarded by the bracket [lo, hi] (f(lo) < 0 < f(hi), f
// increasing), from x: `fd(x)` returns f, f', f'' and the rounding level of f (a RootPoint). Each
// step solves the local quadratic model (exact for the quadratic pieces of the stop point, fast
// where Newton crawls on strongly curved pieces). Where that model misleads (its step leaves the
// bracket, or |f| fell by less than 8x), f - f(lo) is taken as a power of x - lo, with the
// exponent read from f' (exact for c (x - lo)^n: the stop point grows like that from a piece's
// start, with n up to 4 from rest); bisection is the last resort. `f_lo` = f(lo) < 0. Ends when
// |f| is at its rounding level, the model's step is below two ulp of x, or the bracket is a few
// ulp wide.
struct RootPoint {
  double f = 0.0;
  double df = 0.0;
  double ddf = 0.0;
  double tol = 0.0;
};

// Past this many steps the search only bisects: a model step that keeps overshooting from the
// near end and a power-law step that keeps landing just past it (a function flat for a while
// before it rises, fuzz finding P20) would otherwise alternate until the step limit and return a
// point far from the root. A well-behaved root takes 2-4 steps (the random property suite at
// most 18); bisection then narrows any bracket to a few ulp within kRootSteps.
inline constexpr int kModelSteps = 64;
inline constexpr int kRootSteps = 200;

template <class FD>
double find_root_quadratic(FD&& fd, double lo, double hi, double x, double f_lo) noexcept {
  const double origin = lo;
  double last_step = 0.0;  // the previous model step (its model predicted f = 0 here)
  double last_f = 0.0;
  for (int iter = 0; iter < kRootSteps; ++iter) {
    const RootPoint y = fd(x);
    if (std::abs(y.f) <= y.tol) return x;
    if (y.f < 0.0) {
      lo = x;
    } else {
      hi = x;
    }
    double step;
    const double disc = y.df * y.df - 2.0 * y.f * y.ddf;
    if (y.df > 0.0 && disc >= 0.0) {
      step = -2.0 * y.f / (y.df + std::sqrt(disc));  // the model's root nearer to x
    } else if (y.df > 0.0) {
      step = -y.f / y.df;
    } else {
      step = 0.5 * (lo + hi) - x;
    }
    double next = x + step;
    const bool slow = last_f != 0.0 && std::abs(y.f) > 0.125 * std::abs(last_f);
    last_f = y.f;
    if (!(next > lo && next < hi) || slow) {
      // A model step below two ulp of x: x is the root to the resolution of x. Where the
      // positions are small against the excursion before the switch, f's tolerance lies below
      // the change of f per ulp of x; the step then rounded onto the bracket's end and the search
      // bisected until the bracket was a few ulp wide (45 of the random property suite's 414 497
      // roots took 33-53 steps; now at most 18).
      if (std::abs(step) <= 2.0 * DBL_EPSILON * std::abs(x)) return x;
      // f - f_lo = c (x - origin)^n with n = (x - origin) f' / (f - f_lo): its root.
      const double rise = y.f - f_lo;
      const double n = (x - origin) * y.df / rise;
      const double power =
          rise > 0.0 && n > 0.0 ? origin + (x - origin) * std::pow(-f_lo / rise, 1.0 / n) : NAN;
      if (power > lo && power < hi) {
        next = power;
      } else if (!(next > lo && next < hi)) {
        next = 0.5 * (lo + hi);
      }
      step = 0.0;  // not a model step: the next result is checked
    } else if (last_step != 0.0) {
      // The model's error shrinks with the cube of the step: |f| now is what the last model
      // missed by, so the next miss is about |f| (step / last_step)^3. Below the tolerance the
      // step is taken without checking it.
      const double r = std::abs(step / last_step);
      if (std::abs(y.f) * r * r * r <= 0.125 * y.tol) return next;
    }
    if (iter >= kModelSteps) {
      next = 0.5 * (lo + hi);
      step = 0.0;
    }
    if (hi - lo <= 4.0 * DBL_EPSILON * std::abs(hi)) return next;
    last_step = step;
    x = next;
  }
  return x;
}

}  // namespace nc::detail
