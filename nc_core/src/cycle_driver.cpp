#include "nc_core/cycle_driver.hpp"

#include <cmath>
#include <string>
#include <thread>
#include <utility>

#include "nc_core/config.hpp"

namespace nc {

CycleDriver::CycleDriver(Kernel& kernel) : kernel_(kernel) {}

void CycleDriver::add_task(std::string name, double period, std::function<void()> body) {
  const double cycle = kernel_.cycle_time();
  const double ratio = period / cycle;
  if (!std::isfinite(period) || !(period > 0.0)) {
    throw ConfigError("/tasks/" + name + "/period", "must be a finite number > 0",
                      std::to_string(period));
  }
  const double whole = std::round(ratio);
  if (whole < 1.0 || std::abs(ratio - whole) > 1e-9 * ratio) {
    throw ConfigError("/tasks/" + name + "/period",
                      "must be an integer multiple of the NC cycle time " + std::to_string(cycle),
                      std::to_string(period));
  }
  if (!body) throw ConfigError("/tasks/" + name + "/body", "must not be empty");
  tasks_.push_back(Task{std::move(name), static_cast<uint64_t>(whole), std::move(body)});
}

void CycleDriver::tick() {
  if (pacing_) {
    const auto slot = std::chrono::duration<double>(
        static_cast<double>(ticks_ - pacing_origin_tick_) * kernel_.cycle_time());
    std::this_thread::sleep_until(pacing_origin_ +
                                  std::chrono::duration_cast<std::chrono::nanoseconds>(slot));
  }
  // PLC before NC: the tasks due at this tick's time see the NcToPlc of the previous cycle, and
  // their commands are answered by this tick's NC cycle.
  for (Task& task : tasks_) {
    if (ticks_ % task.period_ticks == 0) task.body();
  }
  kernel_.cycle();
  ++ticks_;
}

uint64_t CycleDriver::ticks_for(double seconds, const char* what) const {
  if (!std::isfinite(seconds) || seconds < 0.0) {
    throw ConfigError(std::string("/") + what, "must be a finite number >= 0",
                      std::to_string(seconds));
  }
  // Whole cycles; a hair below a whole number (from the division) still counts as that number.
  return static_cast<uint64_t>(std::ceil(seconds / kernel_.cycle_time() - 1e-9));
}

void CycleDriver::run_for(double seconds) {
  const uint64_t n = ticks_for(seconds, "run_for");
  for (uint64_t i = 0; i < n; ++i)
    tick();
}

bool CycleDriver::run_until(const std::function<bool()>& done, double timeout) {
  const uint64_t n = ticks_for(timeout, "run_until");
  if (done()) return true;
  for (uint64_t i = 0; i < n; ++i) {
    tick();
    if (done()) return true;
  }
  return false;
}

void CycleDriver::set_realtime_pacing(bool on) noexcept {
  pacing_ = on;
  pacing_origin_ = std::chrono::steady_clock::now();
  pacing_origin_tick_ = ticks_;
}

}  // namespace nc
