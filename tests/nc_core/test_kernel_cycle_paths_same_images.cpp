// The kernel runs phases (b) to (f) axis by axis while nothing is coupled and phase by phase over
// the whole kernel once a coupling exists (docs/architecture.md "One tick"). Both ways must give
// the same images: two kernels with the same six working axes, one of them with a coupled pair
// of two more axes standing beside them, publish bit-identical NcToPlc values for those six in
// every cycle — through moves, an override change, a Halt, a feed-enable error and its reset.
#include <catch2/catch.hpp>

#include <array>
#include <bit>
#include <cstdint>
#include <string>

#include "kernel_harness.hpp"

namespace {

constexpr std::size_t kWorking = 6;

struct Rig {
  nc::Kernel kernel;
  std::array<plc::AXIS_REF*, kWorking + 2> axes{};

  explicit Rig(bool couple_spare_pair) {
    for (std::size_t i = 0; i < axes.size(); ++i) {
      nc::AxisConfig c = kt::seed_axis("axis" + std::to_string(i));
      if (i % 2 == 1) {
        c.drive_model = nc::DriveModel::kFirstOrderLag;
        c.drive_time_constant = 0.002;
        c.drive_dead_time = 0.002;
      }
      axes[i] = &kernel.add_axis(c);
      kt::set_enables(*axes[i], true);
    }
    kernel.cycle();
    if (couple_spare_pair) {
      plc::Command gear;
      gear.type = plc::CommandType::kGearIn;
      gear.ratio = 1.0;
      gear.other_axis = axes[kWorking]->NcToPlc.AxisIndex;
      const uint16_t n = axes[kWorking + 1]->Mailbox.post(gear);
      kernel.cycle();
      REQUIRE(axes[kWorking + 1]->Mailbox.answer(n).state != plc::CommandState::kError);
      REQUIRE(kernel.couplings().has_couplings());
    } else {
      kernel.cycle();
    }
  }

  // The same PLC program on both rigs: cycle `k` of the scenario for working axis `i`.
  void plc(int k, std::size_t i) {
    plc::AXIS_REF& a = *axes[i];
    const double far = 200.0 + 37.0 * static_cast<double>(i);
    if (k == 0)
      (void)a.Mailbox.post(kt::move_absolute(far, 900.0 + 100.0 * static_cast<double>(i)));
    if (k == 150 && i == 1) a.PlcToNc.Override = 400000;  // 40 %: the table is replanned
    if (k == 200 && i == 2) (void)a.Mailbox.post(kt::simple(plc::CommandType::kHalt));
    if (k == 120 && i == 3) kt::set_enables(a, true, false, true);  // feed + gone: 0x4357 ramp
    if (k == 600 && i == 3) {
      kt::set_enables(a, true);
      (void)a.Mailbox.post(kt::simple(plc::CommandType::kReset));
    }
    if (k == 700) (void)a.Mailbox.post(kt::move_absolute(-50.0, 1200.0));
  }
};

uint64_t bits(double x) {
  return std::bit_cast<uint64_t>(x);
}

}  // namespace

TEST_CASE(
    "the axis-by-axis cycle of an uncoupled kernel and the phase-by-phase cycle of a coupled "
    "one publish bit-identical images",
    "[kernel][phases]") {
  Rig alone(false);
  Rig phased(true);
  REQUIRE_FALSE(alone.kernel.couplings().has_couplings());
  int moved = 0;
  for (int k = 0; k < 2000; ++k) {
    for (std::size_t i = 0; i < kWorking; ++i) {
      alone.plc(k, i);
      phased.plc(k, i);
    }
    alone.kernel.cycle();
    phased.kernel.cycle();
    for (std::size_t i = 0; i < kWorking; ++i) {
      const plc::NCTOPLC_AXIS_REF& a = alone.axes[i]->NcToPlc;
      const plc::NCTOPLC_AXIS_REF& b = phased.axes[i]->NcToPlc;
      INFO("cycle " << k << ", axis " << i);
      REQUIRE(bits(a.SetPos) == bits(b.SetPos));
      REQUIRE(bits(a.SetVelo) == bits(b.SetVelo));
      REQUIRE(bits(a.SetAcc) == bits(b.SetAcc));
      REQUIRE(bits(a.SetJerk) == bits(b.SetJerk));
      REQUIRE(bits(a.ActPos) == bits(b.ActPos));
      REQUIRE(bits(a.ActVelo) == bits(b.ActVelo));
      REQUIRE(bits(a.ActAcc) == bits(b.ActAcc));
      REQUIRE(bits(a.PosDiff) == bits(b.PosDiff));
      REQUIRE(bits(a.ModuloActPos) == bits(b.ModuloActPos));
      REQUIRE(bits(a.ModuloSetPos) == bits(b.ModuloSetPos));
      REQUIRE(bits(a.TargetPos) == bits(b.TargetPos));
      REQUIRE(bits(a.TargetVelo) == bits(b.TargetVelo));
      REQUIRE(a.StateDWord == b.StateDWord);
      REQUIRE(a.AxisState == b.AxisState);
      REQUIRE(a.ErrorCode == b.ErrorCode);
      REQUIRE(a.Warning == b.Warning);
      REQUIRE(a.CmdNo == b.CmdNo);
      REQUIRE(a.CmdState == b.CmdState);
      REQUIRE(a.CycleCounter == b.CycleCounter);
      if (a.SetVelo != 0.0) ++moved;
    }
  }
  // The scenario really ran: the axes moved, axis 3 went into error and came back, all ended.
  CHECK(moved > 2000);
  for (std::size_t i = 0; i < kWorking; ++i) {
    INFO("axis " << i);
    CHECK(alone.axes[i]->NcToPlc.ErrorCode == 0);
    CHECK(alone.axes[i]->NcToPlc.SetPos == Approx(-50.0));
  }
}

TEST_CASE("the feed-enable error of the scenario above is raised on the uncoupled kernel",
          "[kernel][phases]") {
  Rig alone(false);
  bool error_seen = false;
  for (int k = 0; k < 400; ++k) {
    for (std::size_t i = 0; i < kWorking; ++i)
      alone.plc(k, i);
    alone.kernel.cycle();
    error_seen = error_seen ||
                 alone.axes[3]->NcToPlc.ErrorCode == kt::id(plc::ErrorCode::kFeedEnablePlusMissing);
  }
  CHECK(error_seen);
}
