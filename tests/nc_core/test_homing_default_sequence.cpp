// MC_DefaultHoming, the NC's sequence on the simulated reference cam (SPEC F, issue 13): cam at
// 100 … 110 mm, start at 0, 100 mm/s towards the cam (positive), 10 mm/s off it (back, negative),
// a sync pulse every 5 mm of the raw encoder, Position 0. The cam signal goes through the PLC
// (kt::cam_cycle), so the NC sees it one cycle late, as it would on a machine.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "homing_rig.hpp"

using plc::AxisState;
using plc::CommandState;
using plc::ErrorCode;

namespace {

struct Run {
  std::vector<kt::Sample> samples;  // one per NC cycle after the command was posted
  int done_at = -1;                 // index of the cycle that answered Done (or Error)
};

Run home_until_outcome(kt::Harness& h, uint16_t number, int limit = 200000) {
  Run run;
  for (int i = 0; i < limit; ++i) {
    kt::cam_cycle(h);
    run.samples.push_back(kt::sample(*h.x));
    const CommandState s = h.state_of(number);
    if (s == CommandState::kDone || s == CommandState::kError || s == CommandState::kAborted) {
      run.done_at = i;
      break;
    }
  }
  return run;
}

// The cycle whose actual position jumped by more than `size` against the cycle before (-1: none).
int jump(const Run& run, double size) {
  for (std::size_t i = 1; i < run.samples.size(); ++i) {
    if (std::abs(run.samples[i].act_pos - run.samples[i - 1].act_pos) > size)
      return static_cast<int>(i);
  }
  return -1;
}

// The published cycles before and after the position setting of a default homing to
// `position`, run until Done.
struct Reference {
  kt::Sample before, after;
};

Reference reference_of(kt::Harness& h, double position) {
  const uint16_t n = h.post(kt::home(plc::MC_DefaultHoming, position));
  const Run run = home_until_outcome(h, n);
  REQUIRE(h.state_of(n) == CommandState::kDone);
  const int j = jump(run, 20.0);
  REQUIRE(j > 0);
  return {run.samples[static_cast<std::size_t>(j - 1)], run.samples[static_cast<std::size_t>(j)]};
}

bool bit(const kt::Sample& s, plc::StateBit b) {
  return plc::test_bit(s.state_word, b);
}

}  // namespace

TEST_CASE(
    "default homing: the sync pulse after the cam edge becomes 0; Homed; HomingBusy and "
    "AxisState Homing while it runs",
    "[homing][default]") {
  kt::Harness h(kt::homing_axis());
  REQUIRE(h.x->NcToPlc.ActPos == 0.0);
  const uint16_t n = h.post(kt::home(plc::MC_DefaultHoming, 0.0));
  const Run run = home_until_outcome(h, n);
  REQUIRE(run.done_at > 0);
  REQUIRE(h.state_of(n) == CommandState::kDone);

  // While it runs: HomingBusy, AxisState Homing, HasJob; towards the cam at 100 mm/s.
  double peak = 0.0;
  for (int i = 0; i < run.done_at; ++i) {
    const kt::Sample& s = run.samples[static_cast<std::size_t>(i)];
    INFO("cycle " << i);
    REQUIRE(bit(s, plc::kStateHomingBusy));
    REQUIRE(static_cast<AxisState>(s.axis_state) == AxisState::kHoming);
    REQUIRE(bit(s, plc::kStateHasJob));
    REQUIRE(s.cmd_no == n);
    peak = std::max(peak, s.set_velo);
  }
  CHECK(peak == Approx(100.0).margin(1e-9));

  // The reference: the raw encoder passed its pulse at 95 (the first one below the cam edge at
  // 100, going off the cam at -10 mm/s); from then on 95 raw reads 0.
  const int j = jump(run, 50.0);
  REQUIRE(j > 0);
  const kt::Sample& before = run.samples[static_cast<std::size_t>(j - 1)];
  const kt::Sample& after = run.samples[static_cast<std::size_t>(j)];
  CHECK(before.act_pos <= 95.0);          // the NC saw the pulse passed ...
  CHECK(before.act_pos > 95.0 - 0.0101);  // ... within the last cycle's 0.01 mm
  CHECK(before.set_velo == Approx(-10.0).margin(1e-9));
  CHECK(after.act_pos == Approx(before.act_pos - 95.0 - 0.01).margin(2e-4));
  CHECK(after.pos_diff == Approx(before.pos_diff).margin(1e-9));  // no following-error jump
  CHECK_FALSE(bit(before, plc::kStateHomed));
  CHECK(bit(after, plc::kStateHomed));
  // Only the one jump: before it the off-cam motion began inside the cam, after it the stop.
  CHECK(before.act_pos < 100.0);

  // Done at rest just past the reference, Standstill, Homed, no error.
  const plc::NCTOPLC_AXIS_REF& out = h.x->NcToPlc;
  CHECK(out.SetVelo == 0.0);
  CHECK(out.ActPos < 0.0);
  // The jerk-limited stop from 10 mm/s (J 50000 mm/s³: 2·sqrt(v/J) = 28 ms, 0.14 mm) plus the
  // cycle the pulse was seen in.
  CHECK(out.ActPos > -0.16);
  CHECK(out.ErrorCode == 0);
  CHECK(out.TargetPos == out.SetPos);  // the windows watch where it stopped
  CHECK(kt::bit(*h.x, plc::kStateHomed));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHomingBusy));
  CHECK(kt::axis_state(*h.x) == AxisState::kStandstill);
  h.cycles(50);
  CHECK(kt::axis_state(*h.x) == AxisState::kStandstill);
  CHECK(kt::bit(*h.x, plc::kStateInTargetPosition));
  CHECK(out.ActPos == Approx(run.samples.back().act_pos).margin(1e-9));
}

