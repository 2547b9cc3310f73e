// No allocation in the online functions (brief: real-time discipline in the cycle path): a
// counting global operator new over 20 000 NC cycles in which the override changes, new end
// positions and new velocities (all six cases' kinds, pending activations), modulo starts,
// velocity moves, halts and stops act on a moving axis, counts 0. Runs only in the plain build
// (the sanitizers own the allocator).
#include <catch2/catch.hpp>

#include "counting_allocator.hpp"
#include "kernel_harness.hpp"

TEST_CASE("override, new end positions, new velocities, modulo starts and stops allocate nothing",
          "[no_allocation][override][new_pos][modulo]") {
  kt::Harness h;
  plc::AXIS_REF& x = *h.x;
  ca::g_counting = true;
  for (int k = 0; k < 20000; ++k) {
    switch (k % 2000) {
      case 0:
        x.Mailbox.post(kt::move_absolute(k % 4000 == 0 ? 5000.0 : 0.0, 2000.0));
        break;
      case 300:
        kt::set_override(x, 75.0);
        break;
      case 400:
        x.Mailbox.post(kt::new_pos_and_velo(k % 4000 == 0 ? 4000.0 : 1000.0, 1500.0,
                                            k % 4000 == 0 ? 3000.0 : 2000.0));
        break;
      case 600:
        kt::set_override(x, 0.0);
        break;
      case 900:
        kt::set_override(x, 100.0);
        break;
      case 1000:
        x.Mailbox.post(kt::new_pos(k % 4000 == 0 ? 1000.0 : 4000.0));  // reversal
        break;
      case 1200:
        x.Mailbox.post(kt::move_modulo(540.0, 1500.0, 2));
        break;
      case 1500:
        x.Mailbox.post(kt::move_velocity(1000.0, 4));
        break;
      case 1700:
        x.Mailbox.post(kt::simple(plc::CommandType::kHalt, 8000.0, 90000.0));
        break;
      case 1800:
        x.Mailbox.post(kt::simple(plc::CommandType::kStop));
        break;
      case 1990:
        x.Mailbox.post(kt::simple(plc::CommandType::kStopRelease));
        break;
      default:
        break;
    }
    h.kernel.cycle();
  }
  ca::g_counting = false;
  CHECK(ca::g_allocations == 0);
  CHECK(x.NcToPlc.ErrorCode == 0);
}
