// The HLI coupling stage: its set-up, the cycle (D3), the forward mapping (D5), and DriveBrakes
// (braking of stopped targets, the 70195 software-limit check), kept here next to the cycle that
// calls it. Lists are ListEvaluation's (list_evaluation.cpp), the matrix CouplingMatrix's.
// Choices: docs/behaviour.md "HLI axis coupling".
#include "hli/hli_stage.hpp"

#include "hli/drive_brakes.hpp"
#include "hli/list_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

namespace nc::hli {

namespace {

using plc::ErrorCode;
namespace h = plc::hli;

// Reserves room for `count` elements, at least doubling, so that adding axes one by one copies
// the storage only O(log n) times.
template <class T>
void at_least(std::vector<T>& v, std::size_t count) {
  if (v.capacity() < count) v.reserve(std::max(count, 2 * v.capacity()));
}

Eigen::Index ix(std::size_t i) noexcept {
  return static_cast<Eigen::Index>(i);
}

// 1e-3 mm/s, saturated to int32.
int32_t rev_units(double velocity) noexcept {
  const double scaled = std::round(velocity * 1000.0);
  constexpr double kMax = std::numeric_limits<int32_t>::max();
  constexpr double kMin = std::numeric_limits<int32_t>::min();
  if (!(scaled < kMax)) return std::numeric_limits<int32_t>::max();
  if (!(scaled > kMin)) return std::numeric_limits<int32_t>::min();
  return static_cast<int32_t>(scaled);
}

}  // namespace

AxisSetup axis_setup(const AxisConfig& config) {
  AxisSetup s;
  s.ax_nr = config.id;
  s.emergency_deceleration = config.emergency_deceleration;
  s.sw_limit_min_enabled = config.sw_limit_min_enabled;
  s.sw_limit_max_enabled = config.sw_limit_max_enabled;
  s.sw_limit_min = config.sw_limit_min;
  s.sw_limit_max = config.sw_limit_max;
  s.forward_mapping = config.recalc_link_main_input_position;
  s.forward_mapping_absolute = config.recalc_input_position_absolute;
  s.couplable = config.kind != AxisKind::kTwoSpeed;
  return s;
}

HliStage::HliStage(double cycle_time) : HliState(cycle_time) {
  if (!(cycle_time > 0.0) || !std::isfinite(cycle_time)) {
    throw std::invalid_argument("HliStage: cycle time must be > 0");
  }
}

void HliStage::reserve(std::size_t axes) {
  setups_.reserve(axes);
  pointers_.reserve(axes);
  targets_.reserve(axes);
  source_uses_.reserve(axes);
  dfs_stack_.reserve((axes + 1) * kListSize);
  dfs_seen_.reserve(axes);
  matrix_.reserve(axes);
}

plc::hli::HLI_AX& HliStage::add_axis(const AxisSetup& setup) {
  if (setup.ax_nr == 0) throw std::invalid_argument("HliStage: ax_nr 0 is reserved");
  if (index_of(setup.ax_nr) != kNoAxis) {
    throw std::invalid_argument("HliStage: ax_nr " + std::to_string(setup.ax_nr) + " twice");
  }
  if (!(setup.emergency_deceleration > 0.0) || !std::isfinite(setup.emergency_deceleration) ||
      !std::isfinite(setup.sw_limit_min) || !std::isfinite(setup.sw_limit_max)) {
    throw std::invalid_argument("HliStage: emergency deceleration must be > 0, limits finite");
  }
  const std::size_t n = size() + 1;
  // What the cycle pushes into must hold n axes' worth without reallocating.
  at_least(dfs_stack_, (n + 1) * kListSize);
  setups_.push_back(setup);
  units_.emplace_back();
  pointers_.push_back(&units_.back());
  targets_.emplace_back();
  source_uses_.push_back(0);
  dfs_seen_.resize(n, 0);

  // The new axis is free (d = q), without a row; its column is zero in every stored row.
  matrix_.add_axis(n);
  for (Eigen::VectorXd* v : {&c_, &q_, &qv_, &qa_, &d_, &dv_, &da_}) {
    v->conservativeResize(ix(n));
    (*v)(ix(n - 1)) = 0.0;
  }
  return units_.back();
}

std::size_t HliState::index_of(int ax_nr) const noexcept {
  for (std::size_t i = 0; i < setups_.size(); ++i) {
    if (setups_[i].ax_nr == ax_nr) return i;
  }
  return kNoAxis;
}

bool HliStage::cycle(const Inputs& in, const Outputs& out) noexcept {
  const std::size_t n = size();
  if (in.program_position.size() != n || in.program_velocity.size() != n ||
      in.program_acceleration.size() != n || in.referenced.size() != n ||
      out.drive_position.size() != n || out.drive_velocity.size() != n ||
      out.drive_acceleration.size() != n || out.stop.size() != n ||
      (!in.refusal.empty() && in.refusal.size() != n)) {
    return false;
  }
  const Eigen::Index m = ix(n);
  q_ = Eigen::Map<const Eigen::VectorXd>(in.program_position.data(), m);
  qv_ = Eigen::Map<const Eigen::VectorXd>(in.program_velocity.data(), m);
  qa_ = Eigen::Map<const Eigen::VectorXd>(in.program_acceleration.data(), m);

  // 1. Drive values with the lists in force: unit rows for free axes, the stored rows for the
  //    targets, the brake (kept in c) for braking axes.
  for (std::size_t i = 0; i < n; ++i) {
    if (targets_[i].state == State::kBraking) DriveBrakes(*this).advance_brake(i);
  }
  d_ = q_ + c_;
  dv_ = qv_;
  da_ = qa_;
  matrix_.apply(m, q_, qv_, qa_, c_, d_, dv_, da_);
  for (std::size_t i = 0; i < n; ++i) {
    out.stop[i] = ErrorCode::kNone;
    const Target& t = targets_[i];
    if (t.state != State::kBraking) continue;
    d_(ix(i)) = c_(ix(i));
    dv_(ix(i)) = t.brake_velocity;
    da_(ix(i)) = t.brake_velocity == 0.0
                     ? 0.0
                     : std::copysign(setups_[i].emergency_deceleration, -t.brake_velocity);
  }

  // 2. Lists whose semaphore is set, in axis order; each takes effect from this cycle's d on.
  for (std::size_t i = 0; i < n; ++i) {
    if (units_[i].lr_mc_control.axis_coupling.command_w.semaphor_rw) {
      ListEvaluation(*this).evaluate(i, in.refusal.empty() ? ErrorCode::kNone : in.refusal[i], out);
    }
  }

  // 3. FRACT targets on a referenced axis: can the drive still stop before its limits?
  for (std::size_t i = 0; i < n; ++i) {
    const Target& t = targets_[i];
    if (t.state == State::kCoupled && t.fract && in.referenced[i] &&
        DriveBrakes(*this).cannot_stop_before_limit(i)) {
      DriveBrakes(*this).halt(i, ErrorCode::kHliFractOnReferencedAxis, out);
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    out.drive_position[i] = d_(ix(i));
    out.drive_velocity[i] = dv_(ix(i));
    out.drive_acceleration[i] = da_(ix(i));
    units_[i].lr_state.active_rev_r = rev_units(dv_(ix(i)));
  }
  return true;
}

void HliStage::stop(std::size_t axis) noexcept {
  if (axis < size()) DriveBrakes(*this).brake(axis);
}

void HliStage::release(std::size_t axis) noexcept {
  if (axis < size() && targets_[axis].state != State::kFree)
    ListEvaluation(*this).take(axis, Candidate{});
}

double HliStage::factor(std::size_t target, std::size_t source) const noexcept {
  if (target >= size() || source >= size()) return 0.0;
  if (matrix_.has_row(target)) return matrix_.at(target, source);
  return targets_[target].state == State::kFree && target == source ? 1.0 : 0.0;
}

double HliStage::command_position_request(std::size_t axis) const noexcept {
  if (axis >= size()) return std::numeric_limits<double>::quiet_NaN();
  const AxisSetup& s = setups_[axis];
  const Target& t = targets_[axis];
  const Eigen::Index r = ix(axis);
  if (!s.forward_mapping || t.state != State::kCoupled) return d_(r);
  // Solve d = d0 + Σ K·(q − q0) for the target's own q (relative), or d = Σ K·q (absolute).
  double self = 0.0;
  double others = 0.0;
  for (std::size_t e = 0; e < t.count; ++e) {
    const Entry& entry = t.entries[e];
    if (entry.source == axis) {
      self += entry.factor;
    } else {
      const double q = q_(ix(entry.source));
      others += entry.factor * (s.forward_mapping_absolute ? q : q - entry.q_activation);
    }
  }
  // Without a self entry the drive does not depend on the axis's program coordinate: it stays.
  if (self == 0.0) return q_(r);
  if (s.forward_mapping_absolute) return (d_(r) - others) / self;
  double q0 = q_(r);
  for (std::size_t e = 0; e < t.count; ++e) {
    if (t.entries[e].source == axis) q0 = t.entries[e].q_activation;
  }
  return q0 + (d_(r) - t.d_activation - others) / self;
}

// --- DriveBrakes (drive_brakes.hpp) ---

void DriveBrakes::brake(std::size_t axis) noexcept {
  HliState::Target& t = s_.targets_[axis];
  const Eigen::Index r = ix(axis);
  const double v = s_.dv_(r);
  if (t.state == HliState::State::kCoupled) ListEvaluation(s_).count_sources(axis, t, false);
  t = HliState::Target{};
  t.state = HliState::State::kBraking;
  t.brake_velocity = v;
  s_.matrix_.drop_row(axis);
  s_.c_(r) = s_.d_(r);
  ListEvaluation(s_).publish(axis);
}

void DriveBrakes::halt(std::size_t axis, plc::ErrorCode code, const Outputs& out) noexcept {
  brake(axis);
  out.stop[axis] = code;
  s_.units_[axis].lr_mc_control.axis_coupling.state_r.error_r = plc::to_id(code);
}

void DriveBrakes::advance_brake(std::size_t axis) noexcept {
  HliState::Target& t = s_.targets_[axis];
  const double a = s_.setups_[axis].emergency_deceleration;
  const double v = t.brake_velocity;
  const double step = a * s_.cycle_time_;
  double moved = 0.0;
  if (std::abs(v) > step) {
    const double next = v - std::copysign(step, v);
    moved = 0.5 * (v + next) * s_.cycle_time_;
    t.brake_velocity = next;
  } else {
    // Rest within this cycle: the rest of v²/(2a), so the whole stop is exactly v0²/(2a).
    moved = v * std::abs(v) / (2.0 * a);
    t.brake_velocity = 0.0;
  }
  s_.c_(ix(axis)) += moved;
  // At rest, and the axis's own program at rest too: it follows its program from here.
  if (t.brake_velocity == 0.0 && s_.qv_(ix(axis)) == 0.0) {
    t.state = HliState::State::kFree;
    s_.c_(ix(axis)) -= s_.q_(ix(axis));
  }
}

bool DriveBrakes::cannot_stop_before_limit(std::size_t axis) const noexcept {
  const AxisSetup& s = s_.setups_[axis];
  const Eigen::Index r = ix(axis);
  // Where the drive will be next cycle with its present acceleration, and where it would come to
  // rest from there (v²/2a, as the seed reckons): braking must start now if that is past a limit.
  const double t = s_.cycle_time_;
  const double v_next = s_.dv_(r) + s_.da_(r) * t;
  const double d_next = s_.d_(r) + s_.dv_(r) * t + 0.5 * s_.da_(r) * t * t;
  const double reach = v_next * std::abs(v_next) / (2.0 * s.emergency_deceleration);
  if (s.sw_limit_max_enabled && s_.dv_(r) > 0.0 && d_next + std::max(reach, 0.0) > s.sw_limit_max) {
    return true;
  }
  return s.sw_limit_min_enabled && s_.dv_(r) < 0.0 &&
         d_next + std::min(reach, 0.0) < s.sw_limit_min;
}

}  // namespace nc::hli
