// Scope::record is a cycle function: with the storage reserved at set-up it never allocates.
// (Skipped in the sanitizer build: a counting operator new does not mix with its allocator.)
#include <string>

#include <catch2/catch.hpp>

#include "counting_allocator.hpp"
#include "nc_core/scope.hpp"
#include "plc_interface/axis_ref.hpp"

TEST_CASE(
    "recording 10000 cycles of 8 axes into a scope with capacity "
    "allocates nothing") {
  constexpr int kAxes = 8;
  constexpr int kCycles = 10'000;
  static plc::AXIS_REF axes[kAxes];
  nc::Scope scope(kCycles);
  double plc_variable = 0.0;
  for (int i = 0; i < kAxes; ++i) {
    scope.add_motion_signals(axes[i], "Axis" + std::to_string(i + 1));
  }
  scope.add_variable(&plc_variable, "MAIN.Position", "mm");

  ca::g_allocations = 0;
  ca::g_counting = true;
  for (int k = 0; k < kCycles; ++k) {
    for (auto& axis : axes)
      axis.NcToPlc.SetPos = 0.1 * k;
    plc_variable = 2000.0;
    scope.record(0.001 * k);
  }
  scope.record(10.0);  // full: dropped, still no allocation
  ca::g_counting = false;
  const long during = ca::g_allocations;

  CHECK(during == 0);
  CHECK(scope.size() == static_cast<std::size_t>(kCycles));
  CHECK(scope.dropped() == 1);
  CHECK(scope.values(scope.find("Axis8.SetPos"))[kCycles - 1] == 0.1 * (kCycles - 1));
}
