// The base of nc::Kernel (kernel.hpp) that owns the kernel's axes and what it keeps per axis (the
// snapshots, the coupling graph, the HLI phase, the planning scratch), with the lookups the
// kernel offers on them. Not for direct use: users call these members through nc::Kernel.
//
// Set-up lookups by name throw nc::ConfigError when there is no such axis; the others are
// noexcept and allocate nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "nc_core/axis_config.hpp"
#include "nc_core/axis_snapshot.hpp"
#include "nc_core/coupling_graph.hpp"
#include "plc_interface/axis_ref.hpp"
#include "plc_interface/hli.hpp"
#include "plc_interface/two_speed.hpp"

namespace nc {

class Profile;

namespace detail {

class ServoAxis;
class HliPhase;

class KernelAxes {
 public:
  // Set-up: the axis with this name; ConfigError when there is none.
  plc::AXIS_REF& axis(std::string_view name);
  const plc::AXIS_REF& axis(std::string_view name) const;
  // By index (0 … axis_count()-1, the order of add_axis; NcToPlc.AxisIndex). Unchecked.
  plc::AXIS_REF& axis(std::size_t index) noexcept;
  std::size_t axis_count() const noexcept { return axes_.size(); }
  // The configuration as the axis uses it (id filled in).
  const AxisConfig& config(std::string_view name) const;
  // The simulated reference cam of an axis (AxisConfig::homing_cam_position / _width), a digital
  // input for the PLC to pass to MC_Home.bCalibrationCam. Set-up lookup by name (ConfigError).
  bool reference_cam(std::string_view name) const;
  // Set-up lookup, read in the cycle: the 12-byte NC→I/O image of the two-speed axis `name`
  // (SPEC E4), as written by the last cycle; the reference stays valid for the kernel's life.
  // ConfigError when there is no such axis or it is not of kind kTwoSpeed.
  const plc::NCTOIO_DRIVE_TWO_SPEED& two_speed_output(std::string_view name) const;

  // Axis `index` as the last cycle left it, in the form other axes read it in a cycle (filled in
  // here: a cycle writes snapshots only while some axis reads another). Unchecked index. Between
  // cycles, not concurrently with cycle().
  const AxisSnapshot& snapshot(std::size_t index) const noexcept;
  // Who follows whom (the MC_GearIn / MC_GearInDyn couplings in force).
  const CouplingGraph& couplings() const noexcept { return couplings_; }

  // HLI axis coupling (SPEC D1, seed 002): gpAx[axis_idx], the CNC control unit of each axis,
  // indexed by axis index (the order of add_axis); the pointers stay valid for the kernel's life.
  std::span<plc::hli::HLI_AX* const> gpAx() const noexcept;
  // D5: the program coordinate #CHANNEL INIT [CMDPOS] would give logical axis `ax_nr`
  // (AxisConfig::id) now: the drive position by default, solved through its list with
  // P-AXIS-00436 / 00460. NaN for an unknown axis number.
  double command_position_request(int ax_nr) const noexcept;
  // The check of the steady cycle's kept image (docs/performance.md "Fourth pass", "Fifth
  // pass"): what axis `index` published in the last cycle that only events change (StateDWord
  // bits, AxisState, CoupleState, the compensation's values, TargetVelo, GearRatio, ErrorCode,
  // Warning, CmdNo, CmdState, AxisIndex) equals its full recomputation now. For tests and the
  // fuzz watch, between a cycle and the PLC's next writes. Unchecked index.
  bool published_image_consistent(std::size_t index) const noexcept;

 protected:
  // Set-up: no axes, the planning scratch (the kernel makes the HLI phase once its
  // configuration is valid).
  KernelAxes();
  ServoAxis& find(std::string_view name) const;

  std::vector<std::unique_ptr<ServoAxis>> axes_;
  mutable std::vector<AxisSnapshot> snapshots_;  // snapshot() fills in the motion values
  CouplingGraph couplings_;
  std::vector<uint8_t> group_ready_;  // scratch of Kernel::mark_ready_groups(), one per axis
  // Phase (c): the HLI coupling stage (on the heap: its control units keep their addresses).
  std::unique_ptr<HliPhase> hli_;
  // One planning scratch profile for all axes (a start plans here first, so a refusal changes
  // nothing); on the heap so that its address survives a move of the Kernel.
  std::unique_ptr<Profile> scratch_;
};

}  // namespace detail
}  // namespace nc
