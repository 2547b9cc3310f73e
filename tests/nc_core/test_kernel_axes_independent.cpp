// The phases of Kernel::cycle run over all axes (in blocks while nothing is coupled, issue 8):
// an uncoupled axis's NcToPlc must not depend on how many other axes the kernel runs or on where
// the block boundaries fall. 70 axes (three blocks) with different moves, one of them running
// into a following error, are compared cycle by cycle, byte for byte, with each axis alone in
// its own kernel, every field but AxisIndex (the only one that differs) by its bits.
#include <catch2/catch.hpp>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "kernel_harness.hpp"

namespace {

constexpr std::size_t kAxes = 70;

nc::AxisConfig axis_config(std::size_t i) {
  nc::AxisConfig c = kt::seed_axis("axis" + std::to_string(i));
  if (i % 3 == 1) {
    c.drive_model = nc::DriveModel::kFirstOrderLag;
    c.drive_time_constant = 0.002;
    c.drive_dead_time = 0.002;
  }
  if (i == 33) {  // a saturated drive that cannot follow: a following error mid-move
    c.drive_max_velocity = 200.0;
    c.following_error_limit = 1.0;
  }
  return c;
}

plc::Command command_for(std::size_t i) {
  if (i % 4 == 3) return kt::move_velocity(100.0 + static_cast<double>(i), i % 8 == 3 ? 1 : -1);
  return kt::move_absolute(10.0 * static_cast<double>(i + 1),
                           500.0 + 10.0 * static_cast<double>(i));
}

// Every field of the image but AxisIndex, doubles by their bits (so -0.0 differs from 0.0).
std::array<uint64_t, 24> image(const plc::NCTOPLC_AXIS_REF& o) {
  const auto b = [](double x) { return std::bit_cast<uint64_t>(x); };
  return {o.StateDWord,
          o.ErrorCode,
          o.AxisState,
          o.CoupleState,
          b(o.ActPos),
          b(o.ModuloActPos),
          b(o.ActVelo),
          b(o.ActAcc),
          b(o.PosDiff),
          b(o.SetPos),
          b(o.ModuloSetPos),
          b(o.SetVelo),
          b(o.SetAcc),
          b(o.SetJerk),
          b(o.TargetPos),
          b(o.TargetVelo),
          b(o.CompensationDistance),
          o.Warning,
          o.CmdNo,
          o.CmdState,
          o.CycleCounter,
          b(o.CompensationLength),
          b(o.CompensationVelocityDiff),
          0};
}

}  // namespace

TEST_CASE("an uncoupled axis publishes the same NcToPlc whatever the other axes do",
          "[kernel][phases]") {
  nc::Kernel together;
  std::vector<std::unique_ptr<nc::Kernel>> alone;
  std::vector<plc::AXIS_REF*> in_together;
  std::vector<plc::AXIS_REF*> in_alone;
  for (std::size_t i = 0; i < kAxes; ++i) {
    in_together.push_back(&together.add_axis(axis_config(i)));
    alone.push_back(std::make_unique<nc::Kernel>());
    in_alone.push_back(&alone.back()->add_axis(axis_config(i)));
    kt::set_enables(*in_together.back(), true);
    kt::set_enables(*in_alone.back(), true);
  }
  for (int cycle = 0; cycle < 600; ++cycle) {
    if (cycle == 5 || cycle == 300) {
      for (std::size_t i = 0; i < kAxes; ++i) {
        plc::Command c = command_for(i + static_cast<std::size_t>(cycle));
        REQUIRE(in_together[i]->Mailbox.post(c) != 0);
        REQUIRE(in_alone[i]->Mailbox.post(c) != 0);
      }
    }
    together.cycle();
    for (auto& k : alone)
      k->cycle();
    for (std::size_t i = 0; i < kAxes; ++i) {
      INFO("cycle " << cycle << ", axis " << i);
      REQUIRE(in_together[i]->NcToPlc.AxisIndex == static_cast<int32_t>(i));
      REQUIRE(image(in_together[i]->NcToPlc) == image(in_alone[i]->NcToPlc));
    }
  }
  // The scenario did what it is meant to: the saturated axis is in error, the others are not.
  REQUIRE(in_together[33]->NcToPlc.ErrorCode != 0);
  REQUIRE(in_together[0]->NcToPlc.ErrorCode == 0);
}
