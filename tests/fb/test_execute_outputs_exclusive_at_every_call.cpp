// Busy, Done, Error and CommandAborted are mutually exclusive, and so are Active, Done, Error and
// CommandAborted, at EVERY call — over random sequences of Execute edges and NC answers. Also
// checked at every call: Active only while the axis executes the block's command; a result
// stays while Execute stays high and is shown exactly once when Execute is low; and a rising
// edge posts a command exactly when the block was not Busy.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <set>

#include "block_under_test.hpp"

namespace {

#ifdef NCSDK_SANITIZED
constexpr int kSteps = 3'000;
#else
constexpr int kSteps = 30'000;
#endif
constexpr uint32_t kSeed = 20240611;

bool shows_result(const fbtest::Outputs& o) {
  return o.done || o.error || o.aborted;
}

}  // namespace

TEMPLATE_TEST_CASE(
    "outputs stay exclusive and the result rules hold at every call of a random "
    "run",
    "[fb][rules][random]", FBTEST_EXECUTE_BLOCKS) {
  using A = fbtest::Adapter<TestType>;
  std::mt19937 rng(kSeed);
  INFO("random seed " << kSeed);
  WARN("random seed " << kSeed);
  fbtest::Bench<TestType> b;
  TestType other{};
  fb::MC_Reset reset;
  std::uniform_int_distribution<int> dice(0, 99);

  fbtest::Outputs before;
  bool execute_before = false;
  std::size_t expected_posts = 0;
  std::set<uint16_t> own_numbers;  // command numbers this block posted
  int since_cycle = 0;

  for (int step = 0; step < kSteps; ++step) {
    INFO("step " << step);
    const int roll = dice(rng);
    // PLC side: Execute toggles sometimes, then the block runs.
    const bool execute = roll < 30 ? !execute_before : execute_before;
    const bool rising = execute && !execute_before;
    const fbtest::Outputs now = b.call(execute);
    if (rising && !before.busy) ++expected_posts;
    if (b.block.command_number() != 0) own_numbers.insert(b.block.command_number());

    // A result stays while Execute stays high.
    if (shows_result(before) && execute_before && execute) {
      REQUIRE(now.done == before.done);
      REQUIRE(now.error == before.error);
      REQUIRE(now.aborted == before.aborted);
      REQUIRE(now.error_id == before.error_id);
    }
    // Shown with Execute low: gone at the next call (a new edge may make the block Busy).
    if (shows_result(before) && !execute_before) REQUIRE_FALSE(shows_result(now));

    before = now;
    execute_before = execute;

    // Another PLC block sometimes takes the axis, or resets it.
    const int event = dice(rng);
    if constexpr (A::kAbortable) {
      if (event < 5) {
        A::prepare(other);
        other.Execute = !other.Execute;
        other(b.axis);
      }
    }
    if (event >= 5 && event < 8) {
      reset.Execute = !reset.Execute;
      reset(b.axis);
    }

    // NC side: a cycle at least every 4 steps (the mailbox never fills), and scripted answers.
    if (dice(rng) < 60 || ++since_cycle >= 4) {
      since_cycle = 0;
      const int answer = dice(rng);
      if (answer < 10) b.nc.refuse_next(plc::ErrorCode::kVelocityNotAllowed);
      b.nc.cycle();
      if (answer >= 10 && answer < 25) b.nc.finish();
      if (answer >= 25 && answer < 35) b.nc.reach();
      if (answer >= 35 && answer < 38) b.nc.fail(plc::ErrorCode::kFollowingErrorPosition);
    }
  }
  b.nc.cycle();
  std::size_t own_taken = 0;
  for (const plc::Command& c : b.nc.taken()) {
    if (c.type == A::kType && own_numbers.count(c.number) == 1) ++own_taken;
  }
  REQUIRE(own_numbers.size() == expected_posts);
  REQUIRE(own_taken == expected_posts);
  REQUIRE(expected_posts > static_cast<std::size_t>(kSteps / 50));
}
