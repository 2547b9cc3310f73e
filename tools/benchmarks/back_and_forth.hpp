// The axes and the motion of the kernel benchmarks: kernel_axis(i) is axis i's configuration;
// axis i moves back and forth between 0 and 300 + i mm at 1500 mm/s, the next MC_MoveAbsolute
// command posted straight into its mailbox as soon as the last one is Done (a minimal PLC).
// Benchmark set-up allocates; step() does not.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "nc_core/axis_config.hpp"
#include "plc_interface/axis_ref.hpp"
#include "plc_interface/command.hpp"

namespace bench {

// Axis i of the kernel benchmarks: every odd one with the first-order lag drive and a dead time.
inline nc::AxisConfig kernel_axis(std::size_t i) {
  nc::AxisConfig c;
  c.name = "axis" + std::to_string(i);
  if (i % 2 == 1) {
    c.drive_model = nc::DriveModel::kFirstOrderLag;
    c.drive_time_constant = 0.002;
    c.drive_dead_time = 0.002;
  }
  return c;
}

class BackAndForth {
 public:
  explicit BackAndForth(std::size_t axes) : numbers_(axes, 0), forward_(axes, true) {}

  // Called once per cycle for axis `i` before Kernel::cycle().
  void step(plc::AXIS_REF& axis, std::size_t i) noexcept {
    if (numbers_[i] != 0 && axis.Mailbox.answer(numbers_[i]).state != plc::CommandState::kDone) {
      return;
    }
    plc::Command c;
    c.type = plc::CommandType::kMoveAbsolute;
    c.position = forward_[i] ? 300.0 + static_cast<double>(i) : 0.0;
    c.velocity = 1500.0;
    numbers_[i] = axis.Mailbox.post(c);
    forward_[i] = !forward_[i];
  }

 private:
  std::vector<uint16_t> numbers_;
  std::vector<bool> forward_;
};

}  // namespace bench
