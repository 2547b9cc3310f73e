// Who follows whom among the axes of one kernel (SPEC C): a forest of master → slave links,
// each slave with at most one master (MC_GearIn / MC_GearInDyn make links, MC_GearOut ends
// them). The kernel owns it.
//
// The kernel computes set values in order(): every master before its slaves, index order while
// there is no coupling. The order and the groups (an axis with all axes coupled to it directly or
// indirectly; named by the index of their top master) are cached and recomputed only when a
// coupling changes, never in a steady cycle.
//
// add_axis() is set-up (allocates the room for every later change); all other functions are
// cycle functions: noexcept, no allocation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace nc {

class CouplingGraph {
 public:
  static constexpr std::size_t kNoMaster = SIZE_MAX;

  // Set-up: one more axis, uncoupled, with index axis_count() - 1 afterwards.
  void add_axis();
  std::size_t axis_count() const noexcept { return master_.size(); }

  // Coupling `slave` to `master` would close a loop (also slave == master), or an index is out
  // of range.
  bool would_loop(std::size_t slave, std::size_t master) const noexcept;
  // Couples `slave` to `master`; false (nothing changes) when it would loop or the slave
  // already follows a master.
  bool couple(std::size_t slave, std::size_t master) noexcept;
  // The slave follows nobody afterwards (no change when it was not coupled).
  void decouple(std::size_t slave) noexcept;

  std::size_t master_of(std::size_t axis) const noexcept;
  bool has_couplings() const noexcept { return links_ > 0; }
  // Every axis once, each master before its slaves (stable: index order among equals).
  std::span<const uint32_t> order() const noexcept { return order_; }
  // The top master of the axis's group (the axis itself when it is not coupled).
  std::size_t group(std::size_t axis) const noexcept { return group_[axis]; }
  // How many times order() has been recomputed (a steady cycle never does).
  uint64_t revision() const noexcept { return revision_; }

 private:
  void recompute() noexcept;

  std::vector<uint32_t> master_;  // UINT32_MAX = no master
  std::vector<uint32_t> order_;
  std::vector<uint32_t> group_;
  std::vector<uint32_t> depth_;  // scratch of recompute()
  std::vector<uint32_t> count_;  // scratch of recompute() (one more than axes)
  std::size_t links_ = 0;
  uint64_t revision_ = 0;
};

}  // namespace nc
