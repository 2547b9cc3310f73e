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
//
// Where fd marks a point `quartic`, f is the polynomial of its four derivatives there (exactly, up
// to rounding) on a stretch around it: the search then solves that polynomial by Newton steps from
// the model's root, and returns the result without evaluating f again if `model_holds(root)` says
// the model gives f there to the root's tolerance (issue 17: a root on such a stretch took 2-3
// evaluations of ~150 instructions each).
struct RootPoint {
  double f = 0.0;
  double df = 0.0;
  double ddf = 0.0;
  double tol = 0.0;
  double d3 = 0.0;  // f''' (only where `quartic`)
  double d4 = 0.0;  // f'''' (only where `quartic`)
  bool quartic = false;
};

// A root of P(h) = f(x) + df h + ddf h^2 / 2 + d3 h^3 / 6 + d4 h^4 / 24 by Newton steps from `h`
// (the quadratic model's root): the first h where |P| is within half f's rounding level, or NaN
// if the steps do not get there on an increasing stretch.
inline double quartic_step(const RootPoint& y, double h) noexcept {
  const double c2 = 0.5 * y.ddf;
  const double c3 = y.d3 * (1.0 / 6.0);
  const double c4 = y.d4 * (1.0 / 24.0);
  for (int k = 0; k < 8; ++k) {
    const double p = y.f + h * (y.df + h * (c2 + h * (c3 + h * c4)));
    if (std::abs(p) <= 0.5 * y.tol) return h;
    const double dp = y.df + h * (2.0 * c2 + h * (3.0 * c3 + h * (4.0 * c4)));
    if (!(dp > 0.0)) return NAN;
    h -= p / dp;
  }
  return NAN;
}

// Past this many steps the search only bisects: a model step that keeps overshooting from the
// near end and a power-law step that keeps landing just past it (a function flat for a while
// before it rises, fuzz finding P20) would otherwise alternate until the step limit and return a
// point far from the root. A well-behaved root takes 2-4 steps (the random property suite at
// most 18); bisection then narrows any bracket to a few ulp within kRootSteps.
inline constexpr int kModelSteps = 64;
inline constexpr int kRootSteps = 200;

template <class FD, class ModelHolds>
double find_root_quadratic(FD&& fd, ModelHolds&& model_holds, double lo, double hi, double x,
                           double f_lo) noexcept {
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
    if (y.quartic) {
      const double h = quartic_step(y, step);
      const double root = x + h;
      if (root > lo && root < hi && model_holds(root)) return root;
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
