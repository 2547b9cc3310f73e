// The state of the HLI coupling stage (hli_stage.hpp) that its parts read and write: each axis's
// setup and control unit, its list in force, the coupling matrix, the offsets c and the program
// and drive state of the last cycle. HliStage owns it and runs the cycle; ListEvaluation
// (list_evaluation.hpp) and DriveBrakes (drive_brakes.hpp) are views on it for one call.
// Also the stage's input and output types. index_of() is a cycle function (noexcept).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "hli/coupling_matrix.hpp"
#include "nc_core/axis_config.hpp"
#include "part_of.hpp"
#include "plc_interface/error_code.hpp"
#include "plc_interface/hli.hpp"

namespace nc::hli {

// What the stage needs of an axis's configuration (see axis_setup()).
struct AxisSetup {
  int ax_nr = 0;                          // logical axis number (AxisConfig::id), unique, != 0
  double emergency_deceleration = 1.0;    // mm/s², > 0 (P-AXIS-00003 resolved)
  bool sw_limit_min_enabled = false;      // P-AXIS-00177
  bool sw_limit_max_enabled = false;      // P-AXIS-00178
  double sw_limit_min = 0.0;              // mm
  double sw_limit_max = 0.0;              // mm
  bool forward_mapping = false;           // P-AXIS-00436
  bool forward_mapping_absolute = false;  // P-AXIS-00460
  bool couplable = true;  // false (two-speed axis): neither source nor target of a list, 0x4040
};

// The stage's view of an axis (config.id must already be the effective logical number).
AxisSetup axis_setup(const AxisConfig& config);

// Per-axis inputs of one cycle, in the stage's axis order (the kernel's add_axis order).
struct Inputs {
  std::span<const double> program_position;      // q, mm
  std::span<const double> program_velocity;      // mm/s
  std::span<const double> program_acceleration;  // mm/s²
  std::span<const bool> referenced;              // homed: software limits are monitored (70195)
  // The kernel's reasons to refuse a new list on an axis (kNone: none), checked before the
  // list itself: the axis is in error (0x4F06), has no controller enable (0x4223) or has
  // external setpoint generation enabled (0x424E). Empty: no such reasons (the stage alone).
  std::span<const plc::ErrorCode> refusal = {};
};

// Per-axis outputs of one cycle.
struct Outputs {
  std::span<double> drive_position;      // d, mm: NcToPlc.SetPos
  std::span<double> drive_velocity;      // mm/s
  std::span<double> drive_acceleration;  // mm/s²
  // kNone, or the axis error the kernel raises on the axis this cycle (70200, 70195): the stage
  // has switched the list off and brakes the drive; the kernel stops the program motion.
  std::span<plc::ErrorCode> stop;
};

struct HliState {
  static constexpr std::size_t kNoAxis = static_cast<std::size_t>(-1);
  static constexpr std::size_t kListSize = plc::hli::HLI_AX_COUPLING_MAXIDX + 1;

  explicit HliState(double cycle_time) noexcept : cycle_time_(cycle_time) {}

  std::size_t size() const noexcept { return setups_.size(); }
  // The axis index of logical axis number `ax_nr`, kNoAxis when there is none.
  std::size_t index_of(int ax_nr) const noexcept;

  enum class State : uint8_t { kFree, kCoupled, kBraking };

  struct Entry {
    std::size_t source = 0;
    double factor = 0.0;
    double q_activation = 0.0;  // source's program position when the list was taken
    plc::hli::HLI_AX_COUPLING_STATE_DESC shown{};
  };

  struct Target {
    State state = State::kFree;
    std::array<Entry, kListSize> entries{};
    std::size_t count = 0;
    bool fract = false;  // a FRACT entry with a non-zero factor is in force (70195 monitoring)
    double d_activation = 0.0;
    double brake_velocity = 0.0;  // kBraking: the drive's velocity, decreasing to 0
  };

  // The list parsed from command_w, before it is taken.
  struct Candidate {
    std::array<Entry, kListSize> entries{};
    std::size_t count = 0;
    bool fract = false;
  };

  double cycle_time_;
  std::vector<AxisSetup> setups_;
  std::deque<plc::hli::HLI_AX> units_;  // deque: addresses stay valid as axes are added
  std::vector<plc::hli::HLI_AX*> pointers_;
  std::vector<Target> targets_;
  std::vector<uint32_t> source_uses_;   // entries naming the axis in other axes' lists in force
  std::vector<std::size_t> dfs_stack_;  // loop check scratch (reserved in add_axis)
  std::vector<uint8_t> dfs_seen_;

  CouplingMatrix matrix_;        // K: the targets' rows
  Eigen::VectorXd c_;            // offsets: d = q + c (free), K·q + c (target), c (braking)
  Eigen::VectorXd q_, qv_, qa_;  // program state of the last cycle
  Eigen::VectorXd d_, dv_, da_;  // drive state of the last cycle
};

// The base of the stage's parts (list_evaluation.hpp, drive_brakes.hpp).
using HliPart = PartOf<HliState>;

}  // namespace nc::hli
