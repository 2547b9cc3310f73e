// The per-cycle floor and round of nc_core (encoder quantisation, modulo positions) are bit for
// bit std::floor and std::round — the sign of zero, the half-way cases, the edges at 2^52, inf
// and NaN included — so the faster cycle publishes exactly what it published before.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "../../nc_core/src/axis/rounding.hpp"

namespace {

bool same_bits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
}

}  // namespace

TEST_CASE("floor_exact and round_exact equal std::floor and std::round on special values",
          "[rounding]") {
  const double inf = std::numeric_limits<double>::infinity();
  const double values[] = {0.0,
                           -0.0,
                           0.3,
                           -0.3,
                           0.5,
                           -0.5,
                           1.5,
                           -1.5,
                           2.5,
                           -2.5,
                           1.0,
                           -1.0,
                           0.49999999999999994,
                           -0.49999999999999994,
                           4503599627370495.5,
                           -4503599627370495.5,
                           4503599627370496.0,
                           -4503599627370497.0,
                           1e300,
                           -1e300,
                           1e-300,
                           -1e-300,
                           inf,
                           -inf,
                           std::numeric_limits<double>::quiet_NaN()};
  for (const double x : values) {
    INFO(x);
    REQUIRE(same_bits(nc::detail::floor_exact(x), std::floor(x)));
    REQUIRE(same_bits(nc::detail::round_exact(x), std::round(x)));
  }
}

TEST_CASE("floor_exact and round_exact equal std::floor and std::round on random values",
          "[rounding]") {
  std::mt19937_64 rng(20261123);  // fixed seed
  long mismatches = 0;
  for (int i = 0; i < 2'000'000; ++i) {
    double x = 0.0;
    if (i % 2 == 0) {
      const uint64_t bits = rng();
      std::memcpy(&x, &bits, sizeof x);  // any double
    } else {
      const double unit = static_cast<double>(static_cast<int64_t>(rng())) / 9.2e18;
      x = std::ldexp(unit, static_cast<int>(rng() % 120) - 60);  // around the integers
    }
    if (!same_bits(nc::detail::floor_exact(x), std::floor(x)) ||
        !same_bits(nc::detail::round_exact(x), std::round(x))) {
      ++mismatches;
    }
  }
  REQUIRE(mismatches == 0);
}
