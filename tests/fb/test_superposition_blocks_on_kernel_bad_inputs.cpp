// Every bad input of the superposition blocks (MC_MoveSuperImposed, MC_AbortSuperposition,
// MC_ExtSetPointGenEnable, MC_ExtSetPointGenFeed), sent to the real kernel while another block's
// move runs and again at standstill after it, gives its specific ErrorID and changes nothing: the
// NC→PLC image is bit-identical, cycle by cycle, to the same program run without the bad block,
// and the running move ends exactly as there (seed 000 §2.5 "start parameters": L, VP, VK, AK+,
// AK- > 0 and D ≠ 0; §2.6 start types absolute (1) and relative (2); feed directions -1, 0, +1).
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

// The superposition blocks, each with valid inputs; a case spoils one of them.
struct Blocks {
  Blocks() {
    comp.Distance = 50.0;
    comp.Length = 1'000.0;
    comp.VelocityProcess = kMoveSpeed;
    comp.VelocityDiff = 100.0;
    comp.Acceleration = 500.0;
    comp.Deceleration = 500.0;
    enable.Position = kMoveTarget;
    enable.PositionType = fb::POSITIONTYPE_RELATIVE;  // allowed beside a running move
  }
  fb::MC_MoveSuperImposed comp;
  fb::MC_AbortSuperposition abort;
  fb::MC_ExtSetPointGenEnable enable;
  double feed_position = 0.0;
  int32_t feed_direction = 1;
};

enum class Which { kMoveSuperImposed, kAbortSuperposition, kExtSetPointGenEnable, kFeed };

struct Case {
  std::string what;
  Which which;
  std::function<void(Blocks&)> spoil;
  uint32_t code;
};

Shown call_bad(Which which, Blocks& b, plc::AXIS_REF& axis) {
  auto run = [&](auto& block) { return twin::call_execute(block, axis); };
  switch (which) {
    case Which::kMoveSuperImposed:
      return run(b.comp);
    case Which::kAbortSuperposition:
      return run(b.abort);
    case Which::kExtSetPointGenEnable:
      return run(b.enable);
    case Which::kFeed: {
      const uint32_t id =
          fb::MC_ExtSetPointGenFeed(b.feed_position, 0.0, 0.0, b.feed_direction, axis);
      return Shown{false, id != 0, id};
    }
  }
  return {};
}

// The program of twin_run.hpp; at `inject` the bad block gets its rising edge (or the feed its
// first call) and is then called every cycle with Execute held high.
Run run(const Case* bad, uint64_t inject) {
  nc::AxisConfig config;
  config.name = "X";
  Blocks blocks;
  const twin::Injection injection{
      inject, [&](fb::MC_Power&) { bad->spoil(blocks); },
      [&](fb::MC_Power&, plc::AXIS_REF& axis) { return call_bad(bad->which, blocks, axis); }};
  return twin::run_program(config, bad != nullptr ? &injection : nullptr);
}

