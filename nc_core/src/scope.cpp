#include "nc_core/scope.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace nc {
namespace {

struct SignalInfo {
  std::string_view name;
  std::string_view unit;
};

constexpr SignalInfo info_of(Signal signal) noexcept {
  switch (signal) {
    case Signal::kSetPos:
      return {"SetPos", "mm"};
    case Signal::kActPos:
      return {"ActPos", "mm"};
    case Signal::kModuloSetPos:
      return {"ModuloSetPos", "mm"};
    case Signal::kModuloActPos:
      return {"ModuloActPos", "mm"};
    case Signal::kTargetPos:
      return {"TargetPos", "mm"};
    case Signal::kSetVelo:
      return {"SetVelo", "mm/s"};
    case Signal::kActVelo:
      return {"ActVelo", "mm/s"};
    case Signal::kTargetVelo:
      return {"TargetVelo", "mm/s"};
    case Signal::kSetAcc:
      return {"SetAcc", "mm/s^2"};
    case Signal::kActAcc:
      return {"ActAcc", "mm/s^2"};
    case Signal::kSetJerk:
      return {"SetJerk", "mm/s^3"};
    case Signal::kPosDiff:
      return {"PosDiff", "mm"};
    case Signal::kCompensationDistance:
      return {"CompensationDistance", "mm"};
    case Signal::kStateDWord:
      return {"StateDWord", ""};
    case Signal::kErrorCode:
      return {"ErrorCode", ""};
    case Signal::kAxisState:
      return {"AxisState", ""};
    case Signal::kCoupleState:
      return {"CoupleState", ""};
    case Signal::kCmdNo:
      return {"CmdNo", ""};
    case Signal::kCmdState:
      return {"CmdState", ""};
    case Signal::kOverride:
      return {"Override", ""};
    case Signal::kControlDWord:
      return {"ControlDWord", ""};
  }
  return {"?", ""};
}

// A name must stay a single CSV cell and a readable JSON string.
bool is_valid_name(std::string_view name) noexcept {
  if (name.empty()) return false;
  for (const char c : name) {
    if (c == ',' || c == '"' || c == '\n' || c == '\r') return false;
  }
  return true;
}

}  // namespace

std::string_view signal_name(Signal signal) noexcept {
  return info_of(signal).name;
}
std::string_view signal_unit(Signal signal) noexcept {
  return info_of(signal).unit;
}

Scope::Scope(std::size_t capacity) : ScopeRecording(capacity) {
  if (capacity == 0) throw std::invalid_argument("scope capacity must be at least 1 sample");
  times_.resize(capacity_);
}

std::size_t Scope::add_channel(Channel channel) {
  if (size_ != 0) {
    throw std::logic_error("scope channel '" + channel.info.name +
                           "' added after recording started");
  }
  if (!is_valid_name(channel.info.name)) {
    throw std::invalid_argument("scope channel name '" + channel.info.name +
                                "' is empty or contains a comma, quote or line break");
  }
  if (find(channel.info.name) != channels_.size()) {
    throw std::invalid_argument("scope channel '" + channel.info.name + "' exists already");
  }
  channel.values.resize(capacity_);
  channels_.push_back(std::move(channel));
  return channels_.size() - 1;
}

std::size_t Scope::add_signal(const plc::AXIS_REF& axis, std::string_view axis_name,
                              Signal signal) {
  if (!is_valid_name(axis_name)) {
    throw std::invalid_argument("scope axis name '" + std::string(axis_name) +
                                "' is empty or contains a comma, quote or line break");
  }
  Channel channel;
  channel.info.name = std::string(axis_name) + "." + std::string(signal_name(signal));
  channel.info.axis_name = std::string(axis_name);
  channel.info.unit = std::string(signal_unit(signal));
  channel.info.is_axis_signal = true;
  channel.info.signal = signal;
  channel.axis = &axis;
  return add_channel(std::move(channel));
}

void Scope::add_motion_signals(const plc::AXIS_REF& axis, std::string_view axis_name) {
  for (const Signal signal : kMotionSignals)
    add_signal(axis, axis_name, signal);
}

std::size_t Scope::add_variable(const double* source, std::string_view name,
                                std::string_view unit) {
  if (source == nullptr)
    throw std::invalid_argument("scope variable '" + std::string(name) + "' has no source");
  Channel channel;
  channel.info.name = std::string(name);
  channel.info.unit = std::string(unit);
  channel.variable = source;
  return add_channel(std::move(channel));
}

double Scope::sample(const Channel& channel) noexcept {
  if (channel.variable != nullptr) return *channel.variable;
  const plc::NCTOPLC_AXIS_REF& nc = channel.axis->NcToPlc;
  const plc::PLCTONC_AXIS_REF& plc_side = channel.axis->PlcToNc;
  switch (channel.info.signal) {
    case Signal::kSetPos:
      return nc.SetPos;
    case Signal::kActPos:
      return nc.ActPos;
    case Signal::kModuloSetPos:
      return nc.ModuloSetPos;
    case Signal::kModuloActPos:
      return nc.ModuloActPos;
    case Signal::kTargetPos:
      return nc.TargetPos;
    case Signal::kSetVelo:
      return nc.SetVelo;
    case Signal::kActVelo:
      return nc.ActVelo;
    case Signal::kTargetVelo:
      return nc.TargetVelo;
    case Signal::kSetAcc:
      return nc.SetAcc;
    case Signal::kActAcc:
      return nc.ActAcc;
    case Signal::kSetJerk:
      return nc.SetJerk;
    case Signal::kPosDiff:
      return nc.PosDiff;
    case Signal::kCompensationDistance:
      return nc.CompensationDistance;
    case Signal::kStateDWord:
      return nc.StateDWord;
    case Signal::kErrorCode:
      return nc.ErrorCode;
    case Signal::kAxisState:
      return nc.AxisState;
    case Signal::kCoupleState:
      return nc.CoupleState;
    case Signal::kCmdNo:
      return nc.CmdNo;
    case Signal::kCmdState:
      return nc.CmdState;
    case Signal::kOverride:
      return plc_side.Override;
    case Signal::kControlDWord:
      return plc_side.ControlDWord;
  }
  return 0.0;
}

bool Scope::record(double time) noexcept {
  if (size_ == capacity_) {
    ++dropped_;
    return false;
  }
  times_[size_] = time;
  for (Channel& channel : channels_)
    channel.values[size_] = sample(channel);
  ++size_;
  return true;
}

void Scope::clear() noexcept {
  size_ = 0;
  dropped_ = 0;
}

}  // namespace nc
