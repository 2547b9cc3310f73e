// Every bad input of every block, sent to the real kernel while another block's move runs (and
// again at standstill after it), gives Error with its specific ErrorID — and changes nothing:
// the NC→PLC image is bit-identical, cycle by cycle, to the same program run without the bad
// command, and the running move ends exactly as it does there (brief: "a refused command does
// not change the axis"; SPEC A4; seed 000 §2.1 table 2 and notes 4, 5).
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

constexpr double kSwLimitMin = -500.0;   // mm
constexpr double kSwLimitMax = 3'000.0;  // mm

// Which of the two velocity limits is the lower one: a velocity between them is above exactly
// one of them.
enum class Limit { kRefBelowMax, kMaxBelowRef };

nc::AxisConfig axis_config(Limit limit) {
  nc::AxisConfig c;
  c.name = "X";
  c.sw_limit_min_enabled = true;
  c.sw_limit_max_enabled = true;
  c.sw_limit_min = kSwLimitMin;
  c.sw_limit_max = kSwLimitMax;
  c.max_velocity = limit == Limit::kRefBelowMax ? 2'200.0 : 2'000.0;
  c.ref_velocity = limit == Limit::kRefBelowMax ? 2'000.0 : 2'200.0;
  return c;
}

// Every block that can carry a bad input, each with valid inputs; a case spoils one of them.
struct Blocks {
  Blocks() {
    abs.Position = 1'000.0;
    abs.Velocity = 500.0;
    rel.Distance = 100.0;
    rel.Velocity = 500.0;
    velo.Velocity = 500.0;
    velo.Direction = fb::MC_Positive_Direction;
  }
  fb::MC_MoveAbsolute abs;
  fb::MC_MoveRelative rel;
  fb::MC_MoveVelocity velo;
  fb::MC_Halt halt;
  fb::MC_Stop stop;
};

enum class Which { kMoveAbsolute, kMoveRelative, kMoveVelocity, kHalt, kStop, kPower };

struct Case {
  std::string what;
  Which which;
  std::function<void(Blocks&, fb::MC_Power&)> spoil;
  uint32_t code;
  Limit limit = Limit::kRefBelowMax;
};

Shown call_bad(Which which, Blocks& b, fb::MC_Power& power, plc::AXIS_REF& axis, bool execute) {
  auto run = [&](auto& block) { return twin::call_execute(block, axis, execute); };
  switch (which) {
    case Which::kMoveAbsolute:
      return run(b.abs);
    case Which::kMoveRelative:
      return run(b.rel);
    case Which::kMoveVelocity:
      return run(b.velo);
    case Which::kHalt:
      return run(b.halt);
    case Which::kStop:
      return run(b.stop);
    case Which::kPower:
      return Shown{false, power.Error, power.ErrorID};  // called by the program
  }
  return {};
}

// The program of twin_run.hpp; at `inject` (if a case is given) the bad block gets its rising
// edge, and is then called with Execute held high.
Run run(const Case* bad, uint64_t inject, Limit limit) {
  Blocks blocks;
  const twin::Injection injection{inject, [&](fb::MC_Power& power) { bad->spoil(blocks, power); },
                                  [&](fb::MC_Power& power, plc::AXIS_REF& axis) {
                                    return call_bad(bad->which, blocks, power, axis, true);
                                  }};
  return twin::run_program(axis_config(limit), bad != nullptr ? &injection : nullptr);
}

