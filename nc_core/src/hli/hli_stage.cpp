// The HLI coupling stage: list evaluation (D2, D4), the coupling matrix (D3), braking of stopped
// targets, the 70195 software-limit check and the forward mapping (D5). Choices: docs/behaviour.md
// "HLI axis coupling".
#include "hli/hli_stage.hpp"

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

HliStage::HliStage(double cycle_time) : cycle_time_(cycle_time) {
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
  rows_.reserve(axes);
  row_of_.reserve(axes);
  grow_matrix(axes);
}

// The matrix is kept square at a capacity that grows by doubling (or to a reserve), so adding
// axes one by one copies it O(log n) times; the part beyond the axes in use is zero.
void HliStage::grow_matrix(std::size_t axes) {
  if (axes <= static_cast<std::size_t>(k_.rows())) return;
  const auto capacity = ix(std::max(axes, 2 * static_cast<std::size_t>(k_.rows())));
  k_.conservativeResizeLike(Matrix::Zero(capacity, capacity));
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
  at_least(rows_, n);
  at_least(dfs_stack_, (n + 1) * kListSize);
  setups_.push_back(setup);
  units_.emplace_back();
  pointers_.push_back(&units_.back());
  targets_.emplace_back();
  source_uses_.push_back(0);
  dfs_seen_.resize(n, 0);

  // The new axis is free (d = q), without a row; its column is zero in every stored row.
  grow_matrix(n);
  row_of_.push_back(kNoAxis);
  for (Eigen::VectorXd* v : {&product_, &c_, &q_, &qv_, &qa_, &d_, &dv_, &da_}) {
    v->conservativeResize(ix(n));
    (*v)(ix(n - 1)) = 0.0;
  }
  return units_.back();
}

