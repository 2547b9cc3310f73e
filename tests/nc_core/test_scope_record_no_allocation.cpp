// Scope::record is a cycle function: with the storage reserved at set-up it never allocates.
// (Skipped in the sanitizer build: a counting operator new does not mix with its allocator.)
#include <atomic>
#include <cstdlib>
#include <new>

#include <catch2/catch.hpp>

#include "nc_core/scope.hpp"
#include "plc_interface/axis_ref.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

TEST_CASE("recording 10000 cycles of 8 axes into a scope with capacity allocates nothing") {
  constexpr int kAxes = 8;
  constexpr int kCycles = 10'000;
  static plc::AXIS_REF axes[kAxes];
  nc::Scope scope(kCycles);
  double plc_variable = 0.0;
  for (int i = 0; i < kAxes; ++i) {
    scope.add_motion_signals(axes[i], "Axis" + std::to_string(i + 1));
  }
  scope.add_variable(&plc_variable, "MAIN.Position", "mm");

  const long before = g_allocations.load();
  for (int k = 0; k < kCycles; ++k) {
    for (auto& axis : axes)
      axis.NcToPlc.SetPos = 0.1 * k;
    plc_variable = 2000.0;
    scope.record(0.001 * k);
  }
  scope.record(10.0);  // full: dropped, still no allocation
  const long during = g_allocations.load() - before;

  CHECK(during == 0);
  CHECK(scope.size() == static_cast<std::size_t>(kCycles));
  CHECK(scope.dropped() == 1);
  CHECK(scope.values(scope.find("Axis8.SetPos"))[kCycles - 1] == 0.1 * (kCycles - 1));
}
