// No allocation in BufferMode (real-time discipline in the cycle path): a counting global operator
// new over 30 000 NC cycles in which buffered and blending commands of every kind wait, plan
// their pass (bisections included), take over, are refused while one waits, re-plan under an
// override change and a new end position, and are dropped by MC_Stop — counts 0. Runs only in
// the plain build (the sanitizers own the allocator).
#include <catch2/catch.hpp>

#include "counting_allocator.hpp"
#include "kernel_harness.hpp"

namespace {

plc::Command with_mode(plc::Command c, plc::MC_BufferMode mode) {
  c.buffer_mode = mode;
  return c;
}

}  // namespace

TEST_CASE("buffered and blending commands allocate nothing", "[no_allocation][buffer]") {
  kt::Harness h;
  plc::AXIS_REF& x = *h.x;
  // Built before counting: the commands are plain data, posting copies them.
  const plc::MC_BufferMode modes[] = {plc::MC_Buffered, plc::MC_BlendingLow,
                                      plc::MC_BlendingPrevious, plc::MC_BlendingNext,
                                      plc::MC_BlendingHigh};
  int waited = 0;   // cycles in which a buffered command waited (kBuffered)
  int refused = 0;  // third commands refused with 0x4F60
  uint16_t buffered = 0;
  uint16_t third = 0;
  ca::g_counting = true;
  for (int k = 0; k < 30000; ++k) {
    const plc::MC_BufferMode mode = modes[(k / 3000) % 5];
    const bool odd = (k / 3000) % 2 == 1;
    switch (k % 3000) {
      case 0:
        x.Mailbox.post(kt::move_absolute(odd ? 0.0 : 3000.0, 1000.0));
        break;
      case 10:
        buffered = x.Mailbox.post(with_mode(kt::move_relative(odd ? -500.0 : 500.0, 2000.0), mode));
        break;
      case 20:  // refused: one already waits
        third = x.Mailbox.post(with_mode(kt::move_absolute(100.0, 500.0), mode));
        break;
      case 300:
        kt::set_override(x, 60.0);  // the pass is re-planned
        break;
      case 500:
        kt::set_override(x, 100.0);
        break;
      case 700:
        x.Mailbox.post(kt::new_pos(odd ? 200.0 : 2800.0));  // the pass is re-planned
        break;
      case 2000:
        x.Mailbox.post(with_mode(kt::move_velocity(800.0, odd ? -1 : 1), mode));
        break;
      case 2010:
        x.Mailbox.post(with_mode(kt::simple(plc::CommandType::kHalt), mode));
        break;
      case 2500:
        x.Mailbox.post(with_mode(kt::move_modulo(90.0, 700.0, 1), mode));
        break;
      case 2510:
        x.Mailbox.post(with_mode(kt::move_absolute(odd ? 0.0 : 3000.0, 900.0), mode));
        break;
      case 2600:
        x.Mailbox.post(kt::simple(plc::CommandType::kStop));  // drops the waiting one
        break;
      case 2990:
        x.Mailbox.post(kt::simple(plc::CommandType::kStopRelease));
        break;
      default:
        break;
    }
    h.kernel.cycle();
    if (k % 3000 == 21 && h.answer(third).error_code == kt::id(plc::ErrorCode::kBufferFull)) {
      ++refused;
    }
    if (h.state_of(buffered) == plc::CommandState::kBuffered) ++waited;
  }
  ca::g_counting = false;
  CHECK(ca::g_allocations == 0);
  CHECK(refused == 10);
  CHECK(waited > 1000);
  CHECK(x.NcToPlc.ErrorCode == 0);
}
