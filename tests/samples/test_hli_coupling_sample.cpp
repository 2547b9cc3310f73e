// The HLI coupling sample reproduces seed 002's examples with Y2 = logical axis 8 coupled to
// axis 1 (X 0 → 900 mm, then Y2's own PTP move to 100 mm):
//   1  DIRECT               → Y2's drive 900 mm; its PTP move runs its program only;
//   2  DIRECT + self        → 900 + 100 = 1000 mm;
//   3  self + FRACT −5/9    → −5/9 · 900 + 100 = −400 mm (−500 mm before Y2's own move);
// and P-AXIS-00460's forward-mapping example: X 40, X1 50, X1 coupled 1:1 to X and to itself →
// request 50 (default), 50 (00436), 10 (00436 + 00460); after X +20: 70, 50, 10.
#include <cmath>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "../../samples/hli_coupling/hli_coupling_program.hpp"
#include "text_file.hpp"
#include "well_formed_xml.hpp"

namespace {

using hli_coupling::Example;
using hli_coupling::ExampleSample;
using hli_coupling::kExamples;
using hli_coupling::MappingSample;

using ncsdk_test::read_text;

}  // namespace

TEST_CASE("examples 1-3: Y2's drive ends at 900, 1000 and -400 mm", "[hli][sample]") {
  const double expected_after_x[] = {900.0, 900.0, -500.0};
  const double expected_end[] = {900.0, 1000.0, -400.0};
  for (std::size_t k = 0; k < 3; ++k) {
    ExampleSample sample(kExamples[k]);
    const hli_coupling::ExampleReport& r = sample.run();
    INFO(sample.summary());
    REQUIRE(r.finished);
    CHECK(r.error_id == 0);
    CHECK(r.axis_error == 0);
    CHECK(r.final_x == Approx(900.0).margin(1e-9));
    CHECK(r.y2_drive_after_x == Approx(expected_after_x[k]).margin(1e-9));
    CHECK(r.final_y2 == Approx(expected_end[k]).margin(1e-9));
    CHECK(r.y2_program_target == Approx(100.0).margin(1e-9));     // its program did move to 100
    CHECK(std::abs(r.final_y2_actual - expected_end[k]) <= 0.5);  // the lagging drive settles
    CHECK(sample.ok());
  }
}

TEST_CASE("the handshake: the NC resets semaphor_rw in the cycle it takes the list",
          "[hli][sample]") {
  const std::size_t entries[] = {1, 2, 2};
  const int32_t sources[][2] = {{1, 0}, {1, 8}, {8, 1}};
  const uint16_t modes[][2] = {
      {plc::hli::HLI_AXIS_COUPLING_DIRECT, 0},
      {plc::hli::HLI_AXIS_COUPLING_DIRECT, plc::hli::HLI_AXIS_COUPLING_DIRECT},
      {plc::hli::HLI_AXIS_COUPLING_DIRECT, plc::hli::HLI_AXIS_COUPLING_FRACT}};
  for (std::size_t k = 0; k < 3; ++k) {
    ExampleSample sample(kExamples[k]);
    const hli_coupling::ExampleReport& r = sample.run();
    INFO(sample.summary());
    CHECK(r.semaphore_cycles == 1);
    CHECK(r.active);
    CHECK(kExamples[k].entries == entries[k]);
    for (std::size_t e = 0; e < 2; ++e) {
      CHECK(r.in_force[e].ax_nr == sources[k][e]);
      CHECK(r.in_force[e].mode == modes[k][e]);
    }
    // X is a source (master), Y2 a target (slave), as slave axes publish it.
    CHECK(r.couple_state_x == 1);
    CHECK(r.couple_state_y2 == 3);
  }
}

TEST_CASE("active_rev_r is Y2's drive velocity in 1e-3 mm/s", "[hli][sample]") {
  ExampleSample sample(kExamples[2]);
  const hli_coupling::ExampleReport& r = sample.run();
  const nc::Scope& s = sample.scope();
  const auto velo = s.values(s.find("Y2", nc::Signal::kSetVelo));
  const auto rev = s.values(s.find("Y2.active_rev_r"));
  REQUIRE(velo.size() == rev.size());
  // The scope samples before the cycle, so both are the last cycle's: equal to 0.5e-3 mm/s.
  for (std::size_t i = 0; i < velo.size(); ++i) {
    CAPTURE(i);
    REQUIRE(std::abs(rev[i] - velo[i]) <= 0.5e-3 + 1e-12);
  }
  // −5/9 of X's peak (below 2000 mm/s) at most.
  CHECK(r.max_active_rev > 900000);
  CHECK(r.max_active_rev <= 5 * 2000000 / 9);
}

TEST_CASE("forward mapping: 50 / 50 / 10 after the coupling, 70 / 50 / 10 after X +20",
          "[hli][sample]") {
  MappingSample sample;
  const hli_coupling::MappingReport& r = sample.run();
  INFO(sample.summary());
  REQUIRE(r.finished);
  CHECK(r.error_id == 0);
  CHECK(r.axis_error == 0);
  CHECK(r.at_coupling[0] == Approx(50.0).margin(1e-9));
  CHECK(r.at_coupling[1] == Approx(50.0).margin(1e-9));
  CHECK(r.at_coupling[2] == Approx(10.0).margin(1e-9));
  CHECK(r.after_move[0] == Approx(70.0).margin(1e-9));
  CHECK(r.after_move[1] == Approx(50.0).margin(1e-9));
  CHECK(r.after_move[2] == Approx(10.0).margin(1e-9));
  for (double drive : r.drive_after_move)
    CHECK(drive == Approx(70.0).margin(1e-9));  // every X1's drive followed X by +20
  CHECK(sample.ok());
}

TEST_CASE("the sample writes one CSV and one well-formed SVG per example", "[hli][sample]") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsdk_test_hli_coupling";
  std::filesystem::remove_all(dir);
  for (const Example& example : kExamples) {
    ExampleSample sample(example);
    REQUIRE(sample.run().finished);
    const auto [csv, svg] = sample.write(dir);
    CHECK(csv.filename() == std::string(example.name) + ".csv");
    CHECK(read_text(csv).find("Y2.active_rev_r [mm/s]") != std::string::npos);
    const std::string plot = read_text(svg);
    CHECK(ncsdk_test::xml_problem(plot).empty());
    CHECK(plot.find(example.title) != std::string::npos);
  }
  MappingSample mapping;
  REQUIRE(mapping.run().finished);
  const auto [csv, svg] = mapping.write(dir);
  CHECK(read_text(csv).find("X1_436_460.CMDPOS [mm]") != std::string::npos);
  const std::string plot = read_text(svg);
  CHECK(ncsdk_test::xml_problem(plot).empty());
  CHECK(plot.find("id=\"panel-request\"") != std::string::npos);
  std::filesystem::remove_all(dir);
}
