// fb::HLI_AxisCoupling against a scripted NC side: the semaphore handshake of seed 002 §2 with the
// project's Execute output rules (latched inputs, exclusive outputs, result shown once after a
// falling Execute, no restart while Busy), a pending semaphore of another writer, a null unit.
#include <catch2/catch.hpp>

#include "fb/hli_axis_coupling.hpp"
#include "plc_interface/hli.hpp"

namespace {

namespace h = plc::hli;

// The NC's part: evaluates a pending list (resets the semaphore, answers with `answer`).
struct ScriptedHli {
  h::HLI_AX unit{};
  uint32_t answer = 0;
  int evaluated = 0;
  h::HLI_AX_COUPLING_COMMAND last{};

  void cycle() {
    h::HLI_AX_COUPLING& c = unit.lr_mc_control.axis_coupling;
    if (!c.command_w.semaphor_rw) return;
    ++evaluated;
    last = c.command_w;
    c.command_w.semaphor_rw = false;
    c.state_r.error_r = answer;
  }
};

void check_exclusive(const fb::HLI_AxisCoupling& b) {
  CHECK(int{b.Busy} + int{b.Done} + int{b.Error} <= 1);
  CHECK((b.ErrorID != 0) == b.Error);
}

// Rising edge, one NC cycle, the call that sees the NC's answer.
void trigger(fb::HLI_AxisCoupling& b, ScriptedHli& nc) {
  b.Execute = true;
  b(nc.unit);
  nc.cycle();
  b(nc.unit);
}

fb::HLI_AxisCoupling example_3() {
  fb::HLI_AxisCoupling b;
  b.desc[0] = {8, h::HLI_AXIS_COUPLING_DIRECT, 0, 0};
  b.desc[1] = {1, h::HLI_AXIS_COUPLING_FRACT, -5, 9};
  return b;
}

}  // namespace

TEST_CASE("a rising Execute writes the list and sets the semaphore; Done once the NC took it",
          "[hli][fb]") {
  ScriptedHli nc;
  fb::HLI_AxisCoupling b = example_3();
  b(nc.unit);
  CHECK_FALSE(b.Busy);
  CHECK_FALSE(nc.unit.lr_mc_control.axis_coupling.command_w.semaphor_rw);

  b.Execute = true;
  b(nc.unit);
  CHECK(b.Busy);
  check_exclusive(b);
  const h::HLI_AX_COUPLING_COMMAND& w = nc.unit.lr_mc_control.axis_coupling.command_w;
  CHECK(w.semaphor_rw);
  CHECK(w.desc[1].ax_nr == 1);
  CHECK(w.desc[1].fract_num == -5);
  CHECK(w.desc[1].fract_denom == 9);
  CHECK(w.desc[2].mode == h::HLI_AXIS_COUPLING_INACTIVE);

  b(nc.unit);  // the NC has not run yet
  CHECK(b.Busy);
  nc.cycle();
  b(nc.unit);
  CHECK(b.Done);
  check_exclusive(b);
  for (int i = 0; i < 5; ++i) {  // stays while Execute is high
    nc.cycle();
    b(nc.unit);
    CHECK(b.Done);
  }
  CHECK(nc.evaluated == 1);
  b.Execute = false;
  b(nc.unit);
  CHECK_FALSE(b.Done);
  check_exclusive(b);
}

TEST_CASE("a refused list gives Error with the NC's ID (70397), a new edge starts again",
          "[hli][fb]") {
  ScriptedHli nc;
  nc.answer = 70397;
  fb::HLI_AxisCoupling b = example_3();
  trigger(b, nc);
  CHECK(b.Error);
  CHECK(b.ErrorID == 70397);
  check_exclusive(b);
  // A new rising edge starts again; this time the NC takes it.
  b.Execute = false;
  b(nc.unit);
  CHECK_FALSE(b.Error);
  nc.answer = 0;
  trigger(b, nc);
  CHECK(b.Done);
  CHECK(nc.evaluated == 2);
}

TEST_CASE("a result reached after Execute fell is shown for exactly one call", "[hli][fb]") {
  ScriptedHli nc;
  nc.answer = 70200;
  fb::HLI_AxisCoupling b = example_3();
  b.Execute = true;
  b(nc.unit);
  b.Execute = false;
  b(nc.unit);
  CHECK(b.Busy);  // a falling Execute does not withdraw the list
  nc.cycle();
  b(nc.unit);
  CHECK(b.Error);
  CHECK(b.ErrorID == 70200);
  b(nc.unit);
  CHECK_FALSE(b.Error);
  CHECK(b.ErrorID == 0);
  CHECK_FALSE(b.Busy);
}

TEST_CASE("a rising edge while Busy writes nothing new; inputs are latched at the edge",
          "[hli][fb]") {
  ScriptedHli nc;
  fb::HLI_AxisCoupling b = example_3();
  b.Execute = true;
  b(nc.unit);
  b.desc[1].fract_num = 7;  // after the edge: not taken
  b.Execute = false;
  b(nc.unit);
  b.Execute = true;
  b(nc.unit);  // rising edge while Busy
  CHECK(b.Busy);
  nc.cycle();
  b(nc.unit);
  CHECK(b.Done);
  CHECK(nc.evaluated == 1);
  CHECK(nc.last.desc[1].fract_num == -5);
  nc.cycle();
  CHECK(nc.evaluated == 1);
}

TEST_CASE("a semaphore still set by another writer is waited for, not overwritten", "[hli][fb]") {
  ScriptedHli nc;
  h::HLI_AX_COUPLING_COMMAND& w = nc.unit.lr_mc_control.axis_coupling.command_w;
  w.desc[0] = {3, h::HLI_AXIS_COUPLING_MIRROR, 0, 0};
  w.semaphor_rw = true;  // another program's list, not yet evaluated
  fb::HLI_AxisCoupling b = example_3();
  b.Execute = true;
  b(nc.unit);
  CHECK(b.Busy);
  CHECK(w.desc[0].ax_nr == 3);
  nc.cycle();  // evaluates the other list
  CHECK(nc.last.desc[0].ax_nr == 3);
  b(nc.unit);  // now writes its own
  CHECK(b.Busy);
  CHECK(w.semaphor_rw);
  CHECK(w.desc[0].ax_nr == 8);
  nc.cycle();
  b(nc.unit);
  CHECK(b.Done);
  CHECK(nc.evaluated == 2);
}

TEST_CASE("a null control unit gives Error 0x4F08", "[hli][fb]") {
  fb::HLI_AxisCoupling b = example_3();
  b.Execute = true;
  b(static_cast<h::HLI_AX*>(nullptr));
  CHECK(b.Error);
  CHECK(b.ErrorID == 0x4F08);
  check_exclusive(b);
  ScriptedHli nc;
  h::HLI_AX* units[] = {&nc.unit};
  b.Execute = false;
  b(units[0]);
  b.Execute = true;
  b(units[0]);  // the pointer form, as gpAx[i]
  CHECK(b.Busy);
}
