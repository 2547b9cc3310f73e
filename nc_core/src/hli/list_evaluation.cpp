// ListEvaluation (list_evaluation.hpp): a list parsed, checked and taken into the coupling
// matrix (SPEC D2–D4). Choices: docs/behaviour.md "HLI axis coupling".
#include "hli/list_evaluation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "hli/drive_brakes.hpp"

namespace nc::hli {

namespace {

using plc::ErrorCode;
namespace h = plc::hli;

Eigen::Index ix(std::size_t i) noexcept {
  return static_cast<Eigen::Index>(i);
}

}  // namespace

plc::ErrorCode ListEvaluation::parse(const h::HLI_AX_COUPLING_COMMAND& command,
                                     HliState::Candidate& list) const noexcept {
  list.count = 0;
  list.fract = false;
  for (const h::HLI_AX_COUPLING_DESC& desc : command.desc) {
    if (desc.mode == h::HLI_AXIS_COUPLING_INACTIVE) break;  // ends the list (seed's 4-row table)
    if (desc.mode > h::HLI_AXIS_COUPLING_FRACT) return ErrorCode::kBlockInputOutOfRange;
    const std::size_t source = s_.index_of(desc.ax_nr);
    if (source == HliState::kNoAxis) return ErrorCode::kInvalidAxisReference;
    if (!s_.setups_[source].couplable) return ErrorCode::kAxisKindNotAllowed;
    HliState::Entry& e = list.entries[list.count++];
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
bool ListEvaluation::makes_loop(std::size_t target, const HliState::Candidate& list) noexcept {
  bool mapped = s_.setups_[target].forward_mapping;
  for (std::size_t e = 0; e < list.count; ++e)
    mapped = mapped || s_.setups_[list.entries[e].source].forward_mapping;
  if (!mapped) return false;

  std::fill(s_.dfs_seen_.begin(), s_.dfs_seen_.end(), uint8_t{0});
  s_.dfs_stack_.clear();
  for (std::size_t e = 0; e < list.count; ++e) {
    if (list.entries[e].source != target) s_.dfs_stack_.push_back(list.entries[e].source);
  }
  while (!s_.dfs_stack_.empty()) {
    const std::size_t axis = s_.dfs_stack_.back();
    s_.dfs_stack_.pop_back();
    if (axis == target) return true;
    if (s_.dfs_seen_[axis] != 0) continue;
    s_.dfs_seen_[axis] = 1;
    const HliState::Target& t = s_.targets_[axis];
    if (t.state != HliState::State::kCoupled) continue;
    for (std::size_t e = 0; e < t.count; ++e) {
      // Each axis is expanded once, so at most n·HliState::kListSize pushes: within the reserve.
      if (t.entries[e].source != axis) s_.dfs_stack_.push_back(t.entries[e].source);
    }
  }
  return false;
}

// 70200: the target's drive, or any old or new source's program, moves; for a list switched off
// also the target's own program, which drives it from then on (else the drive would take the
// program's velocity in one cycle: fuzz finding K25).
bool ListEvaluation::involved_axis_moves(std::size_t target,
                                         const HliState::Candidate& list) const noexcept {
  if (s_.dv_(ix(target)) != 0.0) return true;
  if (list.count == 0 && s_.qv_(ix(target)) != 0.0) return true;
  const HliState::Target& t = s_.targets_[target];
  for (std::size_t e = 0; e < t.count; ++e) {
    if (t.state == HliState::State::kCoupled && s_.qv_(ix(t.entries[e].source)) != 0.0) return true;
  }
  for (std::size_t e = 0; e < list.count; ++e) {
    if (s_.qv_(ix(list.entries[e].source)) != 0.0) return true;
  }
  return false;
}

void ListEvaluation::evaluate(std::size_t target, ErrorCode refusal, const Outputs& out) noexcept {
  h::HLI_AX_COUPLING& unit = s_.units_[target].lr_mc_control.axis_coupling;
  unit.command_w.semaphor_rw = false;  // reset in the cycle it is evaluated
  HliState::Candidate list;
  ErrorCode code = !s_.setups_[target].couplable ? ErrorCode::kAxisKindNotAllowed
                   : refusal != ErrorCode::kNone ? refusal
                                                 : parse(unit.command_w, list);
  if (code == ErrorCode::kNone && makes_loop(target, list)) code = ErrorCode::kHliCouplingLoop;
  if (code != ErrorCode::kNone) {
    unit.state_r.error_r = plc::to_id(code);  // refused: the list in force stays
    return;
  }
  if (involved_axis_moves(target, list)) {
    DriveBrakes(s_).halt(target, ErrorCode::kHliChangeWhileMoving, out);
    return;
  }
  unit.state_r.error_r = 0;
  take(target, list);
}

void ListEvaluation::take(std::size_t target, const HliState::Candidate& list) noexcept {
  HliState::Target& t = s_.targets_[target];
  const Eigen::Index r = ix(target);
  const double d_now = s_.d_(r);
  if (t.state == HliState::State::kCoupled) count_sources(target, t, false);
  if (list.count == 0) {
    // Switched off: the drive stays where it stands and follows the program from there.
    t = HliState::Target{};
    s_.matrix_.drop_row(target);
    s_.c_(r) = d_now - s_.q_(r);
    s_.dv_(r) = s_.qv_(r);
    s_.da_(r) = s_.qa_(r);
  } else {
    t.state = HliState::State::kCoupled;
    t.count = list.count;
    t.fract = list.fract;
    t.d_activation = d_now;
    auto row = s_.matrix_.new_row(target, s_.size());
    for (std::size_t e = 0; e < list.count; ++e) {
      t.entries[e] = list.entries[e];
      t.entries[e].q_activation = s_.q_(ix(list.entries[e].source));
      row(ix(list.entries[e].source)) += list.entries[e].factor;
    }
    count_sources(target, t, true);
    // d = d(activation) + Σ K·(q − q(activation)): c = d(activation) − Σ K·q(activation).
    s_.c_(r) = d_now - row.dot(s_.q_);
    s_.dv_(r) = row.dot(s_.qv_);
    s_.da_(r) = row.dot(s_.qa_);
  }
  s_.d_(r) = d_now;  // Δq = 0 at activation: the position does not jump
  publish(target);
}

void ListEvaluation::count_sources(std::size_t target, const HliState::Target& t,
                                   bool add) noexcept {
  for (std::size_t e = 0; e < t.count; ++e) {
    const std::size_t source = t.entries[e].source;
    if (source == target) continue;
    if (add) {
      ++s_.source_uses_[source];
    } else {
      --s_.source_uses_[source];
    }
  }
}

void ListEvaluation::publish(std::size_t axis) noexcept {
  h::HLI_AX_COUPLING_STATE& state = s_.units_[axis].lr_mc_control.axis_coupling.state_r;
  const HliState::Target& t = s_.targets_[axis];
  state.active_r = t.state == HliState::State::kCoupled;
  for (std::size_t e = 0; e < HliState::kListSize; ++e) {
    state.desc[e] =
        state.active_r && e < t.count ? t.entries[e].shown : h::HLI_AX_COUPLING_STATE_DESC{};
  }
}

}  // namespace nc::hli
