// The steady lane's horizon (steady_lane.hpp).
#include "axis/steady_lane.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace nc::detail {

namespace {

constexpr uint32_t kEnables = (1U << plc::kControlEnable) | (1U << plc::kControlFeedEnablePlus) |
                              (1U << plc::kControlFeedEnableMinus);

// How far the position can move from `from` within `span` seconds at constant jerk `j`.
double reach(const KinematicState& from, double j, double span) noexcept {
  return span * (std::abs(from.v) + span * (0.5 * std::abs(from.a) + span * (std::abs(j) / 6.0)));
}

}  // namespace

uint32_t SteadyLane::horizon(const AxisCore& a) noexcept {
  const MasterJob& job = a.job_;
  const JobTable& table = job.table;
  const Profile& profile = table.profile_;
  // The job and what phase (a), check_enables() and finish_job() would look at.
  if (job.kind() != JobKind::kPosition || table.ended_ || table.chained_ ||
      profile.holds_velocity()) {
    return 0;
  }
  if (a.image_.rare || a.buffer_waiting_ || a.propagation_.pending || a.channel_.has_error() ||
      (a.control_seen_ & kEnables) != kEnables || a.hand_velocity_ != 0.0 || a.by_hand_ ||
      !a.group_ready_ || a.drive_command_given_ || a.error_event_ ||
      a.monitors_.window_state_bits() != 0) {
    return 0;
  }
  const JobOnline& online = job.online;
  if (online.activation().armed || online.override_value() != online.handled_override() ||
      a.channel_.ref().PlcToNc.Override != online.override_value()) {
    return 0;
  }
  // The samples: inside the cursor's segment, before its next one and the end tolerance
  // (JobTable::advance()'s at_end, ProfileSample::at()'s first two tests and find()).
  const std::size_t i = ProfileSample::cursor(profile);
  const std::size_t count = profile.segment_count();
  if (i >= count) return 0;
  const double cycle_time = a.cycle_time_;
  const double end = profile.duration();
  double limit = end - JobTable::kEndTolerance * std::max(1.0, end);
  const bool last = i + 1 == count;
  if (!last) limit = std::min(limit, profile.segment(i + 1).t0);
  const Segment& seg = profile.segment(i);
  const auto time = [&table, cycle_time](uint64_t k) noexcept {
    return static_cast<double>(k) * cycle_time + table.offset_;
  };
  const uint64_t first = table.k_ + 1;
  const double t_first = time(first);
  if (!(t_first > 0.0) || !(t_first >= seg.t0) || !(t_first < limit)) return 0;
  // The last sample before the limit: k·T + offset does not fall as k rises, so from an estimate
  // a few steps either way find it exactly.
  constexpr uint64_t kMost = std::numeric_limits<uint32_t>::max() - 1;
  const double estimate = std::floor((limit - table.offset_) / cycle_time);
  if (!(estimate < static_cast<double>(kMost))) return 0;
  uint64_t k = std::max(first, static_cast<uint64_t>(std::max(estimate, 0.0)));
  while (k > first && !(time(k) < limit))
    --k;
  while (k < kMost && time(k + 1) < limit)
    ++k;
  // The software limits: the samples of the first half of the segment are taken from its start,
  // those of the second from its end, each within the segment's length.
  const KinematicState start{seg.p, seg.v, seg.a};
  const KinematicState stop =
      last ? profile.final_state()
           : KinematicState{profile.segment(i + 1).p, profile.segment(i + 1).v,
                            profile.segment(i + 1).a};
  const double span =
      std::max(seg.duration, (last ? profile.duration() : profile.segment(i + 1).t0) - seg.t0);
  const double from_start = reach(start, seg.j, span);
  const double from_stop = reach(stop, seg.j, span);
  // A margin far above the rounding of the samples.
  const double margin =
      1e-9 * (1.0 + std::abs(start.p) + std::abs(stop.p) + from_start + from_stop);
  const double lo = std::min(start.p - from_start, stop.p - from_stop) - margin;
  const double hi = std::max(start.p + from_start, stop.p + from_stop) + margin;
  if (!a.monitors_.limits_clear(lo, hi)) return 0;
  return static_cast<uint32_t>(k);
}

void SteadyLane::enter(AxisCore& a) noexcept {
  a.job_.table.steady_until_ = horizon(a);
}

bool SteadyLane::lane_holds(const AxisCore& a) noexcept {
  const JobTable& table = a.job_.table;
  if (!next(table) || horizon(a) != table.steady_until_) return false;
  const Profile& profile = table.profile_;
  const double t = static_cast<double>(table.k_ + 1) * a.cycle_time_ + table.offset_;
  const double end = profile.duration();
  if (!(t < end - JobTable::kEndTolerance * std::max(1.0, end))) return false;
  const std::size_t cursor = ProfileSample::cursor(profile);
  double jerk = 0.0;
  const KinematicState lane = ProfileSample::in_segment(profile, cursor, t, jerk);
  double full_jerk = 0.0;
  const KinematicState full = profile.at(t, full_jerk);  // moves the cursor to t's segment
  const auto same = [](double x, double y) noexcept {    // bit for bit (−0.0 is not +0.0)
    return std::bit_cast<uint64_t>(x) == std::bit_cast<uint64_t>(y);
  };
  if (ProfileSample::cursor(profile) != cursor || !same(lane.p, full.p) || !same(lane.v, full.v) ||
      !same(lane.a, full.a) || !same(jerk, full_jerk)) {
    return false;
  }
  // run_monitors()'s software limits on the set position (held ±0 added).
  const double p = lane.p + a.stack_.held();
  return !(lane.v > 0.0 && a.monitors_.above_max(p)) && !(lane.v < 0.0 && a.monitors_.below_min(p));
}

}  // namespace nc::detail
