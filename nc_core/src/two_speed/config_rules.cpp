// The rules between the two-speed fields of AxisConfig (SPEC E, seed 004), checked by validate()
// for a kTwoSpeed axis after every field has passed its own range.
#include <cmath>
#include <string>
#include <string_view>

#include "config_text.hpp"
#include "nc_core/config.hpp"

namespace nc {

namespace {

// The planner's numeric range (profile/validate.hpp kMaxLimit), which bounds every velocity a
// servo axis can be commanded.
constexpr double kMaxTwoSpeedVelocity = 1e12;

// `lower` (at `lower_key`) must not exceed `upper` (named `upper_key`).
void require_at_most(std::string_view lower_key, double lower, std::string_view upper_key,
                     double upper) {
  if (lower <= upper) return;
  throw ConfigError(config_text::child("", lower_key),
                    "must be <= " + std::string(upper_key) + " (" + config_text::number(upper) +
                        ") on a two-speed axis",
                    config_text::number(lower));
}

}  // namespace

void validate_two_speed(const AxisConfig& c) {
  // The creep phase lies between the creep and the braking distance (seed 004, example 1).
  require_at_most("braking_distance_positive", c.braking_distance_positive,
                  "creep_distance_positive", c.creep_distance_positive);
  require_at_most("braking_distance_negative", c.braking_distance_negative,
                  "creep_distance_negative", c.creep_distance_negative);
  require_at_most("creep_velocity", c.creep_velocity, "rapid_velocity", c.rapid_velocity);
  // The plant moves at rapid_velocity without a planner's range check; above the NC's numeric
  // range its position and its acceleration over a step (ramp time 0) overflow (fuzz finding K11).
  if (!(c.rapid_velocity <= kMaxTwoSpeedVelocity)) {
    throw ConfigError("/rapid_velocity",
                      "must be <= " + config_text::number(kMaxTwoSpeedVelocity) +
                          " (the NC's numeric range) on a two-speed axis",
                      config_text::number(c.rapid_velocity));
  }
  // The return leg of a looping positioning starts at most one braking distance short of the
  // reversal point; it must still be longer than its own braking distance.
  const double both = c.braking_distance_positive + c.braking_distance_negative;
  if (c.looping_distance_enabled && !(std::abs(c.looping_distance) > both)) {
    throw ConfigError("/looping_distance",
                      "|looping_distance| must be > braking_distance_positive + "
                      "braking_distance_negative (" +
                          config_text::number(both) + ") when looping_distance_enabled",
                      config_text::number(c.looping_distance));
  }
}

}  // namespace nc
