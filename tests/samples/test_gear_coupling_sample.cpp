// The gear coupling sample (samples/gear_coupling, seed 000 §3.2) run as the program runs it: a
// master 0 → 20000 mm at V 2000 mm/s with Slave1 (3/4) and Slave2 (−1/2 of Slave1): 450 / −225
// mm/s at override 30 %, 1500 / −750 at 100 %, 1600 / −800 after the factor change to 4/5 by the
// same MC_GearIn instance, Slave1 at 1600 mm/s after online decoupling while the master runs at
// 2000, both slaves at rest after Slave1's MC_Stop while the master still runs, the cascade exact
// at every cycle, everything at rest at the end with no error; CSV + one well-formed SVG.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <catch2/catch.hpp>

#include "../../samples/gear_coupling/gear_coupling_program.hpp"
#include "well_formed_xml.hpp"

namespace {

std::string contents(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_CASE("the gear coupling sample shows the seed's velocities in every phase") {
  gear_coupling::GearCouplingSample sample;
  const gear_coupling::Report& r = sample.run();
  INFO(sample.summary());
  REQUIRE(r.finished);
  CHECK(r.error_id == 0);
  CHECK(r.axis_errors == 0);
  CHECK(r.at_override_30.master == Approx(600.0).margin(1e-6));
  CHECK(r.at_override_30.slave1 == Approx(450.0).margin(1e-6));
  CHECK(r.at_override_30.slave2 == Approx(-225.0).margin(1e-6));
  CHECK(r.at_override_100.slave1 == Approx(1500.0).margin(1e-6));
  CHECK(r.at_override_100.slave2 == Approx(-750.0).margin(1e-6));
  CHECK(r.after_factor_change.slave1 == Approx(1600.0).margin(1e-6));
  CHECK(r.after_factor_change.slave2 == Approx(-800.0).margin(1e-6));
  CHECK(r.slave1_couple_state_after_decoupling == 1U);  // no longer a slave; Slave2's master
  CHECK(r.after_decoupling.slave1 == Approx(1600.0).margin(1e-6));
  CHECK(r.after_decoupling.slave2 == Approx(-800.0).margin(1e-6));
  CHECK(r.after_slave_stop.slave1 == 0.0);
  CHECK(r.after_slave_stop.slave2 == 0.0);
  CHECK(r.after_slave_stop.master == Approx(2000.0).margin(1e-6));
  CHECK(r.cascade_mismatches == 0);
  CHECK(r.following_mismatches == 0);
  // Slave2 stays coupled to Slave1 throughout: −0.5 × its end position.
  CHECK(r.final_pos[2] == -0.5 * r.final_pos[1]);
  CHECK(r.final_pos[0] < gear_coupling::kTarget);  // stopped on the way
  CHECK(sample.ok());
}

TEST_CASE("the gear coupling sample writes one CSV and one well-formed SVG with all axes") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsdk_test_gear_coupling";
  std::filesystem::remove_all(dir);
  gear_coupling::GearCouplingSample sample;
  REQUIRE(sample.run().finished);
  const auto [csv, svg] = sample.write(dir);
  CHECK(csv.filename() == "gear_coupling.csv");
  const std::string text = contents(csv);
  for (const char* column : {"Master.SetPos [mm]", "Slave1.SetVelo [mm/s]", "Slave2.CoupleState"})
    CHECK(text.find(column) != std::string::npos);
  const std::string plot = contents(svg);
  CHECK(ncsdk_test::xml_problem(plot).empty());
  for (const char* id : {"panel-position", "panel-velocity", "panel-couple-state"})
    CHECK(plot.find(std::string("id=\"") + id + "\"") != std::string::npos);
  CHECK(plot.find("Slave2") != std::string::npos);
  std::filesystem::remove_all(dir);
}
