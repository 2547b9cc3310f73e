// SPEC D4: a refused list is never taken; for 70396, 70397, 70410 (and an unknown axis or mode)
// the list in force stays and nothing moves differently from a twin stage that never got it.
#include <catch2/catch.hpp>

#include <vector>

#include "hli_stage_rig.hpp"

using namespace hlitest;

namespace {

// Two rigs, A = 1, B = 2 (B follows A), C = 3; `mapped` sets P-AXIS-00436 on every axis.
struct Twins {
  Rig tested;
  Rig twin;
  explicit Twins(bool mapped = false) : tested(setups(mapped)), twin(setups(mapped)) {
    for (Rig* r : {&tested, &twin}) {
      r->command(1, {direct(1), inactive()});
      r->cycle();
    }
  }
  static std::vector<nc::hli::AxisSetup> setups(bool mapped) {
    std::vector<nc::hli::AxisSetup> s(3);
    for (int i = 0; i < 3; ++i) {
      s[static_cast<std::size_t>(i)].ax_nr = i + 1;
      s[static_cast<std::size_t>(i)].forward_mapping = mapped;
    }
    return s;
  }
  // Commands `list` on the tested rig's `target`, then moves A and C in both; returns error_r.
  uint32_t refuse(std::size_t target, std::initializer_list<h::HLI_AX_COUPLING_DESC> list) {
    const h::HLI_AX_COUPLING_STATE before = tested.unit(target).state_r;
    tested.command(target, list);
    tested.cycle();
    twin.cycle();
    const uint32_t code = tested.unit(target).state_r.error_r;
    CHECK_FALSE(tested.unit(target).command_w.semaphor_rw);
    CHECK(tested.unit(target).state_r.active_r == before.active_r);
    CHECK(tested.unit(target).state_r.desc == before.desc);
    for (Rig* r : {&tested, &twin}) {
      r->move(0, 40.0, 400.0);
      r->move(2, -15.0, 400.0);
      r->move(1, 5.0, 400.0);
    }
    CHECK(tested.d == twin.d);
    CHECK(tested.dv == twin.dv);
    for (const plc::ErrorCode c : tested.stop)
      CHECK(c == plc::ErrorCode::kNone);
    return code;
  }
};

}  // namespace

TEST_CASE("70396: a FRACT denominator 0 is refused", "[hli]") {
  Twins t;
  CHECK(t.refuse(1, {direct(3), fract(1, 1, 0), inactive()}) == 70396);
  CHECK(t.tested.d[1] == Approx(40.0).margin(1e-9));  // still follows A only
}

TEST_CASE("70397: |K| one above HLI_AXIS_COUPLING_FACT_MAX is refused, exactly it is taken",
          "[hli]") {
  static_assert(h::HLI_AXIS_COUPLING_FACT_MAX == 1000);
  {
    Twins t;
    CHECK(t.refuse(1, {fract(3, 1001, 1)}) == 70397);
  }
  {
    Twins t;
    CHECK(t.refuse(1, {fract(3, -32768, 32)}) == 70397);  // |K| = 1024
  }
  {
    Twins t;
    CHECK(t.refuse(1, {fract(3, 3001, -3)}) == 70397);  // |K| = 1000.33
  }
  Rig rig({1, 2});
  rig.command(1, {fract(1, -1000, 1), inactive()});
  rig.cycle();
  CHECK(rig.unit(1).state_r.error_r == 0);
  CHECK(rig.unit(1).state_r.active_r);
  rig.move(0, 0.5, 10.0);
  CHECK(rig.d[1] == Approx(-500.0).margin(1e-9));
  rig.command(1, {fract(1, 30000, 30), inactive()});  // exactly 1000 as a fraction
  rig.cycle();
  CHECK(rig.unit(1).state_r.error_r == 0);
}

TEST_CASE("70410: with P-AXIS-00436 a loop among distinct axes is refused", "[hli]") {
  SECTION("B follows A; A's list naming B closes the loop") {
    Twins t(true);
    CHECK(t.refuse(0, {direct(2), inactive()}) == 70410);
  }
  SECTION("through a third axis: C follows B, A's list names C") {
    Twins t(true);
    for (Rig* r : {&t.tested, &t.twin}) {
      r->command(2, {direct(2), inactive()});
      r->cycle();
    }
    CHECK(t.refuse(0, {direct(1), mirror(3), inactive()}) == 70410);
  }
}

TEST_CASE("without P-AXIS-00436 the same loop is taken; with it a self entry is taken", "[hli]") {
  {
    Twins t(false);
    t.tested.command(0, {direct(2), inactive()});
    t.tested.cycle();
    CHECK(t.tested.unit(0).state_r.error_r == 0);
    CHECK(t.tested.unit(0).state_r.active_r);
  }
  Twins t(true);
  t.tested.command(0, {direct(1), direct(3), inactive()});  // self entry on A, source C
  t.tested.cycle();
  CHECK(t.tested.unit(0).state_r.error_r == 0);
  CHECK(t.tested.unit(0).state_r.active_r);
}

TEST_CASE("an unknown logical axis number and an unknown mode are refused", "[hli]") {
  {
    Twins t;
    CHECK(t.refuse(1, {direct(3), direct(9), inactive()}) ==
          plc::to_id(plc::ErrorCode::kInvalidAxisReference));
  }
  Twins t;
  CHECK(t.refuse(1, {{3, 5, 1, 1}}) == plc::to_id(plc::ErrorCode::kBlockInputOutOfRange));
}
