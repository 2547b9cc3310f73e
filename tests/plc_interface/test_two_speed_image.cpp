// The two-speed NC → I/O image bit for bit (SPEC E4, E5; seed 004 "Drive interface for
// rapid/creep axes NC → I/O (12 bytes)" and "Axis movement state"): layout, bit numbers, both
// control bytes written from one logical command and always consistent, nAxisState values.
#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>

#include "plc_interface/two_speed.hpp"

using plc::ControlByteBit;
using plc::ExtControlByteBit;
using plc::TwoSpeedDirection;
using plc::TwoSpeedVelocity;

TEST_CASE("the image is 12 bytes at the seed's offsets", "[two_speed][image]") {
  CHECK(sizeof(plc::NCTOIO_DRIVE_TWO_SPEED) == 12);
  CHECK(offsetof(plc::NCTOIO_DRIVE_TWO_SPEED, nOutData1) == 0);
  CHECK(offsetof(plc::NCTOIO_DRIVE_TWO_SPEED, nOutData2) == 4);
  CHECK(offsetof(plc::NCTOIO_DRIVE_TWO_SPEED, nControlByte) == 8);
  CHECK(offsetof(plc::NCTOIO_DRIVE_TWO_SPEED, nExtControlByte) == 9);
  CHECK(offsetof(plc::NCTOIO_DRIVE_TWO_SPEED, nReserved) == 10);
  CHECK(sizeof(plc::NCTOIO_DRIVE_TWO_SPEED::nOutData1) == 4);
  CHECK(sizeof(plc::NCTOIO_DRIVE_TWO_SPEED::nReserved) == 2);
  const plc::NCTOIO_DRIVE_TWO_SPEED zero{};
  CHECK(zero.nOutData1 == 0);
  CHECK(zero.nOutData2 == 0);
  CHECK(zero.nReserved == 0);
}

TEST_CASE("control byte bits sit at the seed's bit numbers", "[two_speed][image]") {
  CHECK(static_cast<int>(ControlByteBit::bMinusHigh) == 0);
  CHECK(static_cast<int>(ControlByteBit::bMinusLow) == 1);
  CHECK(static_cast<int>(ControlByteBit::bPlusLow) == 2);
  CHECK(static_cast<int>(ControlByteBit::bPlusHigh) == 3);
  CHECK(static_cast<int>(ControlByteBit::bBreakInv) == 6);
  CHECK(static_cast<int>(ControlByteBit::bBreak) == 7);
  CHECK(static_cast<int>(ExtControlByteBit::bDirectionMinus) == 0);
  CHECK(static_cast<int>(ExtControlByteBit::bDirectionPlus) == 1);
  CHECK(static_cast<int>(ExtControlByteBit::bVeloLow) == 2);
  CHECK(static_cast<int>(ExtControlByteBit::bVeloHigh) == 3);
  CHECK(static_cast<int>(ExtControlByteBit::bBreakInv) == 6);
  CHECK(static_cast<int>(ExtControlByteBit::bBreak) == 7);
  CHECK(plc::bit_mask(ControlByteBit::bBreak) == 0x80);
}

TEST_CASE("nAxisState values are the seed's", "[two_speed][image]") {
  using S = plc::TwoSpeedAxisState;
  CHECK(static_cast<uint32_t>(S::kInactive) == 0);
  CHECK(static_cast<uint32_t>(S::kStopped) == 20);
  CHECK(static_cast<uint32_t>(S::kMainTravel) == 21);
  CHECK(static_cast<uint32_t>(S::kHighToLowDelay) == 22);
  CHECK(static_cast<uint32_t>(S::kLowSpeedTravel) == 23);
  CHECK(static_cast<uint32_t>(S::kBrakeIncidenceDelay) == 24);
}

namespace {

struct Row {
  TwoSpeedDirection direction;
  TwoSpeedVelocity velocity;
  bool brake;
  uint8_t control;  // expected nControlByte
  uint8_t ext;      // expected nExtControlByte
};

constexpr auto kNone = TwoSpeedDirection::kNone;
constexpr auto kPlus = TwoSpeedDirection::kPositive;
constexpr auto kMinus = TwoSpeedDirection::kNegative;
constexpr auto kOff = TwoSpeedVelocity::kOff;
constexpr auto kLow = TwoSpeedVelocity::kLow;
constexpr auto kHigh = TwoSpeedVelocity::kHigh;

// Every logical command with the bytes the seed's tables give: nControlByte 0 bMinusHigh,
// 1 bMinusLow, 2 bPlusLow, 3 bPlusHigh, 6 bBreakInv, 7 bBreak; nExtControlByte 0 bDirectionMinus,
// 1 bDirectionPlus, 2 bVeloLow, 3 bVeloHigh, 6 bBreakInv, 7 bBreak.
constexpr Row kTable[] = {
    {kNone, kOff, true, 0x80, 0x80},   {kNone, kOff, false, 0x40, 0x40},
    {kNone, kLow, true, 0x80, 0x80},   {kNone, kLow, false, 0x40, 0x40},
    {kNone, kHigh, true, 0x80, 0x80},  {kNone, kHigh, false, 0x40, 0x40},
    {kPlus, kOff, true, 0x80, 0x80},   {kPlus, kOff, false, 0x40, 0x40},
    {kPlus, kLow, true, 0x84, 0x86},   {kPlus, kLow, false, 0x44, 0x46},
    {kPlus, kHigh, true, 0x88, 0x8A},  {kPlus, kHigh, false, 0x48, 0x4A},
    {kMinus, kOff, true, 0x80, 0x80},  {kMinus, kOff, false, 0x40, 0x40},
    {kMinus, kLow, true, 0x82, 0x85},  {kMinus, kLow, false, 0x42, 0x45},
    {kMinus, kHigh, true, 0x81, 0x89}, {kMinus, kHigh, false, 0x41, 0x49},
};

}  // namespace

