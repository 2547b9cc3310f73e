// The external setpoint generator sample (seed 000 §4.1): the PLC's 3-phase generator with a
// rectangular acceleration feeds the axis through the external interface; the axis takes every
// packet exactly (absolute start type: set values = fed values), holds the last position once
// the direction is 0, and ends in the target window of the last leg with generation disabled.
//
// Expected numbers: leg 1, 0 → 1500 mm at V 1000 mm/s, A 2500 mm/s²: ramps of V/A = 0.4 s
// covering 200 mm each, 1100 mm of cruise = 1.1 s, 1.9 s in all. Leg 2, 1500 → 1200 mm: 300 mm
// is less than V²/A = 400 mm, so a triangle peaking at sqrt(300 · 2500) = 866.03 mm/s after
// 0.3464 s, 0.6928 s in all.
#include <cmath>
#include <filesystem>
#include <span>
#include <string>

#include <catch2/catch.hpp>

#include "../../samples/ext_setpoint_generator/ext_setpoint_generator_program.hpp"
#include "text_file.hpp"
#include "well_formed_xml.hpp"

namespace {

using ncsdk_test::read_text;

using ext_setpoint_generator::ExtSetpointGeneratorSample;
using ext_setpoint_generator::kLegs;

struct Trace {
  std::span<const double> t, set_pos, set_velo, set_acc, fed_pos, fed_velo, fed_acc, direction,
      state_word;
};

Trace trace_of(const nc::Scope& s) {
  const auto v = [&s](const char* name) { return s.values(s.find(name)); };
  return {s.time(),          v("Axis1.SetPos"),      v("Axis1.SetVelo"),
          v("Axis1.SetAcc"), v("MAIN.FedPos"),       v("MAIN.FedVelo"),
          v("MAIN.FedAcc"),  v("MAIN.FedDirection"), v("Axis1.StateDWord")};
}

}  // namespace

TEST_CASE("the 3-phase generator: rectangular acceleration, peak V or the triangle's peak") {
  ext_setpoint_generator::ThreePhaseGenerator g;
  g.start(0.0, 1500.0, 1000.0, 2500.0);
  CHECK(g.direction() == 1);
  CHECK(g.peak_velocity() == 1000.0);
  CHECK(g.ramp_time() == Approx(0.4).margin(1e-12));
  CHECK(g.cruise_time() == Approx(1.1).margin(1e-12));
  CHECK(g.duration() == Approx(1.9).margin(1e-12));
  CHECK(g.at(0.2).a == 2500.0);
  CHECK(g.at(0.2).p == Approx(50.0).margin(1e-9));  // A t² / 2
  CHECK(g.at(1.0).a == 0.0);
  CHECK(g.at(1.0).v == 1000.0);
  CHECK(g.at(1.0).p == Approx(800.0).margin(1e-9));  // 200 mm ramp + 600 mm cruise
  CHECK(g.at(1.8).a == -2500.0);
  CHECK(g.at(1.8).p == Approx(1500.0 - 12.5).margin(1e-9));
  CHECK(g.at(1.9).p == 1500.0);
  CHECK(g.at(5.0).v == 0.0);

  g.start(1500.0, 1200.0, 1000.0, 2500.0);
  CHECK(g.direction() == -1);
  CHECK(g.peak_velocity() == Approx(std::sqrt(300.0 * 2500.0)).margin(1e-9));
  CHECK(g.cruise_time() == Approx(0.0).margin(1e-12));
  CHECK(g.duration() == Approx(2.0 * std::sqrt(300.0 / 2500.0)).margin(1e-12));
  CHECK(g.at(g.ramp_time()).p == Approx(1350.0).margin(1e-9));  // half-way at the peak
  CHECK(g.at(g.duration()).p == 1200.0);
}

