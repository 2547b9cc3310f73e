// The NC→PLC image's helpers (phase (f), servo_axis.cpp; the kept image, publish.cpp): a
// StateDWord bit or-ed in, and which bits EventImage keeps (the modulo positions:
// modulo_period.hpp).
#pragma once

#include <cstdint>

#include "plc_interface/axis_ref.hpp"

namespace nc::detail {

// Bits or-ed in without branches (every bit starts at 0).
constexpr void set_state_bit(uint32_t& word, plc::StateBit bit, bool value) noexcept {
  word |= static_cast<uint32_t>(value) << bit;
}

// The StateDWord bits event_image() gives; the others are computed every cycle.
inline constexpr uint32_t kEventStateBits =
    (1U << plc::kStateHomed) | (1U << plc::kStateErrorPropagationDelayed) |
    (1U << plc::kStateHasBeenStopped) | (1U << plc::kStateHasJob) | (1U << plc::kStateHomingBusy) |
    (1U << plc::kStateCompensating) | (1U << plc::kStateExtSetPointGenEnabled) |
    (1U << plc::kStateCoupled) | (1U << plc::kStateContinuousMotion) | (1U << plc::kStatePtpMode) |
    (1U << plc::kStateMotionCommandsLocked) | (1U << plc::kStateOperational) |
    (1U << plc::kStateError);

}  // namespace nc::detail