TEST_CASE("both control bytes are written from one command, bit for bit", "[two_speed][image]") {
  for (const Row& row : kTable) {
    plc::NCTOIO_DRIVE_TWO_SPEED image{};
    image.nOutData1 = 0xDEADBEEF;  // not the function's business: left as it is
    plc::write_control_bytes(image, {row.direction, row.velocity, row.brake});
    INFO("direction " << static_cast<int>(row.direction) << ", velocity "
                      << static_cast<int>(row.velocity) << ", brake " << row.brake);
    CHECK(image.nControlByte == row.control);
    CHECK(image.nExtControlByte == row.ext);
    CHECK(image.nOutData1 == 0xDEADBEEF);
    CHECK(image.nReserved == 0);
    CHECK(plc::control_bytes_consistent(image));
    // Reserved bits 4 and 5 never set; brake and inverted brake always complementary.
    CHECK((image.nControlByte & 0x30) == 0);
    CHECK((image.nExtControlByte & 0x30) == 0);
    CHECK(plc::bit_set(image.nControlByte, ControlByteBit::bBreak) !=
          plc::bit_set(image.nControlByte, ControlByteBit::bBreakInv));
    CHECK(plc::bit_set(image.nExtControlByte, ExtControlByteBit::bBreak) !=
          plc::bit_set(image.nExtControlByte, ExtControlByteBit::bBreakInv));
  }
}

TEST_CASE("the travel bits of one byte follow from the other", "[two_speed][image]") {
  for (const Row& row : kTable) {
    const uint8_t c = row.control;
    const uint8_t e = row.ext;
    using C = ControlByteBit;
    using E = ExtControlByteBit;
    const bool minus = plc::bit_set(e, E::bDirectionMinus);
    const bool plus = plc::bit_set(e, E::bDirectionPlus);
    const bool low = plc::bit_set(e, E::bVeloLow);
    const bool high = plc::bit_set(e, E::bVeloHigh);
    CHECK(plc::bit_set(c, C::bMinusHigh) == (minus && high));
    CHECK(plc::bit_set(c, C::bMinusLow) == (minus && low));
    CHECK(plc::bit_set(c, C::bPlusLow) == (plus && low));
    CHECK(plc::bit_set(c, C::bPlusHigh) == (plus && high));
    CHECK(plc::bit_set(c, C::bBreak) == plc::bit_set(e, E::bBreak));
  }
}

TEST_CASE("reading the control byte gives back the command that wrote it", "[two_speed][image]") {
  for (const Row& row : kTable) {
    const plc::TwoSpeedDriveCommand read = plc::read_control_byte(row.control);
    const bool travel = row.direction != kNone && row.velocity != kOff;
    CHECK(read.brake == row.brake);
    CHECK(read.direction == (travel ? row.direction : kNone));
    CHECK(read.velocity == (travel ? row.velocity : kOff));
  }
  // Contradicting travel bits drive nothing; a brake bit equal to its inverse reads as applied.
  CHECK(plc::read_control_byte(0x4C).velocity == kOff);    // bPlusLow + bPlusHigh
  CHECK(plc::read_control_byte(0x49).direction == kNone);  // bMinusHigh + bPlusHigh
  CHECK(plc::read_control_byte(0x08).brake);
  CHECK(plc::read_control_byte(0xC8).brake);
}

TEST_CASE("every single flipped bit of a consistent image is detected", "[two_speed][image]") {
  for (const Row& row : kTable) {
    plc::NCTOIO_DRIVE_TWO_SPEED image{};
    image.nControlByte = row.control;
    image.nExtControlByte = row.ext;
    REQUIRE(plc::control_bytes_consistent(image));
    for (int bit = 0; bit < 16; ++bit) {
      plc::NCTOIO_DRIVE_TWO_SPEED flipped = image;
      if (bit < 8) {
        flipped.nControlByte = static_cast<uint8_t>(flipped.nControlByte ^ (1U << bit));
      } else {
        flipped.nExtControlByte = static_cast<uint8_t>(flipped.nExtControlByte ^ (1U << (bit - 8)));
      }
      INFO("control " << int{row.control} << ", flipped bit " << bit);
      CHECK_FALSE(plc::control_bytes_consistent(flipped));
    }
  }
}
