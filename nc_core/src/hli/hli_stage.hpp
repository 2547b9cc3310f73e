// The HLI axis-coupling stage (SPEC D2–D5, seed 002): phase (c) of the NC cycle.
//
// Every axis has a program position q (what its own motion commands) and a drive command
// position d. The stage owns each axis's HLI control unit (plc::hli::HLI_AX, what gpAx[i] points
// to) and maps q to d with one coupling matrix over all axes: d = K·q + c (Eigen, dense,
// row-major; only the targets' rows are stored and multiplied, packed at the top, so the cost
// per cycle is (number of targets) × (number of axes)). An axis without a list has the unit row
// (d = q + offset, not stored); a target's row holds its factors, and c is set when the list is
// taken so that d does not jump:
// d = d(activation) + Σ K·(q_source − q_source(activation)). Sources contribute program movement,
// never drive movement, so there are no chains. The stage evaluates a list in the cycle the PLC
// sets semaphor_rw and resets the semaphore in that same cycle; refused lists change nothing
// (error_r says why), 70200 and 70195 stop the target (its list off, its drive braking at the
// emergency deceleration; Outputs::stop tells the kernel to raise the axis error).
// Set-up functions (constructor, reserve, add_axis) may allocate and throw; cycle(), stop() and
// the queries are noexcept and allocate nothing (the matrix is sized in add_axis).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "nc_core/axis_config.hpp"
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

class HliStage {
 public:
  static constexpr std::size_t kNoAxis = static_cast<std::size_t>(-1);
  static constexpr std::size_t kListSize = plc::hli::HLI_AX_COUPLING_MAXIDX + 1;

  explicit HliStage(double cycle_time);  // s, > 0; throws std::invalid_argument

  // Set-up: room for `axes` axes without reallocating the per-axis storage later.
  void reserve(std::size_t axes);
  // Set-up: adds an axis (index = size() before the call); the control unit's address stays
  // valid for the stage's life. Throws std::invalid_argument for ax_nr 0 or a repeated ax_nr,
  // a deceleration <= 0 or non-finite values.
  plc::hli::HLI_AX& add_axis(const AxisSetup& setup);

  std::size_t size() const noexcept { return setups_.size(); }
  // gpAx[axis_idx] of the seed: pointers to the control units, indexed by axis index.
  std::span<plc::hli::HLI_AX* const> gpAx() const noexcept { return pointers_; }
  plc::hli::HLI_AX& unit(std::size_t axis) noexcept { return *pointers_[axis]; }
  std::size_t index_of(int ax_nr) const noexcept;

  // Cycle: computes d for every axis, evaluates the lists whose semaphore is set, monitors
  // FRACT targets against their software limits. False (and nothing done) when a span's size
  // differs from size().
  bool cycle(const Inputs& in, const Outputs& out) noexcept;

  // Cycle: the axis is stopped (the kernel calls this when it stops a target for its own
  // reasons): its list goes off and its drive brakes from its current velocity at the emergency
  // deceleration, then follows its own program motion from where it stands.
  void stop(std::size_t axis) noexcept;
  // Cycle: the target's drive is off (no controller enable): its list goes off without braking,
  // as a list switched off by the PLC (d stays, then follows the axis's own program). No-op for
  // an axis without a list in force.
  void release(std::size_t axis) noexcept;

  // The program coordinate #CHANNEL INIT [CMDPOS] would give the axis now (D5): the drive
  // position d by default; with P-AXIS-00436 the q for which the target's list gives d, relative
  // to the activation positions, or with P-AXIS-00460 as if coupled at position 0.
  double command_position_request(std::size_t axis) const noexcept;

  bool coupled(std::size_t axis) const noexcept { return targets_[axis].state == State::kCoupled; }
  // The axis is a source of another axis's list in force (its self entry does not count).
  bool source_of_other(std::size_t axis) const noexcept { return source_uses_[axis] > 0; }
  bool braking(std::size_t axis) const noexcept { return targets_[axis].state == State::kBraking; }
  // K(target, source) in force: the unit row for an axis without a list, 0 while braking.
  double factor(std::size_t target, std::size_t source) const noexcept;

 private:
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

  plc::ErrorCode parse(const plc::hli::HLI_AX_COUPLING_COMMAND& command,
                       Candidate& list) const noexcept;
  bool makes_loop(std::size_t target, const Candidate& list) noexcept;
  bool involved_axis_moves(std::size_t target, const Candidate& list) const noexcept;
  void evaluate(std::size_t target, plc::ErrorCode refusal, const Outputs& out) noexcept;
  void take(std::size_t target, const Candidate& list) noexcept;
  void drop_row(std::size_t axis) noexcept;
  void grow_matrix(std::size_t axes);
  void halt(std::size_t axis, plc::ErrorCode code, const Outputs& out) noexcept;
  void advance_brake(std::size_t axis) noexcept;
  bool cannot_stop_before_limit(std::size_t axis) const noexcept;
  void publish(std::size_t axis) noexcept;
  // Counts t's sources other than `target` itself in source_uses_ (add) or out of it.
  void count_sources(std::size_t target, const Target& t, bool add) noexcept;

  double cycle_time_;
  std::vector<AxisSetup> setups_;
  std::deque<plc::hli::HLI_AX> units_;  // deque: addresses stay valid as axes are added
  std::vector<plc::hli::HLI_AX*> pointers_;
  std::vector<Target> targets_;
  std::vector<uint32_t> source_uses_;   // entries naming the axis in other axes' lists in force
  std::vector<std::size_t> dfs_stack_;  // loop check scratch (reserved in add_axis)
  std::vector<uint8_t> dfs_seen_;

  // Coupling matrix: row j is the row of target rows_[j] (j < rows_.size()), column = source;
  // square at a capacity >= size(), zero outside the stored rows and the axes in use.
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Matrix k_;
  std::vector<std::size_t> rows_;    // targets in row order (reserved in add_axis)
  std::vector<std::size_t> row_of_;  // axis → its row, kNoAxis when it has none
  Eigen::VectorXd product_;          // K·x of the stored rows (scratch, sized in add_axis)
  Eigen::VectorXd c_;                // offsets: d = q + c (free), K·q + c (target), c (braking)
  Eigen::VectorXd q_, qv_, qa_;      // program state of the last cycle
  Eigen::VectorXd d_, dv_, da_;      // drive state of the last cycle
};

}  // namespace nc::hli
