// The position controller of a continuous servo axis (SPEC A3): P controller with velocity
// feed-forward, v_cmd = ff · v_ff + Kv · (p_set - p_act).
//
// Sampled like a real NC: at the start of a cycle the controller knows the actual (encoder)
// position and the set position of the previous cycle, and the set position for the end of this
// cycle. Its command holds for the cycle, so the feed-forward velocity is the mean set velocity
// over the cycle, (p_set[k] - p_set[k-1]) / T: with an ideal drive and ff = 1 the actual position
// then follows the set position to within the encoder increment, with no lag from the sampling.
// Cycle function (pure, inline).
#pragma once

namespace nc::detail {

struct PositionController {
  double kv = 1.0;            // 1/s
  double feed_forward = 1.0;  // 0 … 1

  double command(double set_previous, double set_now, double actual_previous,
                 double cycle_time) const noexcept {
    const double mean_set_velocity = (set_now - set_previous) / cycle_time;
    return feed_forward * mean_set_velocity + kv * (set_previous - actual_previous);
  }
};

}  // namespace nc::detail
