#include "nc_core/scope.hpp"

#include <array>
#include <charconv>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace nc::detail {
namespace {

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

std::size_t ScopeRecording::find(std::string_view name) const noexcept {
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    if (channels_[i].info.name == name) return i;
  }
  return channels_.size();
}

std::size_t ScopeRecording::find(std::string_view axis_name, Signal signal) const noexcept {
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    const ScopeChannelInfo& info = channels_[i].info;
    if (info.is_axis_signal && info.signal == signal && info.axis_name == axis_name) return i;
  }
  return channels_.size();
}

void ScopeRecording::write_csv(std::ostream& out) const {
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

nlohmann::json ScopeRecording::to_json() const {
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

void ScopeRecording::write_csv(const std::filesystem::path& path) const {
  ensure_parent(path);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot open " + path.string() + " for writing");
  write_csv(out);
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

void ScopeRecording::write_json(const std::filesystem::path& path) const {
  ensure_parent(path);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot open " + path.string() + " for writing");
  out << to_json().dump(1) << '\n';
  out.flush();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace nc::detail
