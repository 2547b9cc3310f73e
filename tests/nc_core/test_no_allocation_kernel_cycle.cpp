// No allocation in the cycle path (brief, ARCHITECTURE "One tick"): a counting global operator
// new over 10 000 NC cycles of 8 moving axes, with their MC_Power and MC_MoveAbsolute blocks
// called every cycle, counts 0; so does Kernel::snapshot() between cycles, which fills the snapshot
// in, and the kept image's check. Runs only in the plain build (the sanitizers own the allocator).
#include <catch2/catch.hpp>

#include <array>
#include <string>

#include "counting_allocator.hpp"
#include "fb/fb.hpp"
#include "kernel_harness.hpp"

TEST_CASE(
    "10000 cycles of 8 moving axes with their MC_Power and MC_MoveAbsolute blocks "
    "allocate nothing",
    "[no_allocation]") {
  constexpr int kAxes = 8;
  nc::Kernel kernel;
  std::array<plc::AXIS_REF*, kAxes> axes{};
  for (int i = 0; i < kAxes; ++i) {
    nc::AxisConfig c = kt::seed_axis("axis" + std::to_string(i));
    if (i % 2 == 1) {  // half of them with the lagging drive and its dead-time line
      c.drive_model = nc::DriveModel::kFirstOrderLag;
      c.drive_time_constant = 0.002;
      c.drive_dead_time = 0.002;
    }
    axes[static_cast<std::size_t>(i)] = &kernel.add_axis(c);
  }
  std::array<fb::MC_Power, kAxes> power{};
  std::array<fb::MC_MoveAbsolute, kAxes> move{};
  std::array<int, kAxes> done_count{};
  int faults = 0;  // an axis error in a snapshot, or a kept image unlike its recomputation

  // Sanity check of the counter itself: it sees an allocation when one happens.
  ca::g_counting = true;
  auto* probe = new int(7);
  ca::g_counting = false;
  delete probe;
  REQUIRE(ca::g_allocations == 1);
  ca::g_allocations = 0;

  ca::g_counting = true;
  for (int cycle = 0; cycle < 10000; ++cycle) {
    for (std::size_t i = 0; i < kAxes; ++i) {
      plc::AXIS_REF& axis = *axes[i];
      power[i].Enable = true;
      power[i].Enable_Positive = true;
      power[i].Enable_Negative = true;
      power[i](axis);
      fb::MC_MoveAbsolute& m = move[i];
      if (m.Done) {
        ++done_count[i];
        m.Execute = false;  // falling edge; the next call starts the way back
      } else if (power[i].Status && !m.Busy) {
        m.Execute = true;
        m.Position = done_count[i] % 2 == 0 ? 300.0 + 10.0 * static_cast<double>(i) : 0.0;
        m.Velocity = 1500.0;
      }
      m(axis);
    }
    kernel.cycle();
    // Between cycles: the snapshot filled in and the kept image's check allocate nothing either.
    const auto k = static_cast<std::size_t>(cycle) % kAxes;
    if (kernel.snapshot(k).error != plc::ErrorCode::kNone) ++faults;
    if (!kernel.published_image_consistent(k)) ++faults;
  }
  ca::g_counting = false;

  CHECK(ca::g_allocations == 0);
  CHECK(faults == 0);
  for (std::size_t i = 0; i < kAxes; ++i) {
    INFO("axis " << i);
    CHECK(done_count[i] >= 8);  // the axes really moved back and forth
    CHECK(axes[i]->NcToPlc.ErrorCode == 0);
  }
}
