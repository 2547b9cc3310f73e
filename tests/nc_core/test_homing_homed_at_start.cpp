// Homed for real (SPEC F, issue 13 step 1): AxisConfig::homed_at_start gives StateDWord bit 1
// (Homed) and MC_ReadStatus's Status.Homed; the software limits are monitored only while the
// axis is homed (docs/behaviour.md "Homing").
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "fb/mc_read_status.hpp"
#include "kernel_harness.hpp"

using plc::CommandState;
using plc::ErrorCode;

namespace {

nc::AxisConfig limited_axis(bool homed) {
  nc::AxisConfig c = kt::seed_axis();
  c.homed_at_start = homed;
  c.sw_limit_min_enabled = true;
  c.sw_limit_max_enabled = true;
  c.sw_limit_min = -100.0;
  c.sw_limit_max = 100.0;
  return c;
}

}  // namespace

TEST_CASE("homed_at_start defaults to true and gives the Homed bit", "[homing][homed]") {
  CHECK(nc::AxisConfig{}.homed_at_start);
  kt::Harness h;
  CHECK(kt::bit(*h.x, plc::kStateHomed));
  fb::MC_ReadStatus status;
  status.Enable = true;
  status(*h.x);
  CHECK(status.Valid);
  CHECK(status.Status.Homed);
  CHECK_FALSE(status.Status.HomingBusy);
}

TEST_CASE("homed_at_start false: Homed clear, in StateDWord and MC_ReadStatus", "[homing][homed]") {
  nc::AxisConfig c = kt::seed_axis();
  c.homed_at_start = false;
  kt::Harness h(c);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHomed));
  h.cycles(10);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHomed));
  fb::MC_ReadStatus status;
  status.Enable = true;
  status(*h.x);
  CHECK(status.StandStill);
  CHECK_FALSE(status.Status.Homed);
}

TEST_CASE("homed_at_start is read from and written to JSON", "[homing][homed][config]") {
  const nlohmann::json doc = {{"axes", {{{"name", "X"}, {"homed_at_start", false}}}}};
  nc::Kernel kernel = nc::Kernel::from_json(doc);
  CHECK_FALSE(kernel.config("X").homed_at_start);
  kernel.cycle();
  CHECK_FALSE(plc::test_bit(kernel.axis("X").NcToPlc.StateDWord, plc::kStateHomed));

  const nlohmann::json bad = {{"axes", {{{"name", "X"}, {"homed_at_start", 1.5}}}}};
  CHECK_THROWS_WITH(nc::Kernel::from_json(bad), Catch::Contains("/axes/0/homed_at_start"));
}

TEST_CASE("software limits are not monitored before the axis is homed", "[homing][homed]") {
  kt::Harness h(limited_axis(false));
  // Homed: a target at 150 would be refused (0x4222); not homed, it is taken.
  const uint16_t out = h.post(kt::move_absolute(150.0, 500.0));
  REQUIRE(h.cycles_until([&] { return h.state_of(out) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
  CHECK(h.x->NcToPlc.SetPos == 150.0);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateSoftLimitMaxExceeded));
  // MoveVelocity outward from beyond the limit is not refused either.
  const uint16_t further = h.post(kt::move_velocity(100.0, +1));
  h.cycles(5);
  CHECK(h.state_of(further) == CommandState::kActive);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
}

TEST_CASE("software limits are monitored on a homed axis (the same moves are refused)",
          "[homing][homed]") {
  kt::Harness h(limited_axis(true));
  const uint16_t out = h.post(kt::move_absolute(150.0, 500.0));
  h.cycles(1);
  CHECK(h.answer(out).error_code == kt::id(ErrorCode::kTargetPositionNotAllowed));
  CHECK(h.x->NcToPlc.SetPos == 0.0);
}
