// The drive-controlled homing sample (seed 000 §4.2, issue 13): the good case homes both axes,
// and each of the seed's three special error codes is provoked through the simulated drive.
#include <catch2/catch.hpp>

#include "../../samples/drive_homing/drive_homing_program.hpp"

using drive_homing::DriveHomingSample;
using drive_homing::Step;
using Fault = drive_homing::SercosDrive::Fault;

TEST_CASE("good case: the drive references Axis1, the NC homes Axis2 on the cam",
          "[samples][drive_homing]") {
  DriveHomingSample sample(Fault::kNone);
  const drive_homing::Report& r = sample.run();
  CHECK(r.ok());
  CHECK(r.step == Step::DONE);
  CHECK(r.error_code == 0);
  CHECK(r.drive_referenced);
  CHECK(r.homing_parameter == drive_homing::kHomingParameter);
  CHECK(r.axis1_homed);
  CHECK(r.axis2_homed);
  CHECK(r.axis2_error == 0);
  // The NC's sequence put 0 at the sync pulse below the cam: the axis stopped just past it.
  CHECK(r.axis2_position < 0.0);
  CHECK(r.axis2_position > -0.2);
}

TEST_CASE("S-0-0044 with parameter scaling: 16#FFFFFFF, nothing started",
          "[samples][drive_homing]") {
  DriveHomingSample sample(Fault::kParameterScaling);
  const drive_homing::Report& r = sample.run();
  CHECK_FALSE(r.ok());
  CHECK(r.step == Step::FAILED);
  CHECK(r.error_code == 0xFFFFFFFU);
  CHECK(r.homing_parameter == 0U);  // S-0-0147 was never written
  CHECK_FALSE(r.drive_referenced);
  CHECK_FALSE(r.axis1_homed);
}

TEST_CASE("the drive aborts homing with an error: 16#FFFFFFE", "[samples][drive_homing]") {
  DriveHomingSample sample(Fault::kHomingAborted);
  const drive_homing::Report& r = sample.run();
  CHECK(r.step == Step::FAILED);
  CHECK(r.error_code == 0xFFFFFFEU);
  CHECK_FALSE(r.drive_referenced);
  CHECK_FALSE(r.axis1_homed);
  CHECK(r.axis2_homed);  // the other axis is not concerned
}

TEST_CASE("procedure completed without the reference flag in S-0-0403: 16#FFFFFFD",
          "[samples][drive_homing]") {
  DriveHomingSample sample(Fault::kNoReferenceFlag);
  const drive_homing::Report& r = sample.run();
  CHECK(r.step == Step::FAILED);
  CHECK(r.error_code == 0xFFFFFFDU);
  CHECK_FALSE(r.drive_referenced);
  CHECK_FALSE(r.axis1_homed);
}
