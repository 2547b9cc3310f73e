#include "axis/monitors.hpp"

#include <algorithm>
#include <cmath>

namespace nc::detail {

namespace {
// Times given as whole multiples of T must map to exactly that many cycles despite rounding in
// the division.
constexpr double kCycleSlack = 1e-9;
}  // namespace

void Monitors::configure(const AxisConfig& config, double cycle_time) noexcept {
  fe_enabled_ = config.following_error_enabled;
  fe_limit_ = config.following_error_limit;
  fe_filter_cycles_ = static_cast<uint64_t>(
      std::floor(config.following_error_filter_time / cycle_time + kCycleSlack));
  fe_count_ = 0;

  tw_enabled_ = config.target_window_enabled;
  tw_window_ = config.target_window;
  tw_cycles_ = std::max<uint64_t>(
      1, static_cast<uint64_t>(std::ceil(config.target_window_time / cycle_time - kCycleSlack)));
  tw_count_ = 0;
  window_bits_ = 0;

  pr_enabled_ = config.position_range_enabled;
  pr_window_ = config.position_range_window;

  min_enabled_ = config.sw_limit_min_enabled;
  max_enabled_ = config.sw_limit_max_enabled;
  min_ = config.sw_limit_min;
  max_ = config.sw_limit_max;
  set_bounds();
}

}  // namespace nc::detail
