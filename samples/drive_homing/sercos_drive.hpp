// A simulated SERCOS drive that homes itself (seed 000 §4.2), and the PLC's two parameter
// blocks that reach it, shaped like the vendor's drive-parameter blocks: Execute starts one
// read or write of a parameter (IDN), Busy while the drive handles it (a few PLC cycles), then
// Done, or Error with ErrorID (the drive's SERCOS error); the result stays while Execute stays
// high, as Tc2_MC2's rules say for Execute-type blocks.
//
// The drive's parameters (IEC 61491 / SERCOS numbering) that the seed's sample uses:
//  - S-0-0044 velocity data scaling type: bit 3 = 1 asks for parameter scaling;
//  - S-0-0147 homing parameter: bit 0 homing direction (0 positive), bit 2 evaluate the home
//    switch, bit 5 evaluate the encoder's marker pulse;
//  - S-0-0148 drive-controlled homing procedure command: write 3 (set and enable) to start it,
//    0 to cancel; read: 0 not set, 3 running, 7 executed, 15 executed with an error;
//  - S-0-0403 position feedback value status: bit 0 = the position feedback is referenced.
// The procedure takes `homing_cycles` drive cycles. What can go wrong is chosen with
// SercosDrive::Fault, so a test can provoke each of the seed's special error codes.
// Plain data and cycle functions: no allocation.
#pragma once

#include <cstdint>

namespace drive_homing {

inline constexpr uint16_t kIdnScalingType = 44;       // S-0-0044
inline constexpr uint16_t kIdnHomingParameter = 147;  // S-0-0147
inline constexpr uint16_t kIdnHomingCommand = 148;    // S-0-0148
inline constexpr uint16_t kIdnPositionStatus = 403;   // S-0-0403

inline constexpr uint32_t kCommandSetAndEnable = 3;
inline constexpr uint32_t kCommandExecuted = 7;
inline constexpr uint32_t kCommandError = 15;

inline constexpr uint32_t kSercosErrorIdnUnknown = 0x1001;  // "IDN not present"
inline constexpr uint32_t kSercosErrorReadOnly = 0x7004;    // "data cannot be changed"
inline constexpr uint32_t kSercosErrorHoming = 0xC14A;      // homing aborted (drive diagnosis)

class SercosDrive {
 public:
  enum class Fault : uint8_t {
    kNone,
    kParameterScaling,  // S-0-0044 asks for parameter scaling (bit 3)
    kHomingAborted,     // the procedure ends with an error
    kNoReferenceFlag,   // the procedure ends, but S-0-0403 bit 0 stays clear
  };

  explicit SercosDrive(Fault fault = Fault::kNone, int homing_cycles = 200) noexcept
      : fault_(fault), homing_cycles_(homing_cycles) {
    scaling_type_ = fault == Fault::kParameterScaling ? 0x000A : 0x0002;  // rotational
  }

  // The parameter channel (one access at a time): false when one is still being handled.
  bool request(bool write, uint16_t idn, uint32_t value) noexcept {
    if (busy_) return false;
    busy_ = true;
    write_ = write;
    idn_ = idn;
    value_ = value;
    countdown_ = kAccessCycles;
    return true;
  }
  bool busy() const noexcept { return busy_; }
  // The last finished access: its SERCOS error (0 = none) and, for a read, the value.
  uint32_t error() const noexcept { return error_; }
  uint32_t value() const noexcept { return value_; }

  // One drive cycle (one PLC cycle here): the access in hand, and the homing procedure.
  void cycle() noexcept {
    if (procedure_ == kCommandSetAndEnable && --homing_left_ <= 0) {
      procedure_ = fault_ == Fault::kHomingAborted ? kCommandError : kCommandExecuted;
      referenced_ = procedure_ == kCommandExecuted && fault_ != Fault::kNoReferenceFlag;
    }
    if (busy_ && --countdown_ <= 0) {
      error_ = write_ ? write(idn_, value_) : read(idn_, value_);
      busy_ = false;
    }
  }

  bool referenced() const noexcept { return referenced_; }
  uint32_t homing_parameter() const noexcept { return homing_parameter_; }

 private:
  static constexpr int kAccessCycles = 3;

  uint32_t read(uint16_t idn, uint32_t& out) const noexcept {
    switch (idn) {
      case kIdnScalingType:
        out = scaling_type_;
        return 0;
      case kIdnHomingParameter:
        out = homing_parameter_;
        return 0;
      case kIdnHomingCommand:
        out = procedure_;
        return 0;
      case kIdnPositionStatus:
        out = referenced_ ? 1U : 0U;
        return 0;
      default:
        return kSercosErrorIdnUnknown;
    }
  }

  uint32_t write(uint16_t idn, uint32_t value) noexcept {
    switch (idn) {
      case kIdnHomingParameter:
        homing_parameter_ = value;
        return 0;
      case kIdnHomingCommand:
        if (value == kCommandSetAndEnable && procedure_ != kCommandSetAndEnable) {
          procedure_ = kCommandSetAndEnable;
          homing_left_ = homing_cycles_;
          referenced_ = false;  // the drive references anew
        } else if (value == 0) {
          procedure_ = 0;  // the command is cancelled (after it has been executed or failed)
        }
        return 0;
      case kIdnScalingType:
      case kIdnPositionStatus:
        return kSercosErrorReadOnly;
      default:
        return kSercosErrorIdnUnknown;
    }
  }

  Fault fault_;
  int homing_cycles_;
  uint32_t scaling_type_ = 0x0002;
  uint32_t homing_parameter_ = 0;
  uint32_t procedure_ = 0;
  int homing_left_ = 0;
  bool referenced_ = false;

  bool busy_ = false;
  bool write_ = false;
  uint16_t idn_ = 0;
  uint32_t value_ = 0;
  int countdown_ = 0;
  uint32_t error_ = 0;
};

// The PLC's parameter block: read (Write false) or write one IDN of the drive.
class FB_SoEAccess {
 public:
  bool Execute = false;
  bool Write = false;
  uint16_t Idn = 0;
  uint32_t Value = 0;  // in for a write, out after a read

  bool Busy = false;
  bool Done = false;
  bool Error = false;
  uint32_t ErrorID = 0;

  void operator()(SercosDrive& drive) noexcept {
    const bool rising = Execute && !previous_;
    previous_ = Execute;
    if (!Execute && !Busy) {  // the result was shown; the outputs reset
      Done = false;
      Error = false;
      ErrorID = 0;
    }
    if (rising && !Busy) {
      Done = false;
      Error = false;
      ErrorID = 0;
      Busy = drive.request(Write, Idn, Value);
      if (!Busy) {
        Error = true;  // the channel is taken by another access
        ErrorID = kSercosErrorBusy;
      }
      return;
    }
    if (Busy && !drive.busy()) {
      Busy = false;
      ErrorID = drive.error();
      Error = ErrorID != 0;
      Done = !Error;
      if (Done && !Write) Value = drive.value();
    }
  }

  static constexpr uint32_t kSercosErrorBusy = 0x0001;

 private:
  bool previous_ = false;  // Execute at the last call
};

}  // namespace drive_homing
