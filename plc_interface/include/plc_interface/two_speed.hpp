// The NC → I/O drive image of a two-speed (rapid/creep) axis and its movement state (SPEC E4, E5,
// seed 004 "I/O configuration: Drive interface for rapid/creep axes NC → I/O (12 bytes)").
//
// NCTOIO_DRIVE_TWO_SPEED mirrors the vendor's 12-byte image, byte for byte. Its two control bytes
// are two equal ways of driving the same contactors: nControlByte has one bit per direction and
// speed, nExtControlByte has a direction bit and a speed bit. write_control_bytes() writes both
// from one logical command (direction, speed, brake), so they can never disagree: a travel bit is
// set only when both a direction and a speed are commanded, bBreakInv is always !bBreak, the
// reserved bits are always 0. The NC writes both bytes every cycle; a drive may read either.
//
// nAxisState (published in NcToPlc.AxisState for a two-speed axis) is TwoSpeedAxisState.
// Plain data and constexpr functions only: no allocation, usable in the cycle path.
#pragma once

#include <cstddef>
#include <cstdint>

namespace plc {

struct NCTOIO_DRIVE_TWO_SPEED {
  uint32_t nOutData1 = 0;       // drive output data 1 (unused by the two-speed sequence: 0)
  uint32_t nOutData2 = 0;       // drive output data 2 (unused: 0)
  uint8_t nControlByte = 0;     // ControlByteBit
  uint8_t nExtControlByte = 0;  // ExtControlByteBit
  uint16_t nReserved = 0;       // always 0

  bool operator==(const NCTOIO_DRIVE_TWO_SPEED&) const = default;
};

static_assert(sizeof(NCTOIO_DRIVE_TWO_SPEED) == 12);
static_assert(offsetof(NCTOIO_DRIVE_TWO_SPEED, nOutData1) == 0);
static_assert(offsetof(NCTOIO_DRIVE_TWO_SPEED, nOutData2) == 4);
static_assert(offsetof(NCTOIO_DRIVE_TWO_SPEED, nControlByte) == 8);
static_assert(offsetof(NCTOIO_DRIVE_TWO_SPEED, nExtControlByte) == 9);
static_assert(offsetof(NCTOIO_DRIVE_TWO_SPEED, nReserved) == 10);

// Bit numbers of nControlByte (seed 004's table; bits 4 and 5 reserved).
enum class ControlByteBit : uint8_t {
  bMinusHigh = 0,  // rapid traverse, negative direction
  bMinusLow = 1,   // slow traverse, negative direction
  bPlusLow = 2,    // slow traverse, positive direction
  bPlusHigh = 3,   // rapid traverse, positive direction
  bBreakInv = 6,   // inverted braking bit (0 = brake active, 1 = passive)
  bBreak = 7,      // braking bit (1 = brake active)
};

// Bit numbers of nExtControlByte (seed 004's table; bits 4 and 5 reserved).
enum class ExtControlByteBit : uint8_t {
  bDirectionMinus = 0,
  bDirectionPlus = 1,
  bVeloLow = 2,
  bVeloHigh = 3,
  bBreakInv = 6,
  bBreak = 7,
};

// nAxisState (seed 004 "Axis movement state").
enum class TwoSpeedAxisState : uint32_t {
  kInactive = 0,              // set value generator not active (before the first start, disabled)
  kStopped = 20,              // axis stopped (after a positioning or a stop)
  kMainTravel = 21,           // main travel phase: rapid or creep by start velocity and override
  kHighToLowDelay = 22,       // braking phase: rapid-to-creep delay time running
  kLowSpeedTravel = 23,       // braking phase: creep travel
  kBrakeIncidenceDelay = 24,  // braking phase: delay time for brake incidence running
};

enum class TwoSpeedDirection : uint8_t { kNone, kPositive, kNegative };
enum class TwoSpeedVelocity : uint8_t { kOff, kLow, kHigh };

// One logical drive command: what both control bytes express.
struct TwoSpeedDriveCommand {
  TwoSpeedDirection direction = TwoSpeedDirection::kNone;
  TwoSpeedVelocity velocity = TwoSpeedVelocity::kOff;
  bool brake = true;  // brake applied

