// std::floor and std::round for the per-cycle paths (encoder quantisation, modulo positions),
// without the library call the baseline x86-64 target makes for them. Bit-identical to the
// std functions for every input, the sign of zero included: the fast path runs for
// |x| < 2^52, where the conversion to int64_t truncates exactly; the rest (large, inf, NaN) goes
// to std. Cycle functions (inline, pure).
#pragma once

#include <cmath>
#include <cstdint>

namespace nc::detail {

inline constexpr double kExactIntegerLimit = 4503599627370496.0;  // 2^52

inline double floor_exact(double x) noexcept {
  if (!(std::abs(x) < kExactIntegerLimit)) return std::floor(x);
  double t = static_cast<double>(static_cast<int64_t>(x));
  if (t > x) t -= 1.0;
  return std::copysign(t, x);
}

// Half-way cases away from zero, as std::round.
inline double round_exact(double x) noexcept {
  if (!(std::abs(x) < kExactIntegerLimit)) return std::round(x);
  double t = static_cast<double>(static_cast<int64_t>(x));
  const double rest = x - t;  // exact below 2^52
  if (rest >= 0.5) {
    t += 1.0;
  } else if (rest <= -0.5) {
    t -= 1.0;
  }
  return std::copysign(t, x);
}

}  // namespace nc::detail
