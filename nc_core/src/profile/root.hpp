// A bracketed root finder for the planner's monotone one-dimensional equations (internal).
#pragma once

#include <cfloat>
#include <cmath>

namespace nc::detail {

// Brent's method on [lo, hi] with f(lo) = f_lo, f(hi) = f_hi of opposite sign (or one zero):
// inverse quadratic / secant steps guarded by bisection, until the bracket is a few ulp wide or
// |f| <= f_tol (the rounding level of f).
template <class F>
double find_root(F&& f, double lo, double hi, double f_lo, double f_hi, double f_tol) noexcept {
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  if ((f_lo > 0.0) == (f_hi > 0.0)) return std::abs(f_lo) < std::abs(f_hi) ? lo : hi;
  double a = lo, fa = f_lo, b = hi, fb = f_hi;
  double c = a, fc = fa, d = b - a, e = d;
  for (int iter = 0; iter < 400; ++iter) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * DBL_EPSILON * std::abs(b) + DBL_MIN;
    const double m = 0.5 * (c - b);
    if (std::abs(m) <= tol || std::abs(fb) <= f_tol) return b;
    if (std::abs(e) < tol || std::abs(fa) <= std::abs(fb)) {
      d = m;
      e = m;
    } else {
      const double s = fb / fa;
      double p, q;
      if (a == c) {
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {
        const double qq = fa / fc, r = fb / fc;
        p = s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0));
        q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) {
        q = -q;
      } else {
        p = -p;
      }
      if (2.0 * p < std::fmin(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (m > 0.0 ? tol : -tol);
    fb = f(b);
  }
  return b;
}

}  // namespace nc::detail

namespace nc::detail {

// A second-order root finder safeguarded by the bracket [lo, hi] (f(lo) < 0 < f(hi), f
// increasing), from x: `fd(x)` returns f, f', f'' and the rounding level of f (a RootPoint). Each
// step solves the local quadratic model (exact for the quadratic pieces of the stop point, fast
// where Newton crawls on strongly curved pieces); steps leaving the bracket become bisections.
// Ends when |f| is at its rounding level or the bracket is a few ulp wide.
struct RootPoint {
  double f = 0.0;
  double df = 0.0;
  double ddf = 0.0;
  double tol = 0.0;
};

template <class FD>
double find_root_quadratic(FD&& fd, double lo, double hi, double x) noexcept {
  double last_step = 0.0;  // the previous model step (its model predicted f = 0 here)
  for (int iter = 0; iter < 100; ++iter) {
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
    if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
      step = 0.0;
    } else if (last_step != 0.0) {
      // The model's error shrinks with the cube of the step: |f| now is what the last model
      // missed by, so the next miss is about |f| (step / last_step)^3. Below the tolerance the
      // step is taken without checking it.
      const double r = std::abs(step / last_step);
      if (std::abs(y.f) * r * r * r <= 0.125 * y.tol) return next;
    }
    if (hi - lo <= 4.0 * DBL_EPSILON * std::abs(hi)) return next;
    last_step = step;
    x = next;
  }
  return x;
}

}  // namespace nc::detail
