// Profile::at(t, jerk) inline (internal): a running job's table is sampled in every cycle of every
// moving axis (job_table.hpp), where the call cost about 10 instructions (docs/performance.md
// "Kernel cycle", "Sixth pass"). profile.cpp's at() and jerk_at() are these functions.
#pragma once

#include <algorithm>
#include <cstddef>

#include "nc_core/profile.hpp"
#include "profile/kinematics.hpp"

namespace nc::detail {

class ProfileSample {
 public:
  // Profile::at(t, jerk) (profile.hpp).
  static KinematicState at(const Profile& profile, double t, double& jerk) noexcept;
  // The segment holding t (0 < t < the end, count > 0): the last one with t0 <= t (the first when
  // none is), searched from `cursor` forwards or backwards and left there.
  static std::size_t find(const SegmentTable& segments, double t, std::size_t& cursor) noexcept;
  // The sample at t in segment i (the one find() gives for t), its jerk into `jerk`: at()'s last
  // step, which the steady lane (axis/steady_lane.hpp) takes alone while t stays in segment i.
  static KinematicState in_segment(const Profile& profile, std::size_t i, double t,
                                   double& jerk) noexcept;
  // The segment of the last sample (Profile::cursor_).
  static std::size_t cursor(const Profile& profile) noexcept { return profile.cursor_; }
  // Asks for the cache lines in_segment(profile, i, …) reads: segment i and the next one's t0 to
  // a, or the final state after the last (three addresses, each less than a line from the last).
  [[gnu::always_inline]] static void prefetch_segment(const Profile& profile,
                                                      std::size_t i) noexcept {
    const Segment* segment = &profile.segments_.items[i];
    __builtin_prefetch(segment);
    __builtin_prefetch(segment + 1);
    __builtin_prefetch(i + 1 < profile.segments_.count ? &segment[1].a : &profile.final_.a);
  }
};

inline std::size_t ProfileSample::find(const SegmentTable& segments, double t,
                                       std::size_t& cursor) noexcept {
  // From the previous call's segment forwards or backwards, which finds the same one as a scan
  // from either end.
  const std::size_t count = segments.count;
  std::size_t i = cursor < count ? cursor : count - 1;
  if (segments.items[i].t0 <= t) {
    while (i + 1 < count && segments.items[i + 1].t0 <= t)
      ++i;
  } else {
    while (i > 0 && segments.items[i].t0 > t)
      --i;
  }
  cursor = i;
  return i;
}

inline KinematicState ProfileSample::at(const Profile& profile, double t, double& jerk) noexcept {
  if (t >= profile.duration_) {
    jerk = 0.0;
    if (!profile.holds_velocity_) return profile.final_;
    return KinematicState{profile.final_.p + profile.final_.v * (t - profile.duration_),
                          profile.final_.v, 0.0};
  }
  if (!(t > 0.0)) {
    jerk = profile.jerk_at(t);  // t <= 0 or NaN: its own rules
    return profile.start_;
  }
  return in_segment(profile, find(profile.segments_, t, profile.cursor_), t, jerk);
}

inline KinematicState ProfileSample::in_segment(const Profile& profile, std::size_t i, double t,
                                                double& jerk) noexcept {
  const SegmentTable& segments = profile.segments_;
  const Segment& seg = segments.items[i];
  jerk = seg.j;
  const double tau = t - seg.t0;
  if (tau <= 0.5 * seg.duration) {
    return advance(KinematicState{seg.p, seg.v, seg.a}, seg.j, tau);
  }
  // In the second half, evaluate back from the segment's end (the next segment's stored start,
  // or the exact final state): rounding stays relative to the nearer boundary, so the profile
  // approaches an exactly known end (v = 0 at a reversal, the target) without the drift of the
  // segment's length.
  const KinematicState end = i + 1 < segments.count
                                 ? KinematicState{segments.items[i + 1].p, segments.items[i + 1].v,
                                                  segments.items[i + 1].a}
                                 : profile.final_;
  const double t_end = i + 1 < segments.count ? segments.items[i + 1].t0 : profile.duration_;
  return advance(end, seg.j, std::min(t - t_end, 0.0));
}

}  // namespace nc::detail