  bool operator==(const TwoSpeedDriveCommand&) const = default;
};

template <class Bit>
constexpr uint8_t bit_mask(Bit bit) noexcept {
  return static_cast<uint8_t>(1U << static_cast<unsigned>(bit));
}
template <class Bit>
constexpr bool bit_set(uint8_t byte, Bit bit) noexcept {
  return (byte & bit_mask(bit)) != 0;
}

// Writes nControlByte and nExtControlByte from `command`; the other fields are left as they are.
// A direction without a speed, or a speed without a direction, sets no travel bit at all.
constexpr void write_control_bytes(NCTOIO_DRIVE_TWO_SPEED& image,
                                   const TwoSpeedDriveCommand& command) noexcept {
  const bool travel =
      command.direction != TwoSpeedDirection::kNone && command.velocity != TwoSpeedVelocity::kOff;
  const bool minus = travel && command.direction == TwoSpeedDirection::kNegative;
  const bool plus = travel && command.direction == TwoSpeedDirection::kPositive;
  const bool high = travel && command.velocity == TwoSpeedVelocity::kHigh;
  const bool low = travel && command.velocity == TwoSpeedVelocity::kLow;
  using C = ControlByteBit;
  using E = ExtControlByteBit;
  uint8_t control = 0;
  uint8_t ext = 0;
  if (minus && high) control |= bit_mask(C::bMinusHigh);
  if (minus && low) control |= bit_mask(C::bMinusLow);
  if (plus && low) control |= bit_mask(C::bPlusLow);
  if (plus && high) control |= bit_mask(C::bPlusHigh);
  if (minus) ext |= bit_mask(E::bDirectionMinus);
  if (plus) ext |= bit_mask(E::bDirectionPlus);
  if (low) ext |= bit_mask(E::bVeloLow);
  if (high) ext |= bit_mask(E::bVeloHigh);
  control |= command.brake ? bit_mask(C::bBreak) : bit_mask(C::bBreakInv);
  ext |= command.brake ? bit_mask(E::bBreak) : bit_mask(E::bBreakInv);
  image.nControlByte = control;
  image.nExtControlByte = ext;
}

// The logical command nControlByte expresses. Contradicting travel bits (both directions, or
// both speeds) read as no travel, as a contactor interlock would; a brake bit that does not
// agree with its inverted bit reads as brake applied (the safe side).
constexpr TwoSpeedDriveCommand read_control_byte(uint8_t control) noexcept {
  using C = ControlByteBit;
  const bool minus = bit_set(control, C::bMinusHigh) || bit_set(control, C::bMinusLow);
  const bool plus = bit_set(control, C::bPlusHigh) || bit_set(control, C::bPlusLow);
  const bool high = bit_set(control, C::bMinusHigh) || bit_set(control, C::bPlusHigh);
  const bool low = bit_set(control, C::bMinusLow) || bit_set(control, C::bPlusLow);
  TwoSpeedDriveCommand command;
  command.brake = bit_set(control, C::bBreak) || !bit_set(control, C::bBreakInv);
  if (minus == plus || high == low) return command;
  command.direction = plus ? TwoSpeedDirection::kPositive : TwoSpeedDirection::kNegative;
  command.velocity = high ? TwoSpeedVelocity::kHigh : TwoSpeedVelocity::kLow;
  return command;
}

// True when both control bytes are exactly what write_control_bytes() makes of one command
// (bMinusHigh ⇔ bDirectionMinus ∧ bVeloHigh, …, bBreakInv = !bBreak, reserved bits 0).
constexpr bool control_bytes_consistent(const NCTOIO_DRIVE_TWO_SPEED& image) noexcept {
  NCTOIO_DRIVE_TWO_SPEED rewritten = image;
  write_control_bytes(rewritten, read_control_byte(image.nControlByte));
  return rewritten.nControlByte == image.nControlByte &&
         rewritten.nExtControlByte == image.nExtControlByte;
}

}  // namespace plc