TEST_CASE("default homing with Position 40 puts 40 at the sync pulse", "[homing][default]") {
  kt::Harness h(kt::homing_axis());
  const Reference ref = reference_of(h, 40.0);
  CHECK(ref.after.act_pos == Approx(ref.before.act_pos - 95.0 + 40.0 - 0.01).margin(2e-4));
  CHECK(h.x->NcToPlc.ActPos > 40.0 - 0.16);
  CHECK(h.x->NcToPlc.ActPos < 40.0);
}

TEST_CASE("sync search in the + direction: through the cam, the pulse at 115 becomes 0",
          "[homing][default]") {
  nc::AxisConfig c = kt::homing_axis();
  c.homing_sync_search_positive = true;
  kt::Harness h(c);
  const Reference ref = reference_of(h, 0.0);
  CHECK(ref.before.act_pos >= 115.0);
  CHECK(ref.before.act_pos < 115.0 + 0.0101);
  CHECK(ref.after.act_pos == Approx(ref.before.act_pos - 115.0 + 0.01).margin(2e-4));
  CHECK(h.x->NcToPlc.ActPos > 0.0);
  CHECK(h.x->NcToPlc.ActPos < 0.16);
}

TEST_CASE("without a sync pulse the cam edge is the reference", "[homing][default]") {
  nc::AxisConfig c = kt::homing_axis();
  c.homing_sync_pulse_distance = 0.0;
  kt::Harness h(c);
  const Reference ref = reference_of(h, 0.0);
  // The cam signal fell at 100; the PLC passed it on one cycle later, so the NC set 0 where
  // the actual stood then, at most two cycles (0.02 mm) below the edge.
  CHECK(ref.before.act_pos < 100.0);
  CHECK(ref.before.act_pos > 100.0 - 0.0201);
  CHECK(ref.after.act_pos == Approx(-0.01).margin(2e-4));
  CHECK(kt::bit(*h.x, plc::kStateHomed));
}

TEST_CASE("a cam never found within the search distance is axis error 0x4F20",
          "[homing][default][errors]") {
  nc::AxisConfig c = kt::homing_axis();
  c.homing_cam_width = 0.0;  // no cam
  kt::Harness h(c);
  const uint16_t n = h.post(kt::home(plc::MC_DefaultHoming, 0.0));
  const Run run = home_until_outcome(h, n);
  REQUIRE(h.state_of(n) == CommandState::kError);
  CHECK(h.answer(n).error_code == kt::id(ErrorCode::kHomingCamNotFound));
  CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kHomingCamNotFound));
  // The search distance is 10000 mm: the error came there, at 100 mm/s.
  CHECK(run.samples.back().set_pos == Approx(10000.0).margin(0.11));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHomed));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHomingBusy));
  CHECK(kt::axis_state(*h.x) == AxisState::kErrorStop);
  // It stops on the emergency ramp and stays.
  h.cycles(200);
  CHECK(h.x->NcToPlc.SetVelo == 0.0);
  // A reset clears it; homing can start again.
  const uint16_t reset = h.post(kt::simple(plc::CommandType::kReset));
  h.cycles(1);
  CHECK(h.state_of(reset) == CommandState::kDone);
  CHECK(h.x->NcToPlc.ErrorCode == 0);
}

