// The ways an Execute-type block's command can end, produced on a ScriptedNc, with the outputs
// the block must then show. Shared by the output-rule suites.
#pragma once

#include <catch2/catch.hpp>

#include "block_under_test.hpp"

namespace fbtest {

enum class Outcome {
  kDone,     // the job ends (positioning reached, standstill, reset done)
  kRefused,  // the NC refuses the command at acceptance: 0x4221
  kFailed,   // the axis goes into error during the job: 0x4550
  kAborted,  // another command takes the axis
};

inline const char* name(Outcome o) {
  switch (o) {
    case Outcome::kDone:
      return "done";
    case Outcome::kRefused:
      return "refused";
    case Outcome::kFailed:
      return "failed";
    case Outcome::kAborted:
      return "aborted";
  }
  return "?";
}

template <class B>
bool applies(Outcome o) {
  using A = Adapter<B>;
  switch (o) {
    case Outcome::kDone:
      return A::kHasDone;
    case Outcome::kRefused:
      return true;
    case Outcome::kFailed:
    case Outcome::kAborted:
      return A::kAbortable;
  }
  return false;
}

// Brings the block's posted command to `o` on the NC side, calling the block with Execute
// unchanged on the way where the job has to run first. `other` is a second block of the same
// type on the same axis, used to take the axis over.
template <class B>
void produce(Bench<B>& b, B& other, Outcome o) {
  switch (o) {
    case Outcome::kDone:
      b.nc.cycle();
      b.nc.finish();
      break;
    case Outcome::kRefused:
      b.nc.refuse_next(plc::ErrorCode::kVelocityNotAllowed);
      b.nc.cycle();
      break;
    case Outcome::kFailed:
      b.nc.cycle();
      REQUIRE(shows_running<B>(b.call()));
      b.nc.fail(plc::ErrorCode::kFollowingErrorPosition);
      break;
    case Outcome::kAborted:
      b.nc.cycle();
      REQUIRE(shows_running<B>(b.call()));
      if constexpr (requires { Adapter<B>::take_over(b.axis); }) {
        Adapter<B>::take_over(b.axis);
      } else {
        Adapter<B>::prepare(other);
        other.Execute = true;
        other(b.axis);
      }
      b.nc.cycle();
      break;
  }
}

// The outputs that show `o`, and only it.
inline void require_shows(const Outputs& out, Outcome o) {
  INFO("outcome " << name(o));
  REQUIRE_FALSE(out.busy);
  REQUIRE_FALSE(out.active);
  REQUIRE(out.done == (o == Outcome::kDone));
  REQUIRE(out.aborted == (o == Outcome::kAborted));
  REQUIRE(out.error == (o == Outcome::kRefused || o == Outcome::kFailed));
  const uint32_t id = o == Outcome::kRefused ? 0x4221U : o == Outcome::kFailed ? 0x4550U : 0U;
  REQUIRE(out.error_id == id);
}

inline void require_all_reset(const Outputs& out) {
  REQUIRE_FALSE(out.busy);
  REQUIRE_FALSE(out.active);
  REQUIRE_FALSE(out.done);
  REQUIRE_FALSE(out.in_velocity);
  REQUIRE_FALSE(out.aborted);
  REQUIRE_FALSE(out.error);
  REQUIRE(out.error_id == 0);
}

}  // namespace fbtest
