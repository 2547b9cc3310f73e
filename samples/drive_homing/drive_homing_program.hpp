// The seed's drive-controlled homing sample (seed 000 §4.2) as an ncsdk PLC program, and beside
// it the NC's own homing on a reference cam.
//
// PROGRAM DriveHoming homes Axis1 through its simulated SERCOS drive (sercos_drive.hpp): it
// reads S-0-0044 and refuses parameter scaling, writes the homing parameter S-0-0147, starts the
// procedure command S-0-0148, waits until the drive reports it executed (or failed), cancels the
// command, checks the reference flag in S-0-0403, and then tells the NC the axis is referenced
// (MC_Home with MC_ForceCalibration). nErrorCode shows the seed's special codes:
//   16#FFFFFFF  S-0-0044 asks for a scaling the program does not support (parameter scaling);
//   16#FFFFFFE  the drive aborted homing with an error;
//   16#FFFFFFD  the procedure completed but S-0-0403 shows no reference flag;
// or the drive's SERCOS error of a failed parameter access, or MC_Home's ErrorID.
// (The seed prints the first as 16#FFFFFF, one digit short of its siblings; issue 13 and this
// program use 16#FFFFFFF.)
//
// PROGRAM CamHoming homes Axis2 with the NC's sequence (MC_DefaultHoming): the PLC reads the
// simulated reference cam input (Kernel::reference_cam, cam at 100 … 110 mm) every cycle and
// passes it to MC_Home.bCalibrationCam.
//
// Header-only so that tests/samples/test_drive_homing_sample.cpp runs exactly this code.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include "fb/mc_home.hpp"
#include "fb/mc_power.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "plc_interface/axis_ref.hpp"
#include "sercos_drive.hpp"

namespace drive_homing {

inline constexpr uint32_t kErrScalingNotSupported = 0xFFFFFFF;  // 16#FFFFFFF
inline constexpr uint32_t kErrHomingAborted = 0xFFFFFFE;        // 16#FFFFFFE
inline constexpr uint32_t kErrNoReferenceFlag = 0xFFFFFFD;      // 16#FFFFFFD

// S-0-0147: positive direction, evaluate the home switch (bit 2) and the marker pulse (bit 5).
inline constexpr uint32_t kHomingParameter = (1U << 2) | (1U << 5);
inline constexpr uint32_t kParameterScalingBit = 1U << 3;  // S-0-0044 bit 3

enum class Step {
  IDLE,
  READ_SCALING,
  WRITE_PARAMETER,
  START_COMMAND,
  WAIT_COMMAND,
  CANCEL_COMMAND,
  READ_STATUS,
  CALIBRATE,
  DONE,
  FAILED,
};

inline const char* step_name(Step s) noexcept {
  switch (s) {
    case Step::IDLE:
      return "IDLE";
    case Step::READ_SCALING:
      return "READ_SCALING";
    case Step::WRITE_PARAMETER:
      return "WRITE_PARAMETER";
    case Step::START_COMMAND:
      return "START_COMMAND";
    case Step::WAIT_COMMAND:
      return "WAIT_COMMAND";
    case Step::CANCEL_COMMAND:
      return "CANCEL_COMMAND";
    case Step::READ_STATUS:
      return "READ_STATUS";
    case Step::CALIBRATE:
      return "CALIBRATE";
    case Step::DONE:
      return "DONE";
    case Step::FAILED:
      return "FAILED";
  }
  return "?";
}

// MC_Power with both feed enables, override 100 %.
inline void enable(fb::MC_Power& power, plc::AXIS_REF& axis) noexcept {
  power.Enable = true;
  power.Enable_Positive = true;
  power.Enable_Negative = true;
  power.Override = 100.0;
  power(axis);
}

// PROGRAM DriveHoming, one call per PLC cycle. A cycle function: no allocation.
struct DriveHoming {
  bool bStart = true;
  uint32_t nErrorCode = 0;
  Step step = Step::IDLE;
  fb::MC_Power Power;
  fb::MC_Home Home;
  FB_SoEAccess Access;
  bool bAborted = false;

  void operator()(plc::AXIS_REF& axis, SercosDrive& drive) noexcept {
    enable(Power, axis);
    uint32_t value = 0;
    switch (step) {
      case Step::IDLE:
        if (bStart && Power.Status) step = Step::READ_SCALING;
        break;
      case Step::READ_SCALING:
        if (access(drive, false, kIdnScalingType, 0, value)) {
          if ((value & kParameterScalingBit) != 0) {
            fail(kErrScalingNotSupported);
          } else {
            step = Step::WRITE_PARAMETER;
          }
        }
        break;
      case Step::WRITE_PARAMETER:
        if (access(drive, true, kIdnHomingParameter, kHomingParameter, value)) {
          step = Step::START_COMMAND;
        }
        break;
      case Step::START_COMMAND:
        if (access(drive, true, kIdnHomingCommand, kCommandSetAndEnable, value)) {
          step = Step::WAIT_COMMAND;
        }
        break;
      case Step::WAIT_COMMAND:
        if (access(drive, false, kIdnHomingCommand, 0, value)) {
          if (value == kCommandExecuted || value == kCommandError) {
            bAborted = value == kCommandError;
            step = Step::CANCEL_COMMAND;
          }
        }
        break;
      case Step::CANCEL_COMMAND:  // a SERCOS procedure command is cancelled after it ended
        if (access(drive, true, kIdnHomingCommand, 0, value)) {
          if (bAborted) {
            fail(kErrHomingAborted);
          } else {
            step = Step::READ_STATUS;
          }
        }
        break;
      case Step::READ_STATUS:
        if (access(drive, false, kIdnPositionStatus, 0, value)) {
          if ((value & 1U) == 0) {
            fail(kErrNoReferenceFlag);
          } else {
            step = Step::CALIBRATE;
          }
        }
        break;
      case Step::CALIBRATE:
        Home.Execute = true;
        Home.HomingMode = fb::MC_ForceCalibration;
        Home(axis);
        if (Home.Done) step = Step::DONE;
        if (Home.Error) fail(Home.ErrorID);
        break;
      case Step::DONE:
      case Step::FAILED:
        Home.Execute = false;
        Home(axis);
        break;
    }
  }

