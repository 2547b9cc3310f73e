// No allocation in the superpositions' cycle path (brief: real-time discipline): a counting
// global operator new over a positioning with a compensation, its compensation stop, a stop
// during a second compensation, and an external setpoint run (absolute and relative, enable,
// feed, disable) counts 0 — commands posted, answered and packets taken inside the counted
// region. Runs only in the plain build (the sanitizers own the allocator).
#include <catch2/catch.hpp>

#include "counting_allocator.hpp"
#include "kernel_harness.hpp"

TEST_CASE("compensation, compensation stop, stop and external setpoints allocate nothing",
          "[no_allocation][compensation][ext_setpoint]") {
  kt::Harness h;
  kt::Harness lagging = [] {
    nc::AxisConfig c = kt::seed_axis("lag");
    c.drive_model = nc::DriveModel::kFirstOrderLag;
    c.drive_time_constant = 0.005;
    c.drive_dead_time = 0.002;
    c.following_error_limit = 50.0;
    return kt::Harness(c);
  }();
  ca::g_allocations = 0;
  ca::g_counting = true;
  for (kt::Harness* k : {&h, &lagging}) {
    k->post(kt::move_absolute(10000.0, 2000.0));
    k->cycles(600);
    k->post(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0));
    k->cycles(1000);
    k->post(kt::simple(plc::CommandType::kAbortSuperposition));
    k->cycles(500);
    k->post(kt::move_superimposed(-100.0, 300.0, 500.0, 1000.0, 2000.0, 3000.0));
    k->cycles(300);
    k->post(kt::simple(plc::CommandType::kHalt));
    k->cycles(1000);
    k->post(kt::ext_enable(0.0, 2));
    for (int i = 0; i < 500; ++i) {
      kt::feed(*k->x, 0.01 * i, 10.0, 0.0, i < 400 ? 1 : 0);
      k->cycles(1);
    }
    k->post(kt::simple(plc::CommandType::kExtSetPointGenDisable));
    k->cycles(2);
    k->post(kt::ext_enable(0.0, 1));
    const double from = k->x->NcToPlc.SetPos;
    for (int i = 0; i < 500; ++i) {
      kt::feed(*k->x, from + 0.1 * i, 100.0, 0.0, 1);
      k->cycles(1);
    }
    k->post(kt::simple(plc::CommandType::kReset));
    k->cycles(10);
  }
  ca::g_counting = false;
  CHECK(ca::g_allocations == 0);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK(lagging.x->NcToPlc.ErrorCode == 0);
}
