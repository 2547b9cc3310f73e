// Coupling changes allocate nothing once the axes are added (issue 8 item 4: the order and the
// groups are recomputed in place). Runs only in the plain build (the sanitizers own the
// allocator).
#include <catch2/catch.hpp>

#include <cstddef>

#include "counting_allocator.hpp"
#include "nc_core/coupling_graph.hpp"

TEST_CASE("coupling and decoupling allocate nothing once the axes are added",
          "[coupling_graph][no_allocation]") {
  nc::CouplingGraph g;
  for (std::size_t i = 0; i < 64; ++i)
    g.add_axis();
  ca::g_allocations = 0;
  ca::g_counting = true;
  for (std::size_t i = 1; i < 64; ++i)
    (void)g.couple(i, i - 1);  // one chain 0 → 1 → … → 63
  const bool loop = g.would_loop(0, 63);
  for (std::size_t i = 1; i < 64; ++i)
    g.decouple(i);
  ca::g_counting = false;
  REQUIRE(ca::g_allocations == 0);
  REQUIRE(loop);
  REQUIRE(g.revision() == 126);
}