 private:
  void fail(uint32_t code) noexcept {
    nErrorCode = code;
    step = Step::FAILED;
  }

  // One parameter access over several cycles: true once it has ended; a failed access ends the
  // program with the drive's error.
  bool access(SercosDrive& drive, bool write, uint16_t idn, uint32_t value,
              uint32_t& out) noexcept {
    Access.Execute = true;
    Access.Write = write;
    Access.Idn = idn;
    if (write) Access.Value = value;
    Access(drive);
    if (Access.Busy) return false;
    const bool error = Access.Error;
    const uint32_t error_id = Access.ErrorID;
    out = Access.Value;
    Access.Execute = false;  // ready for the next access
    Access(drive);
    if (error) {
      fail(error_id);
      return false;
    }
    return true;
  }
};

// PROGRAM CamHoming, one call per PLC cycle: the NC homes Axis2 on its reference cam.
struct CamHoming {
  bool bCamInput = false;  // the digital input of the reference cam (I/O mapping)
  bool bDone = false;
  uint32_t nErrorCode = 0;
  fb::MC_Power Power;
  fb::MC_Home Home;

  void operator()(plc::AXIS_REF& axis) noexcept {
    enable(Power, axis);
    Home.Execute = Power.Status && !bDone && nErrorCode == 0;
    Home.HomingMode = fb::MC_DefaultHoming;
    Home.Position = 0.0;
    Home.bCalibrationCam = bCamInput;
    Home(axis);
    if (Home.Done) bDone = true;
    if (Home.Error) nErrorCode = Home.ErrorID;
  }
};

struct Report {
  bool finished = false;  // both programs ended (DONE / FAILED, and CamHoming done or failed)
  Step step = Step::IDLE;
  uint32_t error_code = 0;   // DriveHoming.nErrorCode
  bool axis1_homed = false;  // Axis1's StateDWord bit 1 at the end
  bool drive_referenced = false;
  uint32_t homing_parameter = 0;  // S-0-0147 as the drive holds it at the end
  bool axis2_homed = false;
  uint32_t axis2_error = 0;     // CamHoming.nErrorCode
  double axis2_position = 0.0;  // Axis2's ActPos at the end (just past 0)
  double end_time = 0.0;

  bool ok() const noexcept {
    return finished && step == Step::DONE && error_code == 0 && axis1_homed && axis2_homed &&
           axis2_error == 0;
  }
};

class DriveHomingSample {
 public:
  explicit DriveHomingSample(SercosDrive::Fault fault = SercosDrive::Fault::kNone)
      : kernel_(nc::KernelConfig{0.001}),
        axis1_(kernel_.add_axis(axis_config("Axis1"))),
        axis2_(kernel_.add_axis(axis_config("Axis2"))),
        drive_(fault),
        driver_(kernel_) {
    driver_.add_task("PlcTask", 0.010, [this] {
      cam_.bCamInput = kernel_.reference_cam("Axis2");  // I/O: read the digital input
      drive_.cycle();
      main_(axis1_, drive_);
      cam_(axis2_);
    });
  }

  DriveHomingSample(const DriveHomingSample&) = delete;
  DriveHomingSample& operator=(const DriveHomingSample&) = delete;

  const Report& run(double timeout = 30.0) {
    report_.finished = driver_.run_until(
        [this] {
          const bool drive_end = main_.step == Step::DONE || main_.step == Step::FAILED;
          return drive_end && (cam_.bDone || cam_.nErrorCode != 0);
        },
        timeout);
    report_.step = main_.step;
    report_.error_code = main_.nErrorCode;
    report_.axis1_homed = plc::test_bit(axis1_.NcToPlc.StateDWord, plc::kStateHomed);
    report_.drive_referenced = drive_.referenced();
    report_.homing_parameter = drive_.homing_parameter();
    report_.axis2_homed = plc::test_bit(axis2_.NcToPlc.StateDWord, plc::kStateHomed);
    report_.axis2_error = cam_.nErrorCode;
    report_.axis2_position = axis2_.NcToPlc.ActPos;
    report_.end_time = kernel_.time();
    return report_;
  }

  std::string summary() const {
    char text[512];
    std::snprintf(text, sizeof text,
                  "drive_homing: %s after %.3f s\n"
                  "  Axis1 (drive-controlled): step %s, nErrorCode 16#%X, Homed %d\n"
                  "  Axis2 (NC, reference cam): Homed %d, ActPos %.4f mm, error 16#%X\n",
                  report_.ok() ? "ok" : "FAILED", report_.end_time, step_name(report_.step),
                  report_.error_code, report_.axis1_homed ? 1 : 0, report_.axis2_homed ? 1 : 0,
                  report_.axis2_position, report_.axis2_error);
    return text;
  }

 private:
  static nc::AxisConfig axis_config(const char* name) {
    nc::AxisConfig config;
    config.name = name;
    config.homed_at_start = false;  // incremental encoders: both axes must home
    return config;
  }

  nc::Kernel kernel_;
  plc::AXIS_REF& axis1_;
  plc::AXIS_REF& axis2_;
  SercosDrive drive_;
  nc::CycleDriver driver_;
  DriveHoming main_;
  CamHoming cam_;
  Report report_;
};

}  // namespace drive_homing
