// The scope: a recorder that samples axis signals every cycle, like TwinCAT ScopeView.
//
// Channels are chosen at set-up (any NcToPlc / PlcToNc signal of any axis, or any double the
// application owns); the storage for `capacity` samples of every channel is reserved then, so
// record() — a cycle function — only copies numbers: no allocation, no locks, no I/O. When the
// storage is full further samples are counted as dropped, never written. After the run the
// recording is written as CSV or JSON (after-run functions: they allocate and may throw).
// svg_plot.hpp draws it the way the seed's figures are drawn (seed 000 §2.1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "plc_interface/axis_ref.hpp"

namespace nc {

// The axis signals a scope can sample. The names (signal_name) are the NcToPlc / PlcToNc field
// names, so a trace column reads like the PLC variable it came from.
enum class Signal : uint8_t {
  kSetPos,                // NcToPlc.SetPos, mm
  kActPos,                // NcToPlc.ActPos, mm
  kModuloSetPos,          // NcToPlc.ModuloSetPos, mm
  kModuloActPos,          // NcToPlc.ModuloActPos, mm
  kTargetPos,             // NcToPlc.TargetPos, mm
  kSetVelo,               // NcToPlc.SetVelo, mm/s
  kActVelo,               // NcToPlc.ActVelo, mm/s
  kTargetVelo,            // NcToPlc.TargetVelo, mm/s
  kSetAcc,                // NcToPlc.SetAcc, mm/s²
  kActAcc,                // NcToPlc.ActAcc, mm/s²
  kSetJerk,               // NcToPlc.SetJerk, mm/s³
  kPosDiff,               // NcToPlc.PosDiff (following error), mm
  kCompensationDistance,  // NcToPlc.CompensationDistance, mm
  kStateDWord,            // NcToPlc.StateDWord (as a number)
  kErrorCode,             // NcToPlc.ErrorCode
  kAxisState,             // NcToPlc.AxisState
  kCoupleState,           // NcToPlc.CoupleState
  kCmdNo,                 // NcToPlc.CmdNo
  kCmdState,              // NcToPlc.CmdState
  kOverride,              // PlcToNc.Override, 0 … 1'000'000
  kControlDWord,          // PlcToNc.ControlDWord
};

std::string_view signal_name(Signal signal) noexcept;
std::string_view signal_unit(Signal signal) noexcept;  // "" for dimensionless words

// The seven signals of the seed's figures, in the order of their colour legend (seed 000 §2.1).
inline constexpr Signal kMotionSignals[] = {Signal::kSetPos,  Signal::kActPos, Signal::kSetVelo,
                                            Signal::kActVelo, Signal::kSetAcc, Signal::kActAcc,
                                            Signal::kPosDiff};

// What one channel records, for readers of a finished recording.
struct ScopeChannelInfo {
  std::string name;       // column name, e.g. "Axis1.SetPos"
  std::string axis_name;  // "" for a channel over an application variable
  std::string unit;       // e.g. "mm/s"
  bool is_axis_signal = false;
  Signal signal = Signal::kSetPos;  // valid when is_axis_signal
};

namespace detail {

// A scope's recording: its channels and samples, and the after-run functions that read and write
// them. Scope (below) fills it; users call these members through Scope.
class ScopeRecording {
 public:
  std::size_t capacity() const noexcept { return capacity_; }
  std::size_t size() const noexcept { return size_; }
  std::size_t dropped() const noexcept { return dropped_; }
  std::size_t channel_count() const noexcept { return channels_.size(); }

  const ScopeChannelInfo& channel(std::size_t index) const { return channels_.at(index).info; }
  // Index of the channel named `name`, or channel_count() when there is none.
  std::size_t find(std::string_view name) const noexcept;
  std::size_t find(std::string_view axis_name, Signal signal) const noexcept;

  std::span<const double> time() const noexcept { return {times_.data(), size_}; }
  std::span<const double> values(std::size_t index) const {
    return {channels_.at(index).values.data(), size_};
  }

  // After-run: the recording as CSV. Header "time [s],<name> [<unit>],…" (the bracket is left
  // out for dimensionless channels), then one row per sample; numbers in their shortest form
  // that reads back to the same double.
  void write_csv(std::ostream& out) const;
  // After-run: {"sample_count": n, "dropped": d, "time": [...], "channels": [{"name", "axis",
  // "signal", "unit", "values": [...]}, …]}.
  nlohmann::json to_json() const;
  // After-run: write to a file (creating its parent folder); throw std::runtime_error naming the
  // path when it cannot be written.
  void write_csv(const std::filesystem::path& path) const;
  void write_json(const std::filesystem::path& path) const;

 protected:
  struct Channel {
    ScopeChannelInfo info;
    const plc::AXIS_REF* axis = nullptr;
    const double* variable = nullptr;
    std::vector<double> values;
  };

  explicit ScopeRecording(std::size_t capacity) noexcept : capacity_(capacity) {}

  std::size_t capacity_;
  std::size_t size_ = 0;
  std::size_t dropped_ = 0;
  std::vector<double> times_;
  std::vector<Channel> channels_;
};

}  // namespace detail

// The recorder: set-up and the cycle; the recording's readers and writers come from
// detail::ScopeRecording.
class Scope : public detail::ScopeRecording {
 public:
  // Set-up: reserves room for `capacity` samples (≥ 1) of the time column. Throws
  // std::invalid_argument for capacity 0.
  explicit Scope(std::size_t capacity);

  // Set-up: adds a channel sampling `signal` of `axis`, named "<axis_name>.<signal name>". The
  // axis must outlive the scope (Kernel::add_axis references stay valid for the kernel's life).
  // Throws std::invalid_argument for an empty or duplicate name or one containing a comma, quote
  // or line break (it must stay one CSV cell), std::logic_error once samples were recorded.
  // Returns the channel's index.
  std::size_t add_signal(const plc::AXIS_REF& axis, std::string_view axis_name, Signal signal);
  // Set-up: adds the seven kMotionSignals of one axis.
  void add_motion_signals(const plc::AXIS_REF& axis, std::string_view axis_name);
  // Set-up: adds a channel over any double the application owns (a PLC variable, a plant value).
  std::size_t add_variable(const double* source, std::string_view name, std::string_view unit);

  // Cycle: samples every channel at time `time` (s). Returns false, and counts the sample as
  // dropped, when the storage is full.
  bool record(double time) noexcept;

  // Cycle: forgets the samples (keeps channels and storage).
  void clear() noexcept;

 private:
  std::size_t add_channel(Channel channel);
  static double sample(const Channel& channel) noexcept;
};

}  // namespace nc
