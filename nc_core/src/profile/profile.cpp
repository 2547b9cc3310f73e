// The Profile container: constant-jerk segments, each storing its own start state, so that
// evaluation is exact at segment boundaries and rounding never accumulates within a segment.
#include "nc_core/profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "profile/kinematics.hpp"
#include "profile/profile_writer.hpp"

namespace nc {

Profile Profile::failure(ErrorCode code) noexcept {
  Profile profile;
  profile.error_ = code;
  return profile;
}

namespace detail {

SegmentTable::SegmentTable(const SegmentTable& other) noexcept : count(other.count) {
  // Only [0, count) is ever read; the rest of the storage stays as it is.
  if (count > 0) std::memcpy(static_cast<void*>(items), other.items, count * sizeof(Segment));
}

SegmentTable& SegmentTable::operator=(const SegmentTable& other) noexcept {
  if (this != &other) {
    count = other.count;
    if (count > 0) std::memcpy(static_cast<void*>(items), other.items, count * sizeof(Segment));
  }
  return *this;
}

std::size_t SegmentTable::find(double t, std::size_t& cursor) const noexcept {
  // The last segment with t0 <= t (the first when none is): from the previous call's segment
  // forwards or backwards, which finds the same one as a scan from either end.
  std::size_t i = cursor < count ? cursor : count - 1;
  if (items[i].t0 <= t) {
    while (i + 1 < count && items[i + 1].t0 <= t)
      ++i;
  } else {
    while (i > 0 && items[i].t0 > t)
      --i;
  }
  cursor = i;
  return i;
}

}  // namespace detail

void Profile::reset(const KinematicState& start) noexcept {
  detail::ProfileWriter(*this, start).close(nullptr, false);
}

bool Profile::append(double duration, double jerk, double exact_a, double exact_v) noexcept {
  detail::ProfileWriter writer(*this);
  const bool ok = writer.append(duration, jerk, exact_a, exact_v);
  writer.store();
  return ok;
}

void Profile::close(const KinematicState* exact_end, bool holds_velocity) noexcept {
  detail::ProfileWriter(*this).close(exact_end, holds_velocity);
}

void Profile::anchor_to_end(std::size_t first) noexcept {
  detail::ProfileWriter::anchor_to_end(*this, first);
}

KinematicState Profile::at(double t) const noexcept {
  double jerk = 0.0;
  return at(t, jerk);
}

KinematicState Profile::at(double t, double& jerk) const noexcept {
  if (t >= duration_) {
    jerk = 0.0;
    if (!holds_velocity_) return final_;
    return KinematicState{final_.p + final_.v * (t - duration_), final_.v, 0.0};
  }
  if (!(t > 0.0)) {
    jerk = jerk_at(t);  // t <= 0 or NaN: its own rules
    return start_;
  }
  const std::size_t i = segments_.find(t, cursor_);
  const Segment& seg = segments_.items[i];
  jerk = seg.j;
  const double tau = t - seg.t0;
  if (tau <= 0.5 * seg.duration) {
    return detail::advance(KinematicState{seg.p, seg.v, seg.a}, seg.j, tau);
  }
  // In the second half, evaluate back from the segment's end (the next segment's stored start,
  // or the exact final state): rounding stays relative to the nearer boundary, so the profile
  // approaches an exactly known end (v = 0 at a reversal, the target) without the drift of the
  // segment's length.
  const KinematicState end =
      i + 1 < segments_.count ? KinematicState{segments_.items[i + 1].p, segments_.items[i + 1].v,
                                               segments_.items[i + 1].a}
                              : final_;
  const double t_end = i + 1 < segments_.count ? segments_.items[i + 1].t0 : duration_;
  return detail::advance(end, seg.j, std::min(t - t_end, 0.0));
}

double Profile::jerk_at(double t) const noexcept {
  if (segments_.count == 0 || t < 0.0 || t >= duration_) return 0.0;
  if (std::isnan(t)) return segments_.items[segments_.count - 1].j;  // as a scan from the end finds
  return segments_.items[segments_.find(t, cursor_)].j;
}

}  // namespace nc
