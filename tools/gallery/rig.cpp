#include "rig.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>

#include "nc_core/svg_plot.hpp"
#include "plc_interface/error_code.hpp"

namespace gallery {
namespace {

constexpr double kCycle = 0.001;  // s, NC cycle and PLC task
// Rounding slack of the limit checks: relative, and the smallest step a printed plot could show.
constexpr double kRelativeSlack = 1e-9;

std::string hex(uint32_t code) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%X", static_cast<unsigned>(code));
  return text;
}

std::vector<double> channel(const nc::Scope& scope, nc::Signal signal) {
  const std::span<const double> values = scope.values(scope.find("Axis", signal));
  return {values.begin(), values.end()};
}

}  // namespace

std::string num(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

nc::AxisConfig seed_axis() {
  nc::AxisConfig config;
  config.name = "Axis";
  config.drive_model = nc::DriveModel::kFirstOrderLag;
  config.drive_time_constant = 0.001;
  config.drive_dead_time = 0.001;
  config.position_kv = 5.0;
  return config;
}

Rig::Rig(const nc::AxisConfig& config, double seconds)
    : kernel_(nc::KernelConfig{kCycle}),
      axis_(kernel_.add_axis(config)),
      driver_(kernel_),
      scope_(static_cast<std::size_t>(std::ceil(seconds / kCycle)) + 4),
      seconds_(seconds) {
  scope_.add_motion_signals(axis_, "Axis");
  scope_.add_signal(axis_, "Axis", nc::Signal::kOverride);
  scope_.add_signal(axis_, "Axis", nc::Signal::kModuloSetPos);
  // The scope runs first in a tick: it records what the NC published at the end of the
  // previous cycle, stamped with that time.
  driver_.add_task("Scope", kCycle, [this] { sample(); });
  driver_.add_task("PlcTask", kCycle, [this] {
    power_.Enable = true;
    power_.Enable_Positive = true;
    power_.Enable_Negative = true;
    power_(axis_);
    watch(power_, "MC_Power");
    if (program_) program_(*this);
  });
}

void Rig::run(const Program& program, const std::function<bool()>& done, double settle) {
  program_ = program;
  const double left = seconds_ - time() - settle;
  if (!driver_.run_until(done, left)) {
    expect(false, "did not finish within " + num(seconds_) + " s");
    return;
  }
  driver_.run_for(settle);
}

void Rig::run_for(const Program& program, double seconds) {
  program_ = program;
  driver_.run_for(std::min(seconds, seconds_ - time()));
}

void Rig::expect(bool ok, const std::string& what) {
  if (!ok) problems_.push_back(what);
}

void Rig::expect_near(double value, double wanted, double tolerance, const std::string& what) {
  expect(std::fabs(value - wanted) <= tolerance,
         what + ": " + num(value) + ", expected " + num(wanted) + " ± " + num(tolerance));
}

void Rig::note_block_error(const std::string& name, uint32_t id) {
  if (std::find(blocks_in_error_.begin(), blocks_in_error_.end(), name) != blocks_in_error_.end()) {
    return;
  }
  blocks_in_error_.push_back(name);
  problems_.push_back(name + " Error " + hex(id) + " (" + std::string(plc::error_text(id)) +
                      ") at " + num(time()) + " s");
}

void Rig::sample() noexcept {
  scope_.record(kernel_.time());
  if (axis_error_ == 0) axis_error_ = axis_.NcToPlc.ErrorCode;
}

void Rig::check_recording() {
  sample();
  if (axis_error_ != 0) {
    problems_.push_back("axis error " + hex(axis_error_) + " (" +
                        std::string(plc::error_text(axis_error_)) + ")");
  }
  if (scope_.dropped() != 0) problems_.push_back("the scope dropped samples");
  const std::vector<double> velo = channel(scope_, nc::Signal::kSetVelo);
  const std::vector<double> acc = channel(scope_, nc::Signal::kSetAcc);
  const std::span<const double> t = scope_.time();
  double max_velo = 0.0;
  double max_acc = 0.0;
  double max_jerk = 0.0;
  for (std::size_t i = 0; i < velo.size(); ++i) {
    max_velo = std::max(max_velo, std::fabs(velo[i]));
    max_acc = std::max(max_acc, std::fabs(acc[i]));
    if (i > 0 && t[i] > t[i - 1]) {
      max_jerk = std::max(max_jerk, std::fabs(acc[i] - acc[i - 1]) / (t[i] - t[i - 1]));
    }
  }
  auto within = [&](double value, double limit, const char* what) {
    if (limit > 0.0 && value > limit * (1.0 + kRelativeSlack) + kRelativeSlack) {
      problems_.push_back(std::string(what) + " " + num(value) + " above its limit " + num(limit));
    }
  };
  within(max_velo, limits_.velocity, "|set velocity|");
  within(max_acc, std::max(limits_.acceleration, limits_.deceleration), "|set acceleration|");
  within(max_jerk, limits_.jerk, "|set jerk| (from the set acceleration)");
}

Figure Rig::write(const std::filesystem::path& out, const std::string& name,
                  const std::string& title, Extra extra) {
  check_recording();
  std::vector<nc::PlotPanel> panels = nc::motion_panels(scope_, "Axis");
  std::vector<double> override_percent;
  std::vector<double> modulo;
  if ((static_cast<uint8_t>(extra) & static_cast<uint8_t>(Extra::kOverride)) != 0) {
    override_percent = channel(scope_, nc::Signal::kOverride);
    for (double& o : override_percent)
      o /= 10'000.0;
    panels.push_back({"panel-override",
                      "Override",
                      "%",
                      {{"PlcToNc.Override", "#6a3d9a", override_percent, 2.0}}});
  }
  if ((static_cast<uint8_t>(extra) & static_cast<uint8_t>(Extra::kModuloSetPos)) != 0) {
    modulo = channel(scope_, nc::Signal::kModuloSetPos);
    panels.push_back(
        {"panel-modulo",
         "Modulo set position",
         "mm",
         {{"modulo set position", std::string(nc::plot_colour::kSetPosition), modulo, 2.0}}});
  }
  Figure figure;
  figure.name = name;
  figure.title = title;
  figure.file = out / (name + ".svg");
  nc::write_svg(figure.file, nc::svg_plot(scope_.time(), panels, {title, 1000, 150}));
  figure.problems = problems_;
  return figure;
}

}  // namespace gallery
