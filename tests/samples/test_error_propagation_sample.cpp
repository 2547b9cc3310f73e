// The error propagation sample (samples/error_propagation, seed 000 §3.1, SPEC C7 DELAYED) run
// as the program runs it: Faulty (slave 1/1, drive saturated at 900 mm/s, DELAYED 0.5 s) raises
// 0x4550 while the master cruises at 1000 mm/s, showing bits 31 and 6 in the same cycle; the PLC
// decouples Healthy (slave 1/2) 0.2 s later; the group reaction reaches the master exactly 500
// NC cycles after Faulty's error, with Faulty's code, and bit 6 goes off in that cycle; Healthy
// runs on at 500 mm/s without an error until the PLC halts it; after the resets and Faulty's
// MC_GearOut everything is single and at rest. CSV + one well-formed SVG.
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "../../samples/error_propagation/error_propagation_program.hpp"
#include "text_file.hpp"
#include "well_formed_xml.hpp"

TEST_CASE("the error propagation sample: only Faulty reacts at once, with bits 31 and 6") {
  error_propagation::ErrorPropagationSample sample;
  const error_propagation::Report& r = sample.run();
  INFO(sample.summary());
  REQUIRE(r.finished);
  CHECK(r.error_id == 0);
  REQUIRE(r.faulty_error_cycle > 0);
  CHECK(r.bits_together);
  CHECK(r.faulty_code == 0x4550U);
  // The master cruised on at 1000 mm/s up to the cycle before the group reaction.
  CHECK(r.master_velo_before_group == Approx(1000.0).margin(1e-6));
}

TEST_CASE("the error propagation sample: the group reacts 0.5 s later, without Healthy") {
  error_propagation::ErrorPropagationSample sample;
  const error_propagation::Report& r = sample.run();
  INFO(sample.summary());
  REQUIRE(r.finished);
  CHECK(r.master_error_cycle - r.faulty_error_cycle == 500);  // 0.5 s / 1 ms
  CHECK(r.delayed_bit_off_cycle == r.master_error_cycle);
  CHECK(r.master_code == 0x4550U);
  // Healthy decoupled about 0.2 s after the error, before the reaction, and ran on.
  CHECK(r.healthy_decoupled_cycle - r.faulty_error_cycle >= 200);
  CHECK(r.healthy_decoupled_cycle - r.faulty_error_cycle <= 205);
  CHECK(r.healthy_velo_at_group == Approx(500.0).margin(1e-6));
  CHECK(r.healthy_errors == 0U);
  // The end: all at rest, no error, no coupling left.
  CHECK(r.healthy_end_velo == 0.0);
  CHECK(r.master_end_velo == 0.0);
  CHECK(r.end_errors == 0U);
  CHECK(r.end_couple[0] == 0U);
  CHECK(r.end_couple[1] == 0U);
  CHECK(r.end_couple[2] == 0U);
  CHECK(sample.ok());
}

TEST_CASE("the error propagation sample writes one CSV and one well-formed SVG with the bits") {
  const auto dir = std::filesystem::temp_directory_path() / "ncsdk_test_error_propagation";
  std::filesystem::remove_all(dir);
  error_propagation::ErrorPropagationSample sample;
  REQUIRE(sample.run().finished);
  const auto [csv, svg] = sample.write(dir);
  CHECK(csv.filename() == "error_propagation.csv");
  const std::string text = ncsdk_test::read_text(csv);
  for (const char* column :
       {"Master.SetVelo [mm/s]", "Faulty.ErrorPropagationDelayed", "Healthy.CoupleState"})
    CHECK(text.find(column) != std::string::npos);
  const std::string plot = ncsdk_test::read_text(svg);
  CHECK(ncsdk_test::xml_problem(plot).empty());
  for (const char* id : {"panel-velocity", "panel-error", "panel-delayed", "panel-couple-state"})
    CHECK(plot.find(std::string("id=\"") + id + "\"") != std::string::npos);
  std::filesystem::remove_all(dir);
}
