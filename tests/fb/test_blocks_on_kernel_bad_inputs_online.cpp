// Every bad input of the blocks of issue 4 (MC_SetOverride, MC_NewPos, MC_NewPosAndVelo,
// MC_MoveModulo, MC_MoveVelocity's MC_Current_Direction), sent to the real kernel while another
// block's move runs (and at standstill after it), gives Error with its specific ErrorID — and
// changes nothing: the NC→PLC image is bit-identical, cycle by cycle, to the same program run
// without it, and the running move ends exactly as there (seed 000 §2.2–§2.4: VNew > 0 and at
// most the max velocity, EPos inside the software limits, override 0 … 100 %).
#include <catch2/catch.hpp>

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "fb/fb.hpp"
#include "nc_core/axis_config.hpp"
#include "twin_run.hpp"

namespace {

using twin::kMoveSpeed;
using twin::kMoveTarget;
using twin::Run;
using twin::Shown;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

constexpr uint64_t kMidMove = 300;       // cruising toward 2000 mm
constexpr uint64_t kStandstill = 3'000;  // after the move
constexpr double kSwLimitMin = -500.0;   // mm
constexpr double kSwLimitMax = 3'000.0;  // mm
constexpr double kMaxVelocity = 2'200.0;

nc::AxisConfig axis_config() {
  nc::AxisConfig c;
  c.name = "X";
  c.sw_limit_min_enabled = true;
  c.sw_limit_max_enabled = true;
  c.sw_limit_min = kSwLimitMin;
  c.sw_limit_max = kSwLimitMax;
  c.max_velocity = kMaxVelocity;
  c.ref_velocity = kMaxVelocity;
  return c;
}

// Every block of issue 4, each with valid inputs; a case spoils one of them.
struct Blocks {
  Blocks() {
    set.Enable = true;
    set.VelFactor = 1.0;
    new_pos.NewPos = 1'500.0;
    npv.NewPos = 1'500.0;
    npv.NewVelo = 500.0;
    npv.ActivationPos = 1'000.0;
    modulo.Position = 90.0;
    modulo.Velocity = 500.0;
    modulo.Direction = fb::MC_Positive_Direction;
    velo.Velocity = 500.0;
    velo.Direction = fb::MC_Current_Direction;
  }
  fb::MC_SetOverride set;
  fb::MC_NewPos new_pos;
  fb::MC_NewPosAndVelo npv;
  fb::MC_MoveModulo modulo;
  fb::MC_MoveVelocity velo;
};

enum class Which { kSetOverride, kNewPos, kNewPosAndVelo, kMoveModulo, kMoveVelocity };

struct Case {
  std::string what;
  Which which;
  std::function<void(Blocks&)> spoil;
  uint32_t code;
  std::vector<uint64_t> inject = {kMidMove, kStandstill};
};

Shown call_bad(Which which, Blocks& b, plc::AXIS_REF& axis) {
  auto run = [&](auto& block) { return twin::call_execute(block, axis); };
  switch (which) {
    case Which::kSetOverride:
      b.set(axis);
      return Shown{b.set.Enabled, b.set.Error, b.set.ErrorID};  // "busy": the value is applied
    case Which::kNewPos:
      return run(b.new_pos);
    case Which::kNewPosAndVelo:
      return run(b.npv);
    case Which::kMoveModulo:
      return run(b.modulo);
    case Which::kMoveVelocity:
      return run(b.velo);
  }
  return {};
}

// The program of twin_run.hpp; at `inject` (if a case is given) the bad block gets its rising
// edge (MC_SetOverride: its first enabled call), and is then called with Execute / Enable held
// high.
Run run(const Case* bad, uint64_t inject) {
  Blocks blocks;
  const twin::Injection injection{
      inject, [&](fb::MC_Power&) { bad->spoil(blocks); },
      [&](fb::MC_Power&, plc::AXIS_REF& axis) { return call_bad(bad->which, blocks, axis); }};
  return twin::run_program(axis_config(), bad != nullptr ? &injection : nullptr);
}

std::vector<Case> cases() {
  std::vector<Case> c;
  using W = Which;
  const struct {
    const char* what;
    double v;
  } non_finite[] = {{"NaN", kNaN}, {"+inf", kInf}, {"-inf", -kInf}};

  // MC_SetOverride: VelFactor outside 0 … 1 or not finite — checked by the block, never written.
  for (const double f : {kNaN, kInf, -kInf, -0.01, 1.01, 75.0}) {
    c.push_back({"MC_SetOverride.VelFactor = " + std::to_string(f), W::kSetOverride,
                 [f](Blocks& b) { b.set.VelFactor = f; }, 0x4238});
  }

  // MC_NewPos: NewPos not finite (0x4F01), outside the software limits (0x4222).
  for (const auto& n : non_finite) {
    const double v = n.v;
    c.push_back({std::string("MC_NewPos.NewPos = ") + n.what, W::kNewPos,
                 [v](Blocks& b) { b.new_pos.NewPos = v; }, 0x4F01});
  }
  c.push_back({"MC_NewPos.NewPos above the software limit max", W::kNewPos,
               [](Blocks& b) { b.new_pos.NewPos = kSwLimitMax + 0.001; }, 0x4222});
  c.push_back({"MC_NewPos.NewPos below the software limit min", W::kNewPos,
               [](Blocks& b) { b.new_pos.NewPos = kSwLimitMin - 0.001; }, 0x4222});
  // A valid NewPos with no positioning running: function not allowed.
  c.push_back({"MC_NewPos at standstill", W::kNewPos, [](Blocks&) {}, 0x424E, {kStandstill}});

  // MC_NewPosAndVelo: EPos not finite (0x4F01); VNew or APos not finite (0x4F02); VNew <= 0
  // (0x4231) or above the max velocity (0x4221); EPos outside the software limits (0x4222).
  for (const auto& n : non_finite) {
    const double v = n.v;
    c.push_back({std::string("MC_NewPosAndVelo.NewPos = ") + n.what, W::kNewPosAndVelo,
                 [v](Blocks& b) { b.npv.NewPos = v; }, 0x4F01});
    c.push_back({std::string("MC_NewPosAndVelo.NewVelo = ") + n.what, W::kNewPosAndVelo,
                 [v](Blocks& b) { b.npv.NewVelo = v; }, 0x4F02});
    c.push_back({std::string("MC_NewPosAndVelo.ActivationPos = ") + n.what, W::kNewPosAndVelo,
                 [v](Blocks& b) { b.npv.ActivationPos = v; }, 0x4F02});
  }
  for (const double v : {0.0, -500.0}) {
    c.push_back({"MC_NewPosAndVelo.NewVelo = " + std::to_string(v), W::kNewPosAndVelo,
                 [v](Blocks& b) { b.npv.NewVelo = v; }, 0x4231});
  }
  c.push_back({"MC_NewPosAndVelo.NewVelo above the max velocity", W::kNewPosAndVelo,
               [](Blocks& b) { b.npv.NewVelo = kMaxVelocity + 0.001; }, 0x4221});
  c.push_back({"MC_NewPosAndVelo.NewPos above the software limit max", W::kNewPosAndVelo,
               [](Blocks& b) { b.npv.NewPos = kSwLimitMax + 0.001; }, 0x4222});
  c.push_back({"MC_NewPosAndVelo.NewPos below the software limit min", W::kNewPosAndVelo,
               [](Blocks& b) { b.npv.NewPos = kSwLimitMin - 0.001; }, 0x4222});
  c.push_back(
      {"MC_NewPosAndVelo at standstill", W::kNewPosAndVelo, [](Blocks&) {}, 0x424E, {kStandstill}});

  // MC_MoveModulo: Position not finite (0x4F01), absurdly many turns (0x4282), an end beyond
  // the software limit (0x4222); Velocity and dynamics as every move; Direction and BufferMode
  // checked by the block (0x4F07, 0x4F03); MC_Current_Direction at standstill (0x4F07).
  for (const auto& n : non_finite) {
    const double v = n.v;
    c.push_back({std::string("MC_MoveModulo.Position = ") + n.what, W::kMoveModulo,
                 [v](Blocks& b) { b.modulo.Position = v; }, 0x4F01});
    c.push_back({std::string("MC_MoveModulo.Velocity = ") + n.what, W::kMoveModulo,
                 [v](Blocks& b) { b.modulo.Velocity = v; }, 0x4F02});
    c.push_back({std::string("MC_MoveModulo.Acceleration = ") + n.what, W::kMoveModulo,
                 [v](Blocks& b) { b.modulo.Acceleration = v; }, 0x4F02});
    c.push_back({std::string("MC_MoveModulo.Deceleration = ") + n.what, W::kMoveModulo,
                 [v](Blocks& b) { b.modulo.Deceleration = v; }, 0x4F02});
    c.push_back({std::string("MC_MoveModulo.Jerk = ") + n.what, W::kMoveModulo,
                 [v](Blocks& b) { b.modulo.Jerk = v; }, 0x4F02});
  }
  c.push_back({"MC_MoveModulo.Position = 1e15 (too many turns)", W::kMoveModulo,
               [](Blocks& b) { b.modulo.Position = 1e15; }, 0x4282});
  c.push_back({"MC_MoveModulo.Position = 3600 (10 turns) beyond the software limit max",
               W::kMoveModulo, [](Blocks& b) { b.modulo.Position = 3'600.0; }, 0x4222});
  for (const double v : {0.0, -500.0}) {
    c.push_back({"MC_MoveModulo.Velocity = " + std::to_string(v), W::kMoveModulo,
                 [v](Blocks& b) { b.modulo.Velocity = v; }, 0x4231});
  }
  c.push_back({"MC_MoveModulo.Velocity above the max velocity", W::kMoveModulo,
               [](Blocks& b) { b.modulo.Velocity = kMaxVelocity + 0.001; }, 0x4221});
  c.push_back({"MC_MoveModulo.Acceleration < 0", W::kMoveModulo,
               [](Blocks& b) { b.modulo.Acceleration = -1.0; }, 0x422F});
  c.push_back({"MC_MoveModulo.Deceleration < 0", W::kMoveModulo,
               [](Blocks& b) { b.modulo.Deceleration = -1.0; }, 0x4230});
  c.push_back(
      {"MC_MoveModulo.Jerk < 0", W::kMoveModulo, [](Blocks& b) { b.modulo.Jerk = -1.0; }, 0x422E});
  for (const int d : {0, 5, 128, -1}) {
    c.push_back({"MC_MoveModulo.Direction = " + std::to_string(d), W::kMoveModulo,
                 [d](Blocks& b) { b.modulo.Direction = static_cast<fb::MC_Direction>(d); },
                 0x4F07});
  }
  c.push_back({"MC_MoveModulo.BufferMode = 6", W::kMoveModulo,
               [](Blocks& b) { b.modulo.BufferMode = static_cast<fb::MC_BufferMode>(6); }, 0x4F03});
  c.push_back({"MC_MoveModulo.Direction = MC_Current_Direction at standstill",
               W::kMoveModulo,
               [](Blocks& b) { b.modulo.Direction = fb::MC_Current_Direction; },
               0x4F07,
               {kStandstill}});

  // MC_MoveVelocity with MC_Current_Direction at standstill: there is no direction to keep.
  c.push_back({"MC_MoveVelocity.Direction = MC_Current_Direction at standstill",
               W::kMoveVelocity,
               [](Blocks&) {},
               0x4F07,
               {kStandstill}});
  return c;
}

}  // namespace

TEST_CASE("the reference program moves to 2000 mm and ends Done without any error",
          "[fb][kernel][online]") {
  const Run ref = run(nullptr, 0);
  REQUIRE(ref.move_done_tick > 0);
  REQUIRE(ref.move_done_tick < static_cast<int64_t>(kStandstill));
  REQUIRE_FALSE(ref.move_aborted_or_failed);
  REQUIRE(ref.trace.back().set_pos == kMoveTarget);
  REQUIRE(ref.trace.back().error_code == 0);
  REQUIRE(ref.trace[kMidMove].set_velo > 0.0);  // the mid-move injection point is in motion
  REQUIRE(ref.trace[kStandstill].set_velo == 0.0);
}

TEST_CASE(
    "every bad input of the blocks of issue 4 gives Error with its own ErrorID and changes "
    "nothing in the axis's state or motion",
    "[fb][kernel][online]") {
  const std::vector<Case> all = cases();
  REQUIRE(all.size() == 57);
  const Run ref = run(nullptr, 0);
  for (const Case& c : all) {
    for (const uint64_t inject : c.inject) {
      INFO(c.what << ", injected at tick " << inject);
      const Run bad = run(&c, inject);

      twin::require_refused_without_effect(bad, ref, c.code);
    }
  }
}

TEST_CASE(
    "the valid inputs of the same blocks are accepted by the kernel (the bad cases differ "
    "from them in one input only)",
    "[fb][kernel][online]") {
  // Mid-move, each block with its valid inputs: no Error (MC_NewPos / MC_NewPosAndVelo Done,
  // MC_MoveModulo / MC_MoveVelocity Busy, MC_SetOverride Enabled).
  for (const Which which : {Which::kSetOverride, Which::kNewPos, Which::kNewPosAndVelo,
                            Which::kMoveModulo, Which::kMoveVelocity}) {
    INFO("block " << static_cast<int>(which));
    const Case good{"valid", which, [](Blocks&) {}, 0, {kMidMove}};
    const Run r = run(&good, kMidMove);
    REQUIRE(r.bad.size() > 2);
    REQUIRE_FALSE(r.bad[1].error);
    REQUIRE(r.bad[1].error_id == 0);
  }
}
