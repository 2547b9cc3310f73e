// The kernel's coupling graph (issue 8 item 4): who follows whom, would_loop(), the cached
// topological order (masters before slaves, index order while nothing is coupled) and the
// groups. No allocation: test_coupling_graph_no_allocation.cpp.
#include <catch2/catch.hpp>

#include <cstddef>
#include <vector>

#include "nc_core/coupling_graph.hpp"

namespace {

nc::CouplingGraph graph_of(std::size_t n) {
  nc::CouplingGraph g;
  for (std::size_t i = 0; i < n; ++i)
    g.add_axis();
  return g;
}

std::vector<uint32_t> order_of(const nc::CouplingGraph& g) {
  return {g.order().begin(), g.order().end()};
}

// Position of `axis` in the order.
std::size_t rank(const nc::CouplingGraph& g, std::size_t axis) {
  const auto order = g.order();
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (order[i] == axis) return i;
  }
  return order.size();
}

}  // namespace

TEST_CASE("an empty coupling graph orders the axes by index and each axis is its own group",
          "[coupling_graph]") {
  const nc::CouplingGraph g = graph_of(5);
  REQUIRE(g.axis_count() == 5);
  REQUIRE_FALSE(g.has_couplings());
  REQUIRE(order_of(g) == std::vector<uint32_t>{0, 1, 2, 3, 4});
  for (std::size_t i = 0; i < 5; ++i) {
    REQUIRE(g.group(i) == i);
    REQUIRE(g.master_of(i) == nc::CouplingGraph::kNoMaster);
  }
  REQUIRE(g.revision() == 0);
}

TEST_CASE("would_loop refuses self-coupling, loops through chains and unknown axes",
          "[coupling_graph]") {
  nc::CouplingGraph g = graph_of(4);
  REQUIRE(g.would_loop(1, 1));
  REQUIRE(g.would_loop(4, 0));  // no axis 4
  REQUIRE(g.would_loop(0, 4));
  REQUIRE_FALSE(g.would_loop(1, 0));
  REQUIRE(g.couple(1, 0));      // 0 → 1
  REQUIRE(g.couple(2, 1));      // 1 → 2
  REQUIRE(g.would_loop(0, 2));  // 2 → 0 would close 0 → 1 → 2 → 0
  REQUIRE(g.would_loop(0, 1));
  REQUIRE_FALSE(g.would_loop(3, 2));
  REQUIRE_FALSE(g.couple(0, 2));  // refused: nothing changes
  REQUIRE(g.master_of(0) == nc::CouplingGraph::kNoMaster);
  REQUIRE(g.revision() == 2);
}

TEST_CASE("a slave follows one master at a time", "[coupling_graph]") {
  nc::CouplingGraph g = graph_of(3);
  REQUIRE(g.couple(2, 0));
  REQUIRE_FALSE(g.couple(2, 1));
  REQUIRE(g.master_of(2) == 0);
  g.decouple(2);
  REQUIRE(g.couple(2, 1));
  REQUIRE(g.master_of(2) == 1);
}

TEST_CASE("the order puts every master before its slaves, stable in index order",
          "[coupling_graph]") {
  nc::CouplingGraph g = graph_of(6);
  // 5 → 3 → 0 and 4 → 1; axis 2 alone.
  REQUIRE(g.couple(3, 5));
  REQUIRE(g.couple(0, 3));
  REQUIRE(g.couple(1, 4));
  REQUIRE(g.has_couplings());
  REQUIRE(order_of(g) == std::vector<uint32_t>{2, 4, 5, 1, 3, 0});
  for (std::size_t slave = 0; slave < 6; ++slave) {
    const std::size_t master = g.master_of(slave);
    if (master != nc::CouplingGraph::kNoMaster) REQUIRE(rank(g, master) < rank(g, slave));
  }
  // Groups are named by their top master.
  REQUIRE(g.group(0) == 5);
  REQUIRE(g.group(3) == 5);
  REQUIRE(g.group(5) == 5);
  REQUIRE(g.group(1) == 4);
  REQUIRE(g.group(4) == 4);
  REQUIRE(g.group(2) == 2);
}

TEST_CASE("decoupling splits the group and restores index order", "[coupling_graph]") {
  nc::CouplingGraph g = graph_of(4);
  REQUIRE(g.couple(0, 3));
  REQUIRE(g.couple(1, 0));
  REQUIRE(g.group(1) == 3);
  g.decouple(0);
  REQUIRE(g.group(1) == 0);
  REQUIRE(g.group(0) == 0);
  REQUIRE(g.group(3) == 3);
  g.decouple(1);
  REQUIRE_FALSE(g.has_couplings());
  REQUIRE(order_of(g) == std::vector<uint32_t>{0, 1, 2, 3});
  const uint64_t revision = g.revision();
  g.decouple(2);  // not coupled: no change, no recomputation
  REQUIRE(g.revision() == revision);
}
