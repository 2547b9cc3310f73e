// The superpositions are deterministic (ARCHITECTURE: bit-for-bit repeatable runs): two kernels
// given the same commands and packets publish bit-identical NC→PLC images in every cycle through
// compensations (full, scaled, stopped, aborted by a stop) and external setpoint runs.
#include <catch2/catch.hpp>

#include <cmath>

#include "kernel_harness.hpp"

namespace {

// One scripted run, step by step; the same script drives both kernels.
void script(kt::Harness& k, int step) {
  using plc::CommandType;
  switch (step) {
    case 0:
      k.post(kt::move_absolute(10000.0, 2000.0));
      break;
    case 600:
      k.post(kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2500.0, 5000.0));
      break;
    case 1400:
      k.post(kt::simple(CommandType::kAbortSuperposition));
      break;
    case 2000:
      k.post(kt::move_superimposed(-80.0, 200.0, 700.0, 300.0, 2000.0, 2000.0));
      break;
    case 2300:
      k.post(kt::simple(CommandType::kHalt));
      break;
    case 3500:
      k.post(kt::ext_enable(5.0, 2));
      break;
    case 4200:
      k.post(kt::simple(CommandType::kExtSetPointGenDisable));
      break;
    default:
      break;
  }
  if (step >= 3500 && step < 4300) {
    const double t = (step - 3500) * 0.001;
    kt::feed(*k.x, 5.0 * std::sin(3.0 * t), 15.0 * std::cos(3.0 * t), -45.0 * std::sin(3.0 * t),
             step < 4100 ? 1 : 0);
  }
}

}  // namespace

TEST_CASE("runs with compensations and external setpoints are bit-for-bit repeatable",
          "[compensation][ext_setpoint][determinism]") {
  kt::Harness a;
  kt::Harness b;
  for (int step = 0; step < 5000; ++step) {
    script(a, step);
    script(b, step);
    a.cycles(1);
    b.cycles(1);
    REQUIRE(kt::same_image(a.x->NcToPlc, b.x->NcToPlc));
  }
  CHECK(a.x->NcToPlc.ErrorCode == 0);
}
