#include "nc_core/coupling_graph.hpp"

namespace nc {

namespace {
constexpr uint32_t kNone32 = UINT32_MAX;
}  // namespace

void CouplingGraph::add_axis() {
  const auto index = static_cast<uint32_t>(master_.size());
  master_.push_back(kNone32);
  order_.push_back(index);
  group_.push_back(index);
  depth_.push_back(0);
  count_.resize(master_.size() + 1, 0);
}

std::size_t CouplingGraph::master_of(std::size_t axis) const noexcept {
  const uint32_t m = master_[axis];
  return m == kNone32 ? kNoMaster : m;
}

bool CouplingGraph::would_loop(std::size_t slave, std::size_t master) const noexcept {
  const std::size_t n = master_.size();
  if (slave >= n || master >= n || slave == master) return true;
  // Up the master chain from `master`: reaching `slave` closes a loop. A chain is at most n long.
  std::size_t at = master;
  for (std::size_t steps = 0; steps < n; ++steps) {
    const uint32_t up = master_[at];
    if (up == kNone32) return false;
    if (up == slave) return true;
    at = up;
  }
  return true;
}

bool CouplingGraph::couple(std::size_t slave, std::size_t master) noexcept {
  if (would_loop(slave, master) || master_[slave] != kNone32) return false;
  master_[slave] = static_cast<uint32_t>(master);
  ++links_;
  recompute();
  return true;
}

void CouplingGraph::decouple(std::size_t slave) noexcept {
  if (slave >= master_.size() || master_[slave] == kNone32) return;
  master_[slave] = kNone32;
  --links_;
  recompute();
}

void CouplingGraph::recompute() noexcept {
  const std::size_t n = master_.size();
  // Depth = number of masters above an axis; the group is the top one. A forest: each chain
  // ends at an uncoupled axis.
  for (std::size_t i = 0; i < n; ++i) {
    uint32_t depth = 0;
    uint32_t top = static_cast<uint32_t>(i);
    while (master_[top] != kNone32) {
      top = master_[top];
      ++depth;
    }
    depth_[i] = depth;
    group_[i] = top;
  }
  // Counting sort by depth, stable: masters (smaller depth) first, index order among equals.
  for (uint32_t& c : count_)
    c = 0;
  for (std::size_t i = 0; i < n; ++i)
    ++count_[depth_[i] + 1];
  for (std::size_t d = 1; d <= n; ++d)
    count_[d] += count_[d - 1];
  for (std::size_t i = 0; i < n; ++i)
    order_[count_[depth_[i]]++] = static_cast<uint32_t>(i);
  ++revision_;
}

}  // namespace nc
