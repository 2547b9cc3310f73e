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
  in_target_ = false;

  pr_enabled_ = config.position_range_enabled;
  pr_window_ = config.position_range_window;
  in_area_ = false;

  min_enabled_ = config.sw_limit_min_enabled;
  max_enabled_ = config.sw_limit_max_enabled;
  min_ = config.sw_limit_min;
  max_ = config.sw_limit_max;
}

bool Monitors::following_error(double lag, bool armed) noexcept {
  if (!fe_enabled_ || !armed || !(std::abs(lag) > fe_limit_)) {
    fe_count_ = 0;
    return false;
  }
  ++fe_count_;
  return fe_count_ > fe_filter_cycles_;
}

void Monitors::windows(double actual, double target, bool settled) noexcept {
  if (!settled) {
    reset_windows();
    return;
  }
  const double distance = std::abs(actual - target);
  in_area_ = !pr_enabled_ || distance <= pr_window_;
  if (!tw_enabled_) {
    in_target_ = true;
    return;
  }
  if (distance <= tw_window_) {
    if (tw_count_ < tw_cycles_) ++tw_count_;
  } else {
    tw_count_ = 0;
  }
  in_target_ = tw_count_ >= tw_cycles_;
}

void Monitors::reset_windows() noexcept {
  tw_count_ = 0;
  in_target_ = false;
  in_area_ = false;
}

}  // namespace nc::detail
