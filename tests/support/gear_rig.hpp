// Kernel tests of linear slave axes (SPEC C1, C3): a kernel of seed axes, all enabled, with the
// coupling commands posted straight into the slaves' mailboxes (no function blocks), and twin
// rigs for "a refused coupling command disturbs nothing" (every axis's NC→PLC image compared
// bit for bit).
//
// Test code: it allocates (names, vectors); never use it inside a counted no-allocation region
// except for post()/cycles(), which do not.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "kernel_harness.hpp"

namespace gr {

// MC_GearIn's command: the master's kernel index and the factor.
inline plc::Command gear_in(std::size_t master, double ratio) {
  plc::Command c;
  c.type = plc::CommandType::kGearIn;
  c.other_axis = static_cast<int32_t>(master);
  c.ratio = ratio;
  return c;
}

inline plc::Command gear_out() {
  plc::Command c;
  c.type = plc::CommandType::kGearOut;
  return c;
}

// `n` seed axes (names "A0" …), enabled, one cycle run. `encoder` marks axis indices that are
// encoder axes; or tune(i, config) changes axis i's configuration before it is added.
struct Rig {
  nc::Kernel kernel;
  std::vector<plc::AXIS_REF*> axes;

  explicit Rig(std::size_t n, const std::vector<std::size_t>& encoder = {})
      : Rig(n, [&encoder](std::size_t i, nc::AxisConfig& c) {
          for (std::size_t e : encoder) {
            if (e == i) c.kind = nc::AxisKind::kEncoder;
          }
        }) {}

  Rig(std::size_t n, const std::function<void(std::size_t, nc::AxisConfig&)>& tune) {
    for (std::size_t i = 0; i < n; ++i) {
      std::string name(1, 'A');
      name += std::to_string(i);
      nc::AxisConfig c = kt::seed_axis(name);
      tune(i, c);
      axes.push_back(&kernel.add_axis(c));
      kt::set_enables(*axes.back(), true);
    }
    kernel.cycle();
  }

  plc::AXIS_REF& at(std::size_t i) { return *axes[i]; }
  uint16_t post(std::size_t axis, const plc::Command& c) { return axes[axis]->Mailbox.post(c); }
  plc::CommandAnswer answer(std::size_t axis, uint16_t n) const {
    return axes[axis]->Mailbox.answer(n);
  }
  void cycles(int n) {
    for (int i = 0; i < n; ++i)
      kernel.cycle();
  }
  // Posts MC_GearIn to `slave`, runs one cycle; the answer.
  plc::CommandAnswer couple(std::size_t slave, std::size_t master, double ratio) {
    const uint16_t n = post(slave, gear_in(master, ratio));
    kernel.cycle();
    return answer(slave, n);
  }
  plc::CommandAnswer decouple(std::size_t slave) {
    const uint16_t n = post(slave, gear_out());
    kernel.cycle();
    return answer(slave, n);
  }
  // Moves `axis` to `target` at `velocity` and runs until the job is Done.
  void move_to(std::size_t axis, double target, double velocity = 2000.0) {
    const uint16_t n = post(axis, kt::move_absolute(target, velocity));
    for (int i = 0; i < 100000 && answer(axis, n).state != plc::CommandState::kDone; ++i)
      kernel.cycle();
  }
};

// One step of a determinism script: what the PLC does to a rig before NC cycle `cycle`.
template <class R>
struct Step {
  int cycle;
  std::function<void(R&)> act;
};

// Plays `script` (sorted by cycle) on two rigs built alike for `cycles` NC cycles, comparing
// every axis's NC→PLC image after each; `each(a)` sees rig `a` after every cycle. The first
// cycle whose images differ, or -1 when they never do.
template <class R, class Each>
int first_difference(const std::vector<Step<R>>& script, R& a, R& b, int cycles, Each&& each) {
  std::size_t next = 0;
  for (int cycle = 0; cycle < cycles; ++cycle) {
    for (; next < script.size() && script[next].cycle == cycle; ++next) {
      script[next].act(a);
      script[next].act(b);
    }
    a.kernel.cycle();
    b.kernel.cycle();
    for (std::size_t i = 0; i < a.axes.size(); ++i) {
      if (!kt::same_image(a.axes[i]->NcToPlc, b.axes[i]->NcToPlc)) return cycle;
    }
    each(a);
  }
  return -1;
}

// Two identical rigs: a command goes to the probe only; every axis's image must stay the same.
struct TwinRigs {
  Rig probe;
  Rig reference;
  TwinRigs(std::size_t n, const std::vector<std::size_t>& encoder)
      : probe(n, encoder), reference(n, encoder) {}
  void both(std::size_t axis, const plc::Command& c) {
    probe.post(axis, c);
    reference.post(axis, c);
  }
  void cycles(int n) {
    probe.cycles(n);
    reference.cycles(n);
  }
  bool same() const {
    for (std::size_t i = 0; i < probe.axes.size(); ++i) {
      if (!kt::same_image(probe.axes[i]->NcToPlc, reference.axes[i]->NcToPlc)) return false;
    }
    return true;
  }
};

}  // namespace gr