std::size_t HliStage::index_of(int ax_nr) const noexcept {
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
    if (targets_[i].state == State::kBraking) advance_brake(i);
  }
  d_ = q_ + c_;
  dv_ = qv_;
  da_ = qa_;
  const Eigen::Index rows = ix(rows_.size());
  if (rows > 0) {
    const auto k = k_.topLeftCorner(rows, m);
    product_.head(rows).noalias() = k * q_;
    for (std::size_t j = 0; j < rows_.size(); ++j)
      d_(ix(rows_[j])) = product_(ix(j)) + c_(ix(rows_[j]));
    product_.head(rows).noalias() = k * qv_;
    for (std::size_t j = 0; j < rows_.size(); ++j)
      dv_(ix(rows_[j])) = product_(ix(j));
    product_.head(rows).noalias() = k * qa_;
    for (std::size_t j = 0; j < rows_.size(); ++j)
      da_(ix(rows_[j])) = product_(ix(j));
  }
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
      evaluate(i, in.refusal.empty() ? ErrorCode::kNone : in.refusal[i], out);
    }
  }

  // 3. FRACT targets on a referenced axis: can the drive still stop before its limits?
  for (std::size_t i = 0; i < n; ++i) {
    const Target& t = targets_[i];
    if (t.state == State::kCoupled && t.fract && in.referenced[i] && cannot_stop_before_limit(i)) {
      halt(i, ErrorCode::kHliFractOnReferencedAxis, out);
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

void HliStage::advance_brake(std::size_t axis) noexcept {
  Target& t = targets_[axis];
  const double a = setups_[axis].emergency_deceleration;
  const double v = t.brake_velocity;
  const double step = a * cycle_time_;
  double moved = 0.0;
  if (std::abs(v) > step) {
    const double next = v - std::copysign(step, v);
    moved = 0.5 * (v + next) * cycle_time_;
    t.brake_velocity = next;
  } else {
    // Rest within this cycle: the rest of v²/(2a), so the whole stop is exactly v0²/(2a).
    moved = v * std::abs(v) / (2.0 * a);
    t.brake_velocity = 0.0;
  }
  c_(ix(axis)) += moved;
  // At rest, and the axis's own program at rest too: it follows its program from here.
  if (t.brake_velocity == 0.0 && qv_(ix(axis)) == 0.0) {
    t.state = State::kFree;
    c_(ix(axis)) -= q_(ix(axis));
  }
}

plc::ErrorCode HliStage::parse(const h::HLI_AX_COUPLING_COMMAND& command,
                               Candidate& list) const noexcept {
  list.count = 0;
  list.fract = false;
  for (const h::HLI_AX_COUPLING_DESC& desc : command.desc) {
    if (desc.mode == h::HLI_AXIS_COUPLING_INACTIVE) break;  // ends the list (seed's 4-row table)
    if (desc.mode > h::HLI_AXIS_COUPLING_FRACT) return ErrorCode::kBlockInputOutOfRange;
    const std::size_t source = index_of(desc.ax_nr);
    if (source == kNoAxis) return ErrorCode::kInvalidAxisReference;
    if (!setups_[source].couplable) return ErrorCode::kAxisKindNotAllowed;
    Entry& e = list.entries[list.count++];
    e.source = source;
    e.shown = h::HLI_AX_COUPLING_STATE_DESC{desc.ax_nr, desc.mode};
    switch (desc.mode) {
      case h::HLI_AXIS_COUPLING_ZERO:
        e.factor = 0.0;
        break;
      case h::HLI_AXIS_COUPLING_DIRECT:
        e.factor = 1.0;
        break;
      case h::HLI_AXIS_COUPLING_MIRROR:
        e.factor = -1.0;
        break;
      default: {  // FRACT
        if (desc.fract_denom == 0) return ErrorCode::kHliDenominatorZero;
        // |num / denom| > FACT_MAX, decided in integers so that exactly the maximum passes.
        if (std::abs(int64_t{desc.fract_num}) >
            int64_t{h::HLI_AXIS_COUPLING_FACT_MAX} * std::abs(int64_t{desc.fract_denom})) {
          return ErrorCode::kHliFactorTooLarge;
        }
        e.factor = static_cast<double>(desc.fract_num) / static_cast<double>(desc.fract_denom);
        list.fract = list.fract || desc.fract_num != 0;  // numerator 0 acts as ZERO
        break;
      }
    }
  }
  return ErrorCode::kNone;
}

// With P-AXIS-00436 on an axis of the new list, the target may not reach itself through other
// axes' lists in force (a loop among distinct axes); the direct self entry is allowed.
bool HliStage::makes_loop(std::size_t target, const Candidate& list) noexcept {
  bool mapped = setups_[target].forward_mapping;
  for (std::size_t e = 0; e < list.count; ++e)
    mapped = mapped || setups_[list.entries[e].source].forward_mapping;
  if (!mapped) return false;

  std::fill(dfs_seen_.begin(), dfs_seen_.end(), uint8_t{0});
  dfs_stack_.clear();
  for (std::size_t e = 0; e < list.count; ++e) {
    if (list.entries[e].source != target) dfs_stack_.push_back(list.entries[e].source);
  }
  while (!dfs_stack_.empty()) {
    const std::size_t axis = dfs_stack_.back();
    dfs_stack_.pop_back();
    if (axis == target) return true;
    if (dfs_seen_[axis] != 0) continue;
    dfs_seen_[axis] = 1;
    const Target& t = targets_[axis];
    if (t.state != State::kCoupled) continue;
    for (std::size_t e = 0; e < t.count; ++e) {
      // Each axis is expanded once, so at most n·kListSize pushes: within the reserve.
      if (t.entries[e].source != axis) dfs_stack_.push_back(t.entries[e].source);
    }
  }
  return false;
}

// 70200: the target's drive, or any old or new source's program, moves.
bool HliStage::involved_axis_moves(std::size_t target, const Candidate& list) const noexcept {
  if (dv_(ix(target)) != 0.0) return true;
  const Target& t = targets_[target];
  for (std::size_t e = 0; e < t.count; ++e) {
    if (t.state == State::kCoupled && qv_(ix(t.entries[e].source)) != 0.0) return true;
  }
  for (std::size_t e = 0; e < list.count; ++e) {
    if (qv_(ix(list.entries[e].source)) != 0.0) return true;
  }
  return false;
}

void HliStage::evaluate(std::size_t target, ErrorCode refusal, const Outputs& out) noexcept {
  h::HLI_AX_COUPLING& unit = units_[target].lr_mc_control.axis_coupling;
  unit.command_w.semaphor_rw = false;  // reset in the cycle it is evaluated
  Candidate list;
  ErrorCode code = !setups_[target].couplable    ? ErrorCode::kAxisKindNotAllowed
                   : refusal != ErrorCode::kNone ? refusal
                                                 : parse(unit.command_w, list);
  if (code == ErrorCode::kNone && makes_loop(target, list)) code = ErrorCode::kHliCouplingLoop;
  if (code != ErrorCode::kNone) {
    unit.state_r.error_r = plc::to_id(code);  // refused: the list in force stays
    return;
  }
  if (involved_axis_moves(target, list)) {
    halt(target, ErrorCode::kHliChangeWhileMoving, out);
    return;
  }
  unit.state_r.error_r = 0;
  take(target, list);
}

void HliStage::take(std::size_t target, const Candidate& list) noexcept {
  Target& t = targets_[target];
  const Eigen::Index r = ix(target);
  const double d_now = d_(r);
  if (t.state == State::kCoupled) count_sources(target, t, false);
  if (list.count == 0) {
    // Switched off: the drive stays where it stands and follows the program from there.
    t = Target{};
    drop_row(target);
    c_(r) = d_now - q_(r);
    dv_(r) = qv_(r);
    da_(r) = qa_(r);
  } else {
    t.state = State::kCoupled;
    t.count = list.count;
    t.fract = list.fract;
    t.d_activation = d_now;
    if (row_of_[target] == kNoAxis) {
      row_of_[target] = rows_.size();
      rows_.push_back(target);  // within the reserve: one row per axis at most
    }
    k_.row(ix(row_of_[target])).setZero();  // the whole capacity: unused columns stay zero
    auto row = k_.row(ix(row_of_[target])).head(ix(size()));
    for (std::size_t e = 0; e < list.count; ++e) {
      t.entries[e] = list.entries[e];
      t.entries[e].q_activation = q_(ix(list.entries[e].source));
      row(ix(list.entries[e].source)) += list.entries[e].factor;
    }
    count_sources(target, t, true);
    // d = d(activation) + Σ K·(q − q(activation)): c = d(activation) − Σ K·q(activation).
    c_(r) = d_now - row.dot(q_);
    dv_(r) = row.dot(qv_);
    da_(r) = row.dot(qa_);
  }
  d_(r) = d_now;  // Δq = 0 at activation: the position does not jump
  publish(target);
}

// Removes the axis's row; the last stored row takes its place.
void HliStage::drop_row(std::size_t axis) noexcept {
  const std::size_t j = row_of_[axis];
  if (j == kNoAxis) return;
  const std::size_t last = rows_.size() - 1;
  if (j != last) {
    k_.row(ix(j)) = k_.row(ix(last));
    k_.row(ix(last)).setZero();
    rows_[j] = rows_[last];
    row_of_[rows_[j]] = j;
  }
  rows_.pop_back();
  row_of_[axis] = kNoAxis;
}

double HliStage::factor(std::size_t target, std::size_t source) const noexcept {
  if (target >= size() || source >= size()) return 0.0;
  if (row_of_[target] != kNoAxis) return k_(ix(row_of_[target]), ix(source));
  return targets_[target].state == State::kFree && target == source ? 1.0 : 0.0;
}

void HliStage::halt(std::size_t axis, plc::ErrorCode code, const Outputs& out) noexcept {
  stop(axis);
  out.stop[axis] = code;
  units_[axis].lr_mc_control.axis_coupling.state_r.error_r = plc::to_id(code);
}

void HliStage::stop(std::size_t axis) noexcept {
  if (axis >= size()) return;
  Target& t = targets_[axis];
  const Eigen::Index r = ix(axis);
  const double v = dv_(r);
  if (t.state == State::kCoupled) count_sources(axis, t, false);
  t = Target{};
  t.state = State::kBraking;
  t.brake_velocity = v;
  drop_row(axis);
  c_(r) = d_(r);
  publish(axis);
}

void HliStage::release(std::size_t axis) noexcept {
  if (axis < size() && targets_[axis].state == State::kCoupled) take(axis, Candidate{});
}

bool HliStage::cannot_stop_before_limit(std::size_t axis) const noexcept {
  const AxisSetup& s = setups_[axis];
  const Eigen::Index r = ix(axis);
  // Where the drive will be next cycle with its present acceleration, and where it would come to
  // rest from there (v²/2a, as the seed reckons): braking must start now if that is past a limit.
  const double t = cycle_time_;
  const double v_next = dv_(r) + da_(r) * t;
  const double d_next = d_(r) + dv_(r) * t + 0.5 * da_(r) * t * t;
  const double reach = v_next * std::abs(v_next) / (2.0 * s.emergency_deceleration);
  if (s.sw_limit_max_enabled && dv_(r) > 0.0 && d_next + std::max(reach, 0.0) > s.sw_limit_max) {
    return true;
  }
  return s.sw_limit_min_enabled && dv_(r) < 0.0 && d_next + std::min(reach, 0.0) < s.sw_limit_min;
}

void HliStage::count_sources(std::size_t target, const Target& t, bool add) noexcept {
  for (std::size_t e = 0; e < t.count; ++e) {
    const std::size_t source = t.entries[e].source;
    if (source == target) continue;
    if (add) {
      ++source_uses_[source];
    } else {
      --source_uses_[source];
    }
  }
}

void HliStage::publish(std::size_t axis) noexcept {
  h::HLI_AX_COUPLING_STATE& state = units_[axis].lr_mc_control.axis_coupling.state_r;
  const Target& t = targets_[axis];
  state.active_r = t.state == State::kCoupled;
  for (std::size_t e = 0; e < kListSize; ++e) {
    state.desc[e] =
        state.active_r && e < t.count ? t.entries[e].shown : h::HLI_AX_COUPLING_STATE_DESC{};
  }
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

}  // namespace nc::hli
