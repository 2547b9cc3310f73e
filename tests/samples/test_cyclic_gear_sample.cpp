// The cyclic slave sample (samples/cyclic_gear, seed 000 §3.3) run as the program runs it: a
// master at 1000 mm/s, a slave on MC_GearInDyn (AccBound 9000 mm/s², above the stability bound
// 1.7 × 5000) whose GearRatio follows a PLC signal: 1.0, a step to 1.5 at 1 s, a sine 1.5 ± 0.2 at
// 1 Hz from 2 s to 3.75 s (its low, 1.3); then Enable falls and the slave decouples in motion, and
// both are stopped.
// - the slave's acceleration within 9000 at every coupled cycle, its position continuous (each
//   step = factor in force × the master's step, to 1e-9 mm);
// - the step reached in 0.5 / (9000 / 1000) s = 56 ms (±1 cycle), InGear then; the sine followed
//   without lag (its rate 0.2 × 2π = 1.26 /s is inside 9 /s);
// - decoupled: CoupleState 0, going on at the factor in force × 1000 mm/s; no warning, no error;
// - CSV + one well-formed SVG with both axes and the factor panel.
#include <cmath>
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "../../samples/cyclic_gear/cyclic_gear_program.hpp"
#include "text_file.hpp"
#include "well_formed_xml.hpp"

TEST_CASE("the cyclic gear sample: factor from a PLC signal within AccBound, then decoupled") {
  cyclic_gear::CyclicGearSample sample;
  const cyclic_gear::Report& r = sample.run();
  INFO(sample.summary());
  REQUIRE(r.finished);
  CHECK(r.error_id == 0);
  CHECK(r.axis_errors == 0);
  CHECK(r.warnings == 0);
  CHECK(r.coupled_cycles > 3700);  // 3.75 s from the master's start
  CHECK(r.max_slave_acc <= 9000.0);
  CHECK(r.max_slave_acc > 8999.0);  // the step uses the bound
  CHECK(r.max_jump < 1e-9);
  CHECK(r.step_cycles >= 55);
  CHECK(r.step_cycles <= 57);
  CHECK(r.step_in_gear);
  CHECK(r.max_lag < 1e-9);
  CHECK(r.couple_after_decoupling == 0U);
  // At the sine's low, 1.5 − 0.2 (to its rounding); the slave goes on at 1.3 × 1000 mm/s.
  CHECK(r.factor_at_decoupling == Approx(1.3).margin(1e-12));
  CHECK(r.velo_after_decoupling == Approx(r.factor_at_decoupling * 1000.0).margin(1e-6));
  CHECK(r.end_velo[0] == 0.0);
  CHECK(r.end_velo[1] == 0.0);
  CHECK(sample.ok());
}

TEST_CASE("the cyclic gear sample writes one CSV and one well-formed SVG") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsdk_test_cyclic_gear";
  std::filesystem::remove_all(dir);
  cyclic_gear::CyclicGearSample sample;
  REQUIRE(sample.run().finished);
  const auto [csv, svg] = sample.write(dir);
  CHECK(csv.filename() == "cyclic_gear.csv");
  const std::string text = ncsdk_test::read_text(csv);
  for (const char* column : {"Master.SetPos [mm]", "Slave.SetAcc", "Slave.GearRatio1"})
    CHECK(text.find(column) != std::string::npos);
  const std::string plot = ncsdk_test::read_text(svg);
  CHECK(ncsdk_test::xml_problem(plot).empty());
  for (const char* id : {"panel-position", "panel-acceleration", "panel-factor"})
    CHECK(plot.find(std::string("id=\"") + id + "\"") != std::string::npos);
  std::filesystem::remove_all(dir);
}
