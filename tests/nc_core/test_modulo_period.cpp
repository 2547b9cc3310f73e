// The published modulo positions keep the period of the last cycle (ModuloPeriod,
// nc_core/src/axis/modulo_period.hpp) instead of dividing in every cycle: they must stay
// modulo_position()'s formula bit for bit, whatever position came before — at and around the
// period edges (a few doubles either side of k · factor), around 0 and the factor, for negative,
// huge and non-finite positions, and factors that are not powers of two.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "axis/modulo_period.hpp"

namespace {

bool same_bits(double a, double b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
}

// Every position in turn through one ModuloPeriod; the number that differ from the formula.
long mismatches(const std::vector<double>& positions, double factor) {
  nc::detail::ModuloPeriod period;
  long count = 0;
  for (const double p : positions) {
    const double expected = nc::detail::modulo_position(p, factor);
    if (!same_bits(period.position(p, factor), expected)) {
      UNSCOPED_INFO("factor " << factor << ", position " << p);
      ++count;
    }
  }
  return count;
}

// `x` and the `ulps` doubles either side of it.
void add_around(std::vector<double>& out, double x, int ulps) {
  const double inf = std::numeric_limits<double>::infinity();
  out.push_back(x);
  double up = x;
  double down = x;
  for (int i = 0; i < ulps; ++i) {
    up = std::nextafter(up, inf);
    down = std::nextafter(down, -inf);
    out.push_back(up);
    out.push_back(down);
  }
}

const double kFactors[] = {360.0, 0.1, 7.3, 1.0 / 3.0, 0.25, 1e-3, 1e9, 2.0 * std::numbers::pi};

std::vector<double> edge_positions(double factor) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> values;
  const double turns[] = {-1e6, -1000.0, -3.0, -2.0, -1.0, 1.0, 2.0, 3.0, 17.0, 1000.0, 1e6, 3e15};
  for (const double k : turns) {
    add_around(values, k * factor, 6);
    add_around(values, (k + 0.5) * factor, 2);
  }
  add_around(values, 0.0, 6);  // the denormals either side, and -0.0
  values.push_back(-0.0);
  add_around(values, factor, 6);
  add_around(values, -factor, 6);
  add_around(values, 0.5 * factor, 2);
  add_around(values, 1e300, 2);
  add_around(values, -1e300, 2);
  add_around(values, std::numeric_limits<double>::max(), 2);
  add_around(values, std::numeric_limits<double>::lowest(), 2);
  add_around(values, -1e-300, 2);
  values.push_back(inf);
  values.push_back(-inf);
  values.push_back(std::numeric_limits<double>::quiet_NaN());
  return values;
}

}  // namespace

TEST_CASE("the kept modulo period gives the formula at and around the period edges", "[modulo]") {
  for (const double factor : kFactors) {
    std::vector<double> values = edge_positions(factor);
    std::sort(values.begin(), values.end(), [](double a, double b) {
      return std::isnan(b) ? !std::isnan(a) : (!std::isnan(a) && a < b);
    });
    // Rising, falling (each position after its neighbour, so after its interval was kept) and
    // in a random order (after a position anywhere).
    CHECK(mismatches(values, factor) == 0);
    std::reverse(values.begin(), values.end());
    CHECK(mismatches(values, factor) == 0);
    std::mt19937_64 rng(20261128);  // fixed seed
    std::shuffle(values.begin(), values.end(), rng);
    CHECK(mismatches(values, factor) == 0);
  }
}

TEST_CASE("the kept modulo period gives the formula along random walks", "[modulo]") {
  std::mt19937_64 rng(8);  // fixed seed
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const double factor : kFactors) {
    for (const double step : {1e-9, 1e-3, 0.3, 2.0, 50.0}) {
      // Steps of up to `step` periods from a few periods below 0, and a slow drift across the
      // edges; every position also a few doubles off.
      std::vector<double> positions;
      double p = -3.5 * factor;
      for (int i = 0; i < 20'000; ++i) {
        p += step * factor * unit(rng);
        if (i % 7 == 0) p = std::round(p / factor) * factor;  // onto an edge now and then
        positions.push_back(p);
        if (i % 5 == 0) add_around(positions, p, 2);
      }
      CHECK(mismatches(positions, factor) == 0);
    }
  }
}