std::vector<Case> cases() {
  std::vector<Case> c;
  using W = Which;
  // A bad value for a velocity-like input: NaN and ±inf (0x4F02), 0 and negative (0x4231),
  // above the reference (and max) velocity and above the max velocity only (0x4221).
  auto velocity_cases = [&](const std::string& block, W which,
                            std::function<void(Blocks&, double)> set) {
    const struct {
      const char* what;
      double v;
      uint32_t code;
      Limit limit;
    } rows[] = {{"NaN", kNaN, 0x4F02, Limit::kRefBelowMax},
                {"+inf", kInf, 0x4F02, Limit::kRefBelowMax},
                {"-inf", -kInf, 0x4F02, Limit::kRefBelowMax},
                {"0", 0.0, 0x4231, Limit::kRefBelowMax},
                {"-500", -500.0, 0x4231, Limit::kRefBelowMax},
                {"2100 above ref 2000 (max 2200)", 2'100.0, 0x4221, Limit::kRefBelowMax},
                {"2100 above max 2000 (ref 2200)", 2'100.0, 0x4221, Limit::kMaxBelowRef},
                {"2300 above both", 2'300.0, 0x4221, Limit::kRefBelowMax}};
    for (const auto& r : rows) {
      const double v = r.v;
      c.push_back({block + ".Velocity = " + r.what, which,
                   [set, v](Blocks& b, fb::MC_Power&) { set(b, v); }, r.code, r.limit});
    }
  };
  // Acceleration, Deceleration, Jerk: NaN and ±inf (0x4F02), negative (0x422F / 0x4230 /
  // 0x422E); 0 means the axis default and is valid.
  auto dynamics_cases = [&](const std::string& block, W which, const std::string& input,
                            uint32_t negative_code, std::function<void(Blocks&, double)> set) {
    const struct {
      const char* what;
      double v;
      uint32_t code;
    } rows[] = {{"NaN", kNaN, 0x4F02},
                {"+inf", kInf, 0x4F02},
                {"-inf", -kInf, 0x4F02},
                {"-1000", -1'000.0, negative_code}};
    for (const auto& r : rows) {
      const double v = r.v;
      c.push_back({block + "." + input + " = " + r.what, which,
                   [set, v](Blocks& b, fb::MC_Power&) { set(b, v); }, r.code});
    }
  };
  auto move_dynamics = [&](const std::string& block, W which, auto member_of) {
    dynamics_cases(block, which, "Acceleration", 0x422F,
                   [member_of](Blocks& b, double v) { member_of(b).Acceleration = v; });
    dynamics_cases(block, which, "Deceleration", 0x4230,
                   [member_of](Blocks& b, double v) { member_of(b).Deceleration = v; });
    dynamics_cases(block, which, "Jerk", 0x422E,
                   [member_of](Blocks& b, double v) { member_of(b).Jerk = v; });
  };

  // MC_MoveAbsolute
  for (const double p : {kNaN, kInf, -kInf}) {
    c.push_back({"MC_MoveAbsolute.Position = " + std::to_string(p), W::kMoveAbsolute,
                 [p](Blocks& b, fb::MC_Power&) { b.abs.Position = p; }, 0x4F01});
  }
  c.push_back({"MC_MoveAbsolute.Position above the software limit max", W::kMoveAbsolute,
               [](Blocks& b, fb::MC_Power&) { b.abs.Position = kSwLimitMax + 0.001; }, 0x4222});
  c.push_back({"MC_MoveAbsolute.Position below the software limit min", W::kMoveAbsolute,
               [](Blocks& b, fb::MC_Power&) { b.abs.Position = kSwLimitMin - 0.001; }, 0x4222});
  velocity_cases("MC_MoveAbsolute", W::kMoveAbsolute,
                 [](Blocks& b, double v) { b.abs.Velocity = v; });
  move_dynamics("MC_MoveAbsolute", W::kMoveAbsolute,
                [](Blocks& b) -> fb::MC_MoveAbsolute& { return b.abs; });
  c.push_back(
      {"MC_MoveAbsolute.BufferMode = 6", W::kMoveAbsolute,
       [](Blocks& b, fb::MC_Power&) { b.abs.BufferMode = static_cast<fb::MC_BufferMode>(6); },
       0x4F03});

  // MC_MoveRelative
  for (const double d : {kNaN, kInf, -kInf}) {
    c.push_back({"MC_MoveRelative.Distance = " + std::to_string(d), W::kMoveRelative,
                 [d](Blocks& b, fb::MC_Power&) { b.rel.Distance = d; }, 0x4F01});
  }
  c.push_back({"MC_MoveRelative.Distance beyond the software limit max", W::kMoveRelative,
               [](Blocks& b, fb::MC_Power&) { b.rel.Distance = 5'000.0; }, 0x4222});
  c.push_back({"MC_MoveRelative.Distance beyond the software limit min", W::kMoveRelative,
               [](Blocks& b, fb::MC_Power&) { b.rel.Distance = -5'000.0; }, 0x4222});
  velocity_cases("MC_MoveRelative", W::kMoveRelative,
                 [](Blocks& b, double v) { b.rel.Velocity = v; });
  move_dynamics("MC_MoveRelative", W::kMoveRelative,
                [](Blocks& b) -> fb::MC_MoveRelative& { return b.rel; });
  c.push_back(
      {"MC_MoveRelative.BufferMode = -1", W::kMoveRelative,
       [](Blocks& b, fb::MC_Power&) { b.rel.BufferMode = static_cast<fb::MC_BufferMode>(-1); },
       0x4F03});

  // MC_MoveVelocity
  velocity_cases("MC_MoveVelocity", W::kMoveVelocity,
                 [](Blocks& b, double v) { b.velo.Velocity = v; });
  move_dynamics("MC_MoveVelocity", W::kMoveVelocity,
                [](Blocks& b) -> fb::MC_MoveVelocity& { return b.velo; });
  // MC_Current_Direction is a valid direction (keep the running motion's), not a bad input.
  for (const fb::MC_Direction d : {fb::MC_Shortest_Way, fb::MC_Undefined_Direction}) {
    c.push_back({"MC_MoveVelocity.Direction = " + std::to_string(static_cast<int>(d)),
                 W::kMoveVelocity, [d](Blocks& b, fb::MC_Power&) { b.velo.Direction = d; },
                 0x4F07});
  }
  c.push_back(
      {"MC_MoveVelocity.BufferMode = 42", W::kMoveVelocity,
       [](Blocks& b, fb::MC_Power&) { b.velo.BufferMode = static_cast<fb::MC_BufferMode>(42); },
       0x4F03});

  // MC_Halt and MC_Stop: Deceleration and Jerk (0 = the running motion's).
  dynamics_cases("MC_Halt", W::kHalt, "Deceleration", 0x4230,
                 [](Blocks& b, double v) { b.halt.Deceleration = v; });
  dynamics_cases("MC_Halt", W::kHalt, "Jerk", 0x422E, [](Blocks& b, double v) { b.halt.Jerk = v; });
  c.push_back(
      {"MC_Halt.BufferMode = 7", W::kHalt,
       [](Blocks& b, fb::MC_Power&) { b.halt.BufferMode = static_cast<fb::MC_BufferMode>(7); },
       0x4F03});
  dynamics_cases("MC_Stop", W::kStop, "Deceleration", 0x4230,
                 [](Blocks& b, double v) { b.stop.Deceleration = v; });
  dynamics_cases("MC_Stop", W::kStop, "Jerk", 0x422E, [](Blocks& b, double v) { b.stop.Jerk = v; });

  // MC_Power: the program's own MC_Power gets a bad Override (written nowhere: 0x4238).
  for (const double o : {kNaN, kInf, -kInf, -0.5, 100.5}) {
    c.push_back({"MC_Power.Override = " + std::to_string(o), W::kPower,
                 [o](Blocks&, fb::MC_Power& p) { p.Override = o; }, 0x4238});
  }
  return c;
}

}  // namespace

TEST_CASE("the reference program moves to 2000 mm and ends Done without any error",
          "[fb][kernel]") {
  const Run ref = run(nullptr, 0, Limit::kRefBelowMax);
  REQUIRE(ref.move_done_tick > 0);
  REQUIRE_FALSE(ref.move_aborted_or_failed);
  REQUIRE(ref.trace.back().set_pos == kMoveTarget);
  REQUIRE(ref.trace.back().act_pos == Approx(kMoveTarget).margin(0.01));
  REQUIRE(ref.trace.back().error_code == 0);
  REQUIRE(ref.trace[300].set_velo > 0.0);  // the injection point mid-move is in motion
}

TEST_CASE(
    "every bad input of every block gives Error with its own ErrorID and changes nothing "
    "in the axis's state or motion",
    "[fb][kernel]") {
  const std::vector<Case> all = cases();
  REQUIRE(all.size() == 97);
  const Run references[] = {run(nullptr, 0, Limit::kRefBelowMax),
                            run(nullptr, 0, Limit::kMaxBelowRef)};
  // Mid-move (cruising toward 2000 mm) and at standstill after the move ended.
  for (const uint64_t inject : {300U, 3'000U}) {
    for (const Case& c : all) {
      INFO(c.what << ", injected at tick " << inject);
      const Run& ref = references[c.limit == Limit::kRefBelowMax ? 0 : 1];
      REQUIRE(ref.move_done_tick > 0);
      REQUIRE(ref.move_done_tick < 3'000);
      const Run bad = run(&c, inject, c.limit);

      twin::require_refused_without_effect(bad, ref, c.code);
    }
  }
}
