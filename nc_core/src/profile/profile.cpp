// The Profile container: constant-jerk segments, each storing its own start state, so that
// evaluation is exact at segment boundaries and rounding never accumulates within a segment.
#include "nc_core/profile.hpp"

#include <cmath>
#include <cstring>

#include "profile/profile_sample.hpp"
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
  return detail::ProfileSample::at(*this, t, jerk);
}

double Profile::jerk_at(double t) const noexcept {
  if (segments_.count == 0 || t < 0.0 || t >= duration_) return 0.0;
  if (std::isnan(t)) return segments_.items[segments_.count - 1].j;  // as a scan from the end finds
  return segments_.items[detail::ProfileSample::find(segments_, t, cursor_)].j;
}

}  // namespace nc