TEST_CASE("the sample ends at the last leg's target, InTargetPosition, generation disabled") {
  ExtSetpointGeneratorSample sample;
  const auto& report = sample.run();
  INFO(sample.summary());
  REQUIRE(report.finished);
  CHECK(report.error_id == 0);
  CHECK(report.axis_error == 0);
  CHECK(report.final_set_pos == 1200.0);
  CHECK(std::fabs(report.final_act_pos - 1200.0) <= sample.kernel().config("Axis1").target_window);
  CHECK(report.final_in_target);
  CHECK_FALSE(report.final_enabled);
  for (std::size_t i = 0; i < ext_setpoint_generator::kLegCount; ++i) {
    CAPTURE(i);
    CHECK(report.legs[i].set_pos == kLegs[i].target);  // when InTargetPosition was seen
    CHECK(report.legs[i].in_target_time > report.legs[i].end_time);
  }
  CHECK(report.legs[0].peak_velocity == 1000.0);
  CHECK(report.legs[1].peak_velocity == Approx(866.0254).margin(1e-4));
  CHECK(report.ok());
}

TEST_CASE("every packet with direction ±1 is taken exactly: set values = fed values") {
  ExtSetpointGeneratorSample sample;
  REQUIRE(sample.run().ok());
  const Trace tr = trace_of(sample.scope());
  // Each scope row holds the packet fed in a PLC cycle and what the NC published at the end of
  // the NC cycle that read it.
  std::size_t taken = 0;
  double max_velocity = 0.0;
  for (std::size_t i = 0; i < tr.t.size(); ++i) {
    if (tr.direction[i] == 0.0) continue;
    CAPTURE(tr.t[i]);
    REQUIRE(tr.set_pos[i] == tr.fed_pos[i]);
    REQUIRE(tr.set_velo[i] == tr.fed_velo[i]);
    REQUIRE(tr.set_acc[i] == tr.fed_acc[i]);
    // Rectangular acceleration: +A, 0 or -A only.
    REQUIRE((tr.fed_acc[i] == 0.0 || std::fabs(tr.fed_acc[i]) == 2500.0));
    max_velocity = std::max(max_velocity, std::fabs(tr.set_velo[i]));
    ++taken;
  }
  // Leg 1: 1.9 s = 1900 cycles of motion, leg 2: 0.6928 s = 693 (the first cycle at or past
  // the end feeds the target); plus one packet before and one after each leg (±1 for rounding
  // of 1.9 / 0.001).
  CHECK(taken >= 1900 + 693 + 2 * 2);
  CHECK(taken <= 1901 + 693 + 2 * 2);
  CHECK(max_velocity == 1000.0);
}

TEST_CASE("once the direction is 0 again, the set position holds the target") {
  ExtSetpointGeneratorSample sample;
  REQUIRE(sample.run().ok());
  const Trace tr = trace_of(sample.scope());
  std::size_t last_packet = 0;
  for (std::size_t i = 0; i < tr.t.size(); ++i) {
    if (tr.direction[i] != 0.0) last_packet = i;
  }
  REQUIRE(last_packet > 0);
  for (std::size_t i = last_packet; i < tr.t.size(); ++i) {
    CAPTURE(tr.t[i]);
    REQUIRE(tr.set_pos[i] == 1200.0);
    REQUIRE(tr.set_velo[i] == 0.0);
    REQUIRE(tr.set_acc[i] == 0.0);
  }
  // The generation was enabled (bit 14) while the packets came, and is off at the end.
  const auto bit14 = [&tr](std::size_t i) {
    return plc::test_bit(static_cast<uint32_t>(tr.state_word[i]), plc::kStateExtSetPointGenEnabled);
  };
  CHECK(bit14(last_packet));
  CHECK_FALSE(bit14(tr.t.size() - 1));
}

TEST_CASE("the sample writes a CSV trace and a well-formed SVG plot with the fed values") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsdk_test_ext_setpoint_generator";
  std::filesystem::remove_all(dir);
  ExtSetpointGeneratorSample sample;
  REQUIRE(sample.run().ok());
  const auto [csv, svg] = sample.write(dir);
  const std::string text = read_text(csv);
  CHECK(text.rfind("time [s],Axis1.SetPos [mm]", 0) == 0);
  CHECK(text.find("MAIN.FedPos [mm]") != std::string::npos);
  CHECK(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) ==
        sample.scope().size() + 1);
  const std::string plot = read_text(svg);
  CHECK(ncsdk_test::xml_problem(plot).empty());
  CHECK(plot.find("FedPos") != std::string::npos);
  CHECK(plot.find("id=\"panel-direction\"") != std::string::npos);
  std::filesystem::remove_all(dir);
}
