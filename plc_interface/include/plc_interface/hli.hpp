// The CNC HLI axis-coupling control unit, mirrored field by field (SPEC D1, seed 002 §2).
//
// gpAx[axis_idx]^.lr_mc_control.axis_coupling of the seed is, in C++,
// gpAx[axis_idx]->lr_mc_control.axis_coupling: the PLC writes a list of coupling
// specifications into command_w.desc[] and sets command_w.semaphor_rw; the NC evaluates the list
// in its next cycle, resets semaphor_rw in that same cycle and shows the outcome in state_r
// (active_r, the couplings in force in desc[], the ID of the last evaluation in error_r).
// lr_state.active_rev_r is the axis's command velocity in 1e-3 mm/s (1e-3 °/s).
// Plain data, std only: the same single thread runs PLC and NC (the cycle driver), so the
// semaphore is a plain bool. Field types follow the seed's value ranges.
#pragma once

#include <array>
#include <cstdint>

namespace plc::hli {

// Highest index of a coupling list (8 entries) and of the axis table (64 axes).
inline constexpr int HLI_AX_COUPLING_MAXIDX = 7;
inline constexpr int HLI_SYS_AX_MAXIDX = 63;
// Largest |K| = |fract_num / fract_denom| accepted (P-ERR-70397 above it). Chosen below the
// 32768 an int16 fraction can reach, so that the error can be provoked; exactly 1000 is accepted.
inline constexpr int HLI_AXIS_COUPLING_FACT_MAX = 1000;

// Coupling modes (seed 002 "Coupling modes").
inline constexpr uint16_t HLI_AXIS_COUPLING_INACTIVE = 0;  // ends the list; first entry: all off
inline constexpr uint16_t HLI_AXIS_COUPLING_ZERO = 1;      // K = 0 (shuts the axis down)
inline constexpr uint16_t HLI_AXIS_COUPLING_DIRECT = 2;    // K = 1
inline constexpr uint16_t HLI_AXIS_COUPLING_MIRROR = 3;    // K = -1
inline constexpr uint16_t HLI_AXIS_COUPLING_FRACT = 4;     // K = fract_num / fract_denom

// One coupling specification as the PLC commands it.
struct HLI_AX_COUPLING_DESC {
  int32_t ax_nr = 0;  // logical axis number of the source axis (nc::AxisConfig::id)
  uint16_t mode = HLI_AXIS_COUPLING_INACTIVE;
  int16_t fract_num = 0;    // FRACT only; 0 acts as ZERO
  int16_t fract_denom = 0;  // FRACT only; 0 is refused (70396)

  bool operator==(const HLI_AX_COUPLING_DESC&) const = default;
};

// One coupling in force as the NC shows it.
struct HLI_AX_COUPLING_STATE_DESC {
  int32_t ax_nr = 0;
  uint16_t mode = HLI_AXIS_COUPLING_INACTIVE;

  bool operator==(const HLI_AX_COUPLING_STATE_DESC&) const = default;
};

struct HLI_AX_COUPLING_COMMAND {
  std::array<HLI_AX_COUPLING_DESC, HLI_AX_COUPLING_MAXIDX + 1> desc{};
  bool semaphor_rw = false;  // set by the PLC, reset by the NC after evaluating the list
};

struct HLI_AX_COUPLING_STATE {
  bool active_r = false;  // a coupling list is in force on this axis
  std::array<HLI_AX_COUPLING_STATE_DESC, HLI_AX_COUPLING_MAXIDX + 1> desc{};  // in force
  uint32_t error_r = 0;  // ID of the last evaluation (0, 70200, 70396, 70397, 70410, …) or 70195
};

struct HLI_AX_COUPLING {
  HLI_AX_COUPLING_COMMAND command_w;
  HLI_AX_COUPLING_STATE state_r;
};

struct HLI_MC_CONTROL {
  HLI_AX_COUPLING axis_coupling;
};

struct HLI_AX_STATE {
  int32_t active_rev_r = 0;  // command velocity of the drive, 1e-3 mm/s (1e-3 °/s), saturated
};

// What gpAx[axis_idx] points to.
struct HLI_AX {
  HLI_MC_CONTROL lr_mc_control;
  HLI_AX_STATE lr_state;
};

}  // namespace plc::hli
