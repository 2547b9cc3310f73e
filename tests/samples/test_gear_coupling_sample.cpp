// The gear coupling sample (samples/gear_coupling, seed 000 §3.2) run as the program runs it, a
// master and two slaves first as a star, then as a cascade:
// - star (Slave1 3/4, Slave2 −1/2 of the master, coupled at rest at 0): master 0 → 10000 mm at
//   V 2000 mm/s; 600 / 450 / −300 mm/s at override 30 %, 2000 / 1500 / −1000 at 100 %; at rest at
//   10000 / 7500 / −5000 mm; CoupleState 1 / 3 / 3;
// - Slave2 decoupled at rest (1 / 3 / 0) and coupled to Slave1 with −1/2 (offset −1250 mm):
//   cascade, CoupleState 1 / 2 / 3; master on to 20000 at 100 %: 2000 / 1500 / −750 mm/s;
//   factor change to 4/5 by the same MC_GearIn instance: 1600 / −800; online decoupling of
//   Slave1 (0 / 1 / 3) at 1600 mm/s while the master runs at 2000; both slaves at rest after
//   Slave1's MC_Stop while the master still runs;
// - every coupled cycle of each slave bit for bit on factor × master set position + offset, no
//   error; CSV + one well-formed SVG with all axes.
#include <cstdint>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "../../samples/gear_coupling/gear_coupling_program.hpp"
#include "text_file.hpp"
#include "well_formed_xml.hpp"

namespace {

void check_velocities(const gear_coupling::Snapshot& s, double master, double slave1,
                      double slave2) {
  CHECK(s.velo[0] == Approx(master).margin(1e-6));
  CHECK(s.velo[1] == Approx(slave1).margin(1e-6));
  CHECK(s.velo[2] == Approx(slave2).margin(1e-6));
}

void check_couple_states(const gear_coupling::Snapshot& s, uint32_t master, uint32_t slave1,
                         uint32_t slave2) {
  CHECK(s.couple[0] == master);
  CHECK(s.couple[1] == slave1);
  CHECK(s.couple[2] == slave2);
}

// InGear of MC_GearIn master → Slave1, master → Slave2, Slave1 → Slave2.
void check_in_gear(const gear_coupling::Snapshot& s, bool gear1, bool star2, bool cascade2) {
  CHECK(s.in_gear[0] == gear1);
  CHECK(s.in_gear[1] == star2);
  CHECK(s.in_gear[2] == cascade2);
}

}  // namespace

TEST_CASE("the gear coupling sample's star: both slaves follow the master at 30 % and 100 %") {
  gear_coupling::GearCouplingSample sample;
  const gear_coupling::Report& r = sample.run();
  INFO(sample.summary());
  REQUIRE(r.finished);
  CHECK(r.error_id == 0);
  CHECK(r.axis_errors == 0);
  check_couple_states(r.star_coupled, 1, 3, 3);
  check_in_gear(r.star_coupled, true, true, false);
  CHECK(r.star_offsets[0] == 0.0);
  CHECK(r.star_offsets[1] == 0.0);
  check_velocities(r.at_override_30, 600.0, 450.0, -300.0);      // 0.3 × 2000, × 3/4, × −1/2
  check_velocities(r.at_override_100, 2000.0, 1500.0, -1000.0);  // 2000, × 3/4, × −1/2
  check_couple_states(r.at_override_100, 1, 3, 3);
  // At rest at the master's end position: 10000, 0.75 × 10000, −0.5 × 10000.
  CHECK(r.star_arrived.pos[0] == 10000.0);
  CHECK(r.star_arrived.pos[1] == 7500.0);
  CHECK(r.star_arrived.pos[2] == -5000.0);
  check_velocities(r.star_arrived, 0.0, 0.0, 0.0);
  check_in_gear(r.star_arrived, true, true, false);
  // MC_GearOut at rest: Slave2 a single axis holding −5000 mm, the master still Slave1's.
  check_couple_states(r.slave2_decoupled, 1, 3, 0);
  CHECK(r.slave2_decoupled.pos[2] == -5000.0);
  CHECK_FALSE(r.slave2_decoupled.in_gear[1]);
}