std::vector<Case> cases() {
  std::vector<Case> c;
  using W = Which;
  const auto comp = [&](const std::string& what, std::function<void(fb::MC_MoveSuperImposed&)> f,
                        uint32_t code) {
    c.push_back(
        {"MC_MoveSuperImposed." + what, W::kMoveSuperImposed, [f](Blocks& b) { f(b.comp); }, code});
  };
  // D: not finite 0x4F01, 0 0x4244.
  for (const double d : {kNaN, kInf, -kInf}) {
    comp(
        "Distance = " + std::to_string(d), [d](auto& b) { b.Distance = d; }, 0x4F01);
  }
  comp(
      "Distance = 0", [](auto& b) { b.Distance = 0.0; }, 0x4244);
  // L, VP, VK, AK+, AK-: not finite 0x4F02; <= 0 their own code.
  const struct {
    const char* input;
    double fb::MC_MoveSuperImposed::*member;
    uint32_t code;
  } positive[] = {{"Length", &fb::MC_MoveSuperImposed::Length, 0x4270},
                  {"VelocityProcess", &fb::MC_MoveSuperImposed::VelocityProcess, 0x4271},
                  {"VelocityDiff", &fb::MC_MoveSuperImposed::VelocityDiff, 0x4271},
                  {"Acceleration", &fb::MC_MoveSuperImposed::Acceleration, 0x4272},
                  {"Deceleration", &fb::MC_MoveSuperImposed::Deceleration, 0x4272}};
  for (const auto& p : positive) {
    const auto member = p.member;
    for (const double v : {kNaN, kInf, -kInf}) {
      comp(
          std::string(p.input) + " = " + std::to_string(v), [member, v](auto& b) { b.*member = v; },
          0x4F02);
    }
    for (const double v : {0.0, -1.0}) {
      comp(
          std::string(p.input) + " = " + std::to_string(v), [member, v](auto& b) { b.*member = v; },
          p.code);
    }
  }
  // MC_AbortSuperposition with no compensation running.
  c.push_back({"MC_AbortSuperposition without a compensation", W::kAbortSuperposition,
               [](Blocks&) {}, 0x4246});
  // MC_ExtSetPointGenEnable: a PositionType outside E_PositionType (the block's check), a
  // target that is not finite (the NC's).
  for (const int type : {0, 3, -1}) {
    c.push_back(
        {"MC_ExtSetPointGenEnable.PositionType = " + std::to_string(type), W::kExtSetPointGenEnable,
         [type](Blocks& b) { b.enable.PositionType = static_cast<fb::E_PositionType>(type); },
         0x4239});
  }
  for (const double p : {kNaN, kInf}) {
    c.push_back({"MC_ExtSetPointGenEnable.Position = " + std::to_string(p),
                 W::kExtSetPointGenEnable, [p](Blocks& b) { b.enable.Position = p; }, 0x4F01});
  }
  // MC_ExtSetPointGenFeed: a direction outside -1, 0, +1 writes nothing.
  for (const int32_t d : {2, -2, 1000}) {
    c.push_back({"MC_ExtSetPointGenFeed Direction = " + std::to_string(d), W::kFeed,
                 [d](Blocks& b) {
                   b.feed_direction = d;
                   b.feed_position = 123.0;
                 },
                 0x4F07});
  }
  return c;
}

}  // namespace

TEST_CASE("a valid compensation on the same program is accepted and moves the end by D",
          "[fb][kernel][superimposed]") {
  // The control case: the program and the blocks' default inputs do reach the NC, so an
  // identical image in the bad cases means "refused", not "never sent".
  const Case valid{"valid", Which::kMoveSuperImposed, [](Blocks&) {}, 0};
  const Run ref = run(nullptr, 0);
  const Run ok = run(&valid, 400);
  REQUIRE(ref.move_done_tick > 0);
  REQUIRE(ref.trace.back().set_pos == kMoveTarget);
  REQUIRE(ok.bad.size() > 2);
  CHECK(ok.bad[1].busy);
  CHECK_FALSE(ok.bad[1].error);
  CHECK(ok.trace.back().set_pos == Approx(kMoveTarget + 50.0).margin(1e-9));
  CHECK(ok.trace.back().compensation_distance == Approx(50.0).margin(1e-9));
}

TEST_CASE(
    "every bad input of the superposition blocks gives its own ErrorID and changes nothing "
    "in the axis's state or motion",
    "[fb][kernel][superimposed]") {
  const std::vector<Case> all = cases();
  REQUIRE(all.size() == 4 + 5 * 5 + 1 + 3 + 2 + 3);
  const Run ref = run(nullptr, 0);
  REQUIRE(ref.move_done_tick > 0);
  REQUIRE(ref.move_done_tick < 3'000);
  REQUIRE(ref.trace[400].set_velo == kMoveSpeed);  // mid-move injection: cruising
  // Mid-move (cruising toward 2000 mm) and at standstill after the move ended.
  for (const uint64_t inject : {400U, 3'000U}) {
    for (const Case& c : all) {
      INFO(c.what << ", injected at tick " << inject);
      const Run bad = run(&c, inject);
      twin::require_refused_without_effect(bad, ref, c.code);
    }
  }
}
