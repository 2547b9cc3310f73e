// The cycle driver: runs PLC tasks and the NC kernel in deterministic simulated time (SPEC A2).
//
// Time is an integer tick counter; one tick is one NC cycle and time() = ticks · T (never a
// floating running sum), so two runs with the same inputs are bit-identical. A PLC task has a
// period that is an integer multiple of the NC cycle and runs at t = 0, P, 2P, …. In a tick the
// PLC tasks due at the tick's time run first, in the order they were added, and then
// Kernel::cycle() (ARCHITECTURE "One tick": PLC reads NcToPlc, calls blocks, writes PlcToNc and
// posts commands; the NC answers them in the same tick).
//
// Wall-clock pacing (set_realtime_pacing) makes each tick wait until its real-time slot; it is
// off by default and never changes the simulated results.
//
// add_task, run_for and run_until are set-up/driver functions (they may throw ConfigError on bad
// arguments); tick() itself allocates nothing — task bodies are the user's.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "nc_core/kernel.hpp"

namespace nc {

class CycleDriver {
 public:
  explicit CycleDriver(Kernel& kernel);

  // `period` in s: a positive integer multiple of the NC cycle (within 1e-9 relative), else
  // ConfigError. An empty body is a ConfigError too.
  void add_task(std::string name, double period, std::function<void()> body);

  // One tick: the PLC tasks due now, then one NC cycle; time advances by one NC cycle.
  void tick();
  // Ticks for `seconds` (rounded to whole NC cycles; >= 0 and finite, else ConfigError).
  void run_for(double seconds);
  // Ticks until done() is true (checked before the first tick and after every tick) or until
  // `timeout` seconds have passed; returns done()'s last value.
  bool run_until(const std::function<bool()>& done, double timeout);

  void set_realtime_pacing(bool on) noexcept;
  bool realtime_pacing() const noexcept { return pacing_; }

  uint64_t ticks() const noexcept { return ticks_; }
  double time() const noexcept { return static_cast<double>(ticks_) * kernel_.cycle_time(); }
  std::size_t task_count() const noexcept { return tasks_.size(); }
  Kernel& kernel() noexcept { return kernel_; }

 private:
  struct Task {
    std::string name;
    uint64_t period_ticks;
    std::function<void()> body;
  };

  uint64_t ticks_for(double seconds, const char* what) const;

  Kernel& kernel_;
  std::vector<Task> tasks_;
  uint64_t ticks_ = 0;
  bool pacing_ = false;
  std::chrono::steady_clock::time_point pacing_origin_{};
  uint64_t pacing_origin_tick_ = 0;
};

}  // namespace nc
