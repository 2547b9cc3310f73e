// NcToPlc's modulo positions (ModuloActPos, ModuloSetPos; phase (f), servo_axis.cpp): the formula,
// and the period a position is in kept from cycle to cycle, so that a steady cycle does not divide.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "axis/rounding.hpp"

namespace nc::detail {

// p modulo `factor` in [0, factor). `factor` is finite and > 0 (AxisConfig validation).
inline double modulo_position(double p, double factor) noexcept {
  // Within the first period the formula gives p itself (floor 0; p + 0.0 as it turns -0.0 into
  // +0.0): no division.
  if (p >= 0.0 && p < factor) return p + 0.0;
  double m = p - factor * floor_exact(p / factor);
  if (m >= factor || m < 0.0) m = 0.0;  // rounding at the period edge
  return m;
}

// modulo_position() bit for bit, with the division only when the position leaves the interval
// of the last call. floor(p / factor) never falls as p rises (the division is correctly rounded
// and factor > 0), so the positions with the same floor k are an interval, and within it the
// formula is p − factor · k, which never falls either: where that stays in [0, factor) (no rounding
// at the period's edges) the formula is p + offset with offset = −(factor · k), an exact rewrite of
// the subtraction. The first period is [0, factor) with offset +0.0 (the formula's own case,
// p + 0.0). An interval's edges come from k · factor and (k + 1) · factor, checked with the
// division and, where they are off, found to the last double by halving. A non-finite position
// and one at a rounded edge keep no interval. One per position kind and axis; `factor` the same
// in every call (the axis's).
class ModuloPeriod {
 public:
  double position(double p, double factor) noexcept {
    if (p >= lo_ && p < hi_) return p + offset_;
    return enter(p, factor);
  }

 private:
  // The doubles' order as integers (−0.0 and +0.0 both 0), and back.
  static int64_t order(double x) noexcept {
    const auto bits = std::bit_cast<int64_t>(x);
    return bits < 0 ? -(bits & std::numeric_limits<int64_t>::max()) : bits;
  }
  static double from_order(int64_t i) noexcept {
    return i < 0 ? std::bit_cast<double>((-i) | std::numeric_limits<int64_t>::min())
                 : std::bit_cast<double>(i);
  }
  // The first double in (below, above] for which `holds` (monotone: false at `below`, true at
  // `above`). The edge is mostly a few doubles from one end: steps doubling from both ends find
  // a bracket around it first, then halving.
  template <typename Holds>
  static double first(double below, double above, Holds holds) noexcept {
    int64_t lo = order(below);
    int64_t hi = order(above);
    const auto width = [&] { return static_cast<uint64_t>(hi) - static_cast<uint64_t>(lo); };
    for (int64_t step = 1; width() > 2U * static_cast<uint64_t>(step); step *= 2) {
      if (holds(from_order(lo + step))) {
        hi = lo + step;
        break;
      }
      lo += step;
      if (!holds(from_order(hi - step))) {
        lo = hi - step;
        break;
      }
      hi -= step;
    }
    while (width() > 1U) {
      const int64_t mid = lo + static_cast<int64_t>(width() / 2U);
      (holds(from_order(mid)) ? hi : lo) = mid;
    }
    return from_order(hi);
  }

  // p left the interval: the formula, and the interval p is in (rare: out of the cycle's path).
  [[gnu::cold, gnu::noinline]] double enter(double p, double factor) noexcept {
    const double m = modulo_position(p, factor);
    lo_ = 0.0;
    hi_ = 0.0;  // empty unless set below
    offset_ = 0.0;
    if (p >= 0.0 && p < factor) {
      hi_ = factor;
      return m;
    }
    const double k = floor_exact(p / factor);
    const double c = factor * k;
    if (!std::isfinite(k) || p - c < 0.0 || p - c >= factor) return m;
    const auto at_least_k = [&](double q) { return floor_exact(q / factor) >= k; };
    const auto above_k = [&](double q) { return floor_exact(q / factor) > k; };
    const double inf = std::numeric_limits<double>::infinity();
    // [lo, hi) holds p (c <= p); every position between two of period k is of period k.
    double lo = c;
    if (!at_least_k(lo)) lo = first(lo, p, at_least_k);
    double hi = std::max((k + 1.0) * factor, std::nextafter(p, inf));
    if (above_k(hi)) hi = first(p, hi, above_k);
    const double last = std::nextafter(hi, -inf);
    if (last - c >= factor) hi = first(p, last, [&](double q) { return q - c >= factor; });
    lo_ = lo;
    hi_ = hi;
    offset_ = -c;
    return m;
  }

  double lo_ = 0.0;  // [lo_, hi_): p + offset_ is the formula; empty at first
  double hi_ = 0.0;
  double offset_ = 0.0;
};

}  // namespace nc::detail
