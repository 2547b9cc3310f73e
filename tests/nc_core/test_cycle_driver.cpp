// The cycle driver (SPEC A2): PLC tasks at integer multiples of the NC cycle, PLC before NC in a
// tick, run_for / run_until, simulated time as ticks · T.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "kernel_harness.hpp"
#include "nc_core/config.hpp"
#include "nc_core/cycle_driver.hpp"

TEST_CASE("tasks run at t = 0, P, 2P, … with periods that are multiples of the NC cycle",
          "[cycle_driver]") {
  nc::Kernel kernel(nc::KernelConfig{0.001});
  nc::CycleDriver driver(kernel);
  std::vector<double> fast, medium, slow;
  driver.add_task("fast", 0.001, [&] { fast.push_back(driver.time()); });
  driver.add_task("medium", 0.002, [&] { medium.push_back(driver.time()); });
  driver.add_task("slow", 0.005, [&] { slow.push_back(driver.time()); });
  driver.run_for(1.0);
  CHECK(driver.ticks() == 1000);
  CHECK(kernel.cycle_count() == 1000);
  CHECK(driver.time() == 1.0);
  REQUIRE(fast.size() == 1000);
  REQUIRE(medium.size() == 500);
  REQUIRE(slow.size() == 200);
  CHECK(fast.front() == 0.0);
  CHECK(medium[1] == 0.002);
  CHECK(slow[3] == 3.0 * 5.0 * 0.001);
  CHECK(slow.back() == 995.0 * 0.001);
}

TEST_CASE("in a tick the PLC tasks run in insertion order before the NC cycle", "[cycle_driver]") {
  nc::Kernel kernel(nc::KernelConfig{0.0005});
  nc::CycleDriver driver(kernel);
  std::vector<int> order;
  std::vector<uint64_t> nc_cycles_seen;
  driver.add_task("second", 0.001, [&] { order.push_back(2); });
  driver.add_task("first", 0.0005, [&] {
    order.push_back(1);
    nc_cycles_seen.push_back(kernel.cycle_count());
  });
  driver.tick();
  driver.tick();
  driver.tick();
  CHECK(order == std::vector<int>{2, 1, 1, 2, 1});
  // The task at tick n sees n completed NC cycles: PLC first, then NC.
  CHECK(nc_cycles_seen == std::vector<uint64_t>{0, 1, 2});
}

TEST_CASE("a command posted by a PLC task is answered by the NC cycle of the same tick",
          "[cycle_driver]") {
  nc::Kernel kernel;
  plc::AXIS_REF& x = kernel.add_axis(kt::seed_axis());
  nc::CycleDriver driver(kernel);
  uint16_t number = 0;
  plc::CommandState seen_in_plc = plc::CommandState::kFree;
  driver.add_task("plc", 0.001, [&] {
    kt::set_enables(x, true);
    if (driver.ticks() == 3) number = x.Mailbox.post(kt::move_absolute(10.0, 100.0));
    if (driver.ticks() == 4) seen_in_plc = x.Mailbox.answer(number).state;
  });
  driver.run_for(0.004);
  CHECK(x.Mailbox.answer(number).state == plc::CommandState::kActive);
  CHECK(x.NcToPlc.CmdNo == number);
  driver.tick();
  CHECK(seen_in_plc == plc::CommandState::kActive);
}

TEST_CASE("run_until stops at the first tick where done() holds, or at the timeout",
          "[cycle_driver]") {
  nc::Kernel kernel;
  nc::CycleDriver driver(kernel);
  CHECK(driver.run_until([&] { return driver.ticks() >= 250; }, 1.0));
  CHECK(driver.ticks() == 250);
  CHECK(driver.run_until([] { return true; }, 1.0));  // already true: no tick
  CHECK(driver.ticks() == 250);
  CHECK_FALSE(driver.run_until([] { return false; }, 0.1));
  CHECK(driver.ticks() == 350);
  CHECK(driver.time() == 350 * 0.001);
  driver.run_for(0.0);
  CHECK(driver.ticks() == 350);
}

TEST_CASE("simulated time is ticks times the cycle, never a running sum", "[cycle_driver]") {
  nc::Kernel kernel(nc::KernelConfig{0.0001});
  nc::CycleDriver driver(kernel);
  driver.run_for(3.7);
  CHECK(driver.ticks() == 37000);
  CHECK(driver.time() == 37000 * 0.0001);
  CHECK(kernel.time() == driver.time());
}

TEST_CASE("task periods that are not whole multiples of the NC cycle are refused",
          "[cycle_driver]") {
  nc::Kernel kernel(nc::KernelConfig{0.001});
  nc::CycleDriver driver(kernel);
  auto body = [] {};
  CHECK_THROWS_AS(driver.add_task("a", 0.0015, body), nc::ConfigError);
  CHECK_THROWS_AS(driver.add_task("b", 0.0005, body), nc::ConfigError);
  CHECK_THROWS_AS(driver.add_task("c", 0.0, body), nc::ConfigError);
  CHECK_THROWS_AS(driver.add_task("d", -0.002, body), nc::ConfigError);
  CHECK_THROWS_AS(driver.add_task("e", std::numeric_limits<double>::quiet_NaN(), body),
                  nc::ConfigError);
  CHECK_THROWS_AS(driver.add_task("f", std::numeric_limits<double>::infinity(), body),
                  nc::ConfigError);
  CHECK_THROWS_AS(driver.add_task("g", 0.002, std::function<void()>{}), nc::ConfigError);
  CHECK(driver.task_count() == 0);
  // Within 1e-9 relative of a whole multiple is a whole multiple.
  CHECK_NOTHROW(driver.add_task("h", 0.003 * (1.0 + 1e-12), body));
  CHECK_NOTHROW(driver.add_task("i", 0.1, body));
  CHECK(driver.task_count() == 2);
  CHECK_THROWS_AS(driver.run_for(-1.0), nc::ConfigError);
  CHECK_THROWS_AS(driver.run_until([] { return false; }, std::nan("")), nc::ConfigError);
}

TEST_CASE("wall-clock pacing makes a tick last at least one NC cycle and changes no result",
          "[cycle_driver]") {
  nc::Kernel paced_kernel(nc::KernelConfig{0.002});
  nc::CycleDriver paced(paced_kernel);
  plc::AXIS_REF& x = paced_kernel.add_axis(kt::seed_axis());
  kt::set_enables(x, true);
  x.Mailbox.post(kt::move_absolute(5.0, 500.0));
  paced.set_realtime_pacing(true);
  CHECK(paced.realtime_pacing());
  const auto start = std::chrono::steady_clock::now();
  paced.run_for(0.05);  // 25 ticks
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(elapsed >= 0.048);  // ticks 1 … 24 each waited for their slot

  nc::Kernel free_kernel(nc::KernelConfig{0.002});
  nc::CycleDriver unpaced(free_kernel);
  plc::AXIS_REF& y = free_kernel.add_axis(kt::seed_axis());
  kt::set_enables(y, true);
  y.Mailbox.post(kt::move_absolute(5.0, 500.0));
  unpaced.run_for(0.05);
  CHECK(kt::same_image(x.NcToPlc, y.NcToPlc));
}