TEST_CASE("a cam edge never left within the search distance is axis error 0x4F22",
          "[homing][default][errors]") {
  nc::AxisConfig c = kt::homing_axis();
  c.homing_cam_width = 1000.0;  // the axis cannot leave it within 300 mm
  c.homing_search_distance = 300.0;
  c.homing_sync_search_positive = true;
  kt::Harness h(c);
  const uint16_t n = h.post(kt::home(plc::MC_DefaultHoming, 0.0));
  home_until_outcome(h, n);
  REQUIRE(h.state_of(n) == CommandState::kError);
  CHECK(h.answer(n).error_code == kt::id(ErrorCode::kHomingSyncPulseNotFound));
  CHECK(h.x->NcToPlc.ErrorCode == kt::id(ErrorCode::kHomingSyncPulseNotFound));
}

TEST_CASE("MC_Stop during homing aborts it; Homed stays as it was", "[homing][default][stop]") {
  for (bool homed_at_start : {false, true}) {
    INFO("homed at start: " << homed_at_start);
    nc::AxisConfig c = kt::homing_axis();
    c.homed_at_start = homed_at_start;
    kt::Harness h(c);
    CHECK(kt::bit(*h.x, plc::kStateHomed) == homed_at_start);
    const uint16_t n = h.post(kt::home(plc::MC_DefaultHoming, 0.0));
    for (int i = 0; i < 500; ++i)
      kt::cam_cycle(h);
    REQUIRE(h.state_of(n) == CommandState::kActive);
    CHECK_FALSE(kt::bit(*h.x, plc::kStateHomed));  // cleared when the default homing started
    const bool homed = kt::bit(*h.x, plc::kStateHomed);
    const uint16_t stop = h.post(kt::simple(plc::CommandType::kStop));
    kt::cam_cycle(h);
    CHECK(h.state_of(n) == CommandState::kAborted);
    CHECK(h.state_of(stop) == CommandState::kActive);
    CHECK_FALSE(kt::bit(*h.x, plc::kStateHomingBusy));
    CHECK(kt::axis_state(*h.x) == AxisState::kStopping);
    const int stopped = h.cycles_until([&] { return h.state_of(stop) == CommandState::kDone; });
    REQUIRE(stopped > 0);
    CHECK(h.x->NcToPlc.SetVelo == 0.0);
    CHECK(h.x->NcToPlc.SetPos < 100.0);  // stopped on its way to the cam
    CHECK(kt::bit(*h.x, plc::kStateHomed) == homed);
    CHECK(h.x->NcToPlc.ErrorCode == 0);
  }
}

TEST_CASE("losing the controller enable during homing is axis error 0x4260",
          "[homing][default][errors]") {
  kt::Harness h(kt::homing_axis());
  const uint16_t n = h.post(kt::home(plc::MC_DefaultHoming, 0.0));
  for (int i = 0; i < 300; ++i)
    kt::cam_cycle(h);
  kt::set_enables(*h.x, false);
  kt::cam_cycle(h);
  CHECK(h.state_of(n) == CommandState::kError);
  CHECK(h.answer(n).error_code == 0x4260U);
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHomingBusy));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateHomed));
}

TEST_CASE("a move during homing aborts it, and a second MC_Home replaces the first",
          "[homing][default]") {
  kt::Harness h(kt::homing_axis());
  const uint16_t first = h.post(kt::home(plc::MC_DefaultHoming, 0.0));
  for (int i = 0; i < 100; ++i)
    kt::cam_cycle(h);
  const uint16_t second = h.post(kt::home(plc::MC_DefaultHoming, 0.0));
  kt::cam_cycle(h);
  CHECK(h.state_of(first) == CommandState::kAborted);
  CHECK(h.state_of(second) == CommandState::kActive);
  const uint16_t move = h.post(kt::move_absolute(20.0, 500.0));
  kt::cam_cycle(h);
  CHECK(h.state_of(second) == CommandState::kAborted);
  CHECK(h.state_of(move) == CommandState::kActive);
  CHECK(kt::axis_state(*h.x) == AxisState::kDiscreteMotion);
  REQUIRE(h.cycles_until([&] { return h.state_of(move) == CommandState::kDone; }) > 0);
  CHECK(h.x->NcToPlc.SetPos == 20.0);
}