TEST_CASE("the gear coupling sample's cascade: factors multiply, factor change, decoupling") {
  gear_coupling::GearCouplingSample sample;
  const gear_coupling::Report& r = sample.run();
  INFO(sample.summary());
  REQUIRE(r.finished);
  // Slave2 on Slave1 with −1/2 at 7500 / −5000 mm: offset −5000 − (−0.5 × 7500) = −1250.
  check_couple_states(r.cascade_coupled, 1, 2, 3);
  check_in_gear(r.cascade_coupled, true, false, true);
  CHECK(r.cascade_offset == -1250.0);
  check_velocities(r.cascade_running, 2000.0, 1500.0, -750.0);      // Slave2: 3/4 × −1/2 × 2000
  check_velocities(r.after_factor_change, 2000.0, 1600.0, -800.0);  // 4/5
  check_couple_states(r.after_factor_change, 1, 2, 3);
  CHECK(r.after_factor_change.in_gear[0]);
  // Online decoupling: Slave1 goes on at 1600 mm/s as a master (of Slave2), the master single.
  check_couple_states(r.after_decoupling, 0, 1, 3);
  check_velocities(r.after_decoupling, 2000.0, 1600.0, -800.0);
  CHECK_FALSE(r.after_decoupling.in_gear[0]);
  CHECK(r.after_decoupling.in_gear[2]);
  // Slave1's MC_Stop stops Slave2 with it; the master runs on.
  CHECK(r.after_slave_stop.velo[0] == Approx(2000.0).margin(1e-6));
  CHECK(r.after_slave_stop.velo[1] == 0.0);
  CHECK(r.after_slave_stop.velo[2] == 0.0);
  // Everything at rest at the end, Slave2 still on Slave1's formula, the master short of 20000.
  check_velocities(r.end, 0.0, 0.0, 0.0);
  CHECK(r.end.pos[2] == -0.5 * r.end.pos[1] - 1250.0);
  CHECK(r.end.pos[0] > 10000.0);
  CHECK(r.end.pos[0] < gear_coupling::kTarget);
  check_couple_states(r.end, 0, 1, 3);
}

TEST_CASE("the gear coupling sample's slaves are on factor × master + offset at every cycle") {
  gear_coupling::GearCouplingSample sample;
  const gear_coupling::Report& r = sample.run();
  INFO(sample.summary());
  REQUIRE(r.finished);
  // Slave1 coupled from the star's start to its online decoupling (about 7.5 s), Slave2 in both
  // topologies until the end (about 11.7 s) except the cycles between its MC_GearOut and the
  // cascade's MC_GearIn; 1 ms cycles.
  CHECK(r.follow[0].checked > 7000);
  CHECK(r.follow[1].checked > 11000);
  CHECK(r.follow[0].mismatches == 0);
  CHECK(r.follow[1].mismatches == 0);
  CHECK(sample.ok());
}

TEST_CASE("the gear coupling sample writes one CSV and one well-formed SVG with all axes") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsdk_test_gear_coupling";
  std::filesystem::remove_all(dir);
  gear_coupling::GearCouplingSample sample;
  REQUIRE(sample.run().finished);
  const auto [csv, svg] = sample.write(dir);
  CHECK(csv.filename() == "gear_coupling.csv");
  const std::string text = ncsdk_test::read_text(csv);
  for (const char* column : {"Master.SetPos [mm]", "Slave1.SetVelo [mm/s]", "Slave2.CoupleState"})
    CHECK(text.find(column) != std::string::npos);
  const std::string plot = ncsdk_test::read_text(svg);
  CHECK(ncsdk_test::xml_problem(plot).empty());
  for (const char* id : {"panel-position", "panel-velocity", "panel-couple-state"})
    CHECK(plot.find(std::string("id=\"") + id + "\"") != std::string::npos);
  CHECK(plot.find("Slave2") != std::string::npos);
  std::filesystem::remove_all(dir);
}
