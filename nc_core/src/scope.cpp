#include "nc_core/scope.hpp"

#include <array>
#include <charconv>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include <nlohmann/json.hpp>

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

// Shortest text that reads back to the same double; deterministic (no locale).
void put_number(std::ostream& out, double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out.write(buffer.data(), result.ptr - buffer.data());
}

std::string header_cell(std::string_view name, std::string_view unit) {
  std::string cell(name);
  if (!unit.empty()) {
    cell += " [";
    cell += unit;
    cell += ']';
  }
  return cell;
}

void ensure_parent(const std::filesystem::path& path) {
  const auto parent = path.parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(parent, ec);
  if (ec) {
    throw std::runtime_error("cannot create folder " + parent.string() + ": " + ec.message());
  }
}

}  // namespace

std::string_view signal_name(Signal signal) noexcept {
  return info_of(signal).name;
}
std::string_view signal_unit(Signal signal) noexcept {
  return info_of(signal).unit;
}

Scope::Scope(std::size_t capacity) : capacity_(capacity) {
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

std::size_t Scope::find(std::string_view name) const noexcept {
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    if (channels_[i].info.name == name) return i;
  }
  return channels_.size();
}

std::size_t Scope::find(std::string_view axis_name, Signal signal) const noexcept {
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    const ScopeChannelInfo& info = channels_[i].info;
    if (info.is_axis_signal && info.signal == signal && info.axis_name == axis_name) return i;
  }
  return channels_.size();
}

void Scope::write_csv(std::ostream& out) const {
  out << header_cell("time", "s");
  for (const Channel& channel : channels_) {
    out << ',' << header_cell(channel.info.name, channel.info.unit);
  }
  out << '\n';
  for (std::size_t row = 0; row < size_; ++row) {
    put_number(out, times_[row]);
    for (const Channel& channel : channels_) {
      out << ',';
      put_number(out, channel.values[row]);
    }
    out << '\n';
  }
}

nlohmann::json Scope::to_json() const {
  nlohmann::json doc;
  doc["sample_count"] = size_;
  doc["dropped"] = dropped_;
  doc["time"] =
      std::vector<double>(times_.begin(), times_.begin() + static_cast<std::ptrdiff_t>(size_));
  nlohmann::json channels = nlohmann::json::array();
  for (const Channel& channel : channels_) {
    nlohmann::json entry;
    entry["name"] = channel.info.name;
    entry["axis"] = channel.info.axis_name;
    entry["signal"] =
        channel.info.is_axis_signal ? std::string(signal_name(channel.info.signal)) : std::string();
    entry["unit"] = channel.info.unit;
    entry["values"] = std::vector<double>(
        channel.values.begin(), channel.values.begin() + static_cast<std::ptrdiff_t>(size_));
    channels.push_back(std::move(entry));
  }
  doc["channels"] = std::move(channels);
  return doc;
}

void Scope::write_csv(const std::filesystem::path& path) const {
  ensure_parent(path);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot open " + path.string() + " for writing");
  write_csv(out);
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void Scope::write_json(const std::filesystem::path& path) const {
  ensure_parent(path);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot open " + path.string() + " for writing");
  out << to_json().dump(1) << '\n';
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace nc
