// The kernel refusal tests' shared check (SPEC B1, B2, B5, B6, NC_ERROR_CODES.md): a bad command
// goes to the probe of kt::TwinKernels only, is answered kError with its specific code, and the
// two NC→PLC images stay bit-identical in the cycle of the refusal and for a number of cycles
// after it — a refused command disturbs nothing. Each test file keeps its own list of cases.
#pragma once

#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>
#include <string>

#include "kernel_harness.hpp"

namespace kt {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Vmax 2200, Vref 2100 (so "above Vref" and "above Vmax" are separate cases); software limits
// ±100000 enabled.
inline nc::AxisConfig refusal_axis() {
  nc::AxisConfig c = seed_axis();
  c.ref_velocity = 2100.0;
  c.sw_limit_min_enabled = true;
  c.sw_limit_max_enabled = true;
  c.sw_limit_min = -100000.0;
  c.sw_limit_max = 100000.0;
  return c;
}

// One bad command and the code it must be refused with.
struct Bad {
  std::string what;
  plc::Command command;
  plc::ErrorCode expected;
};

// `c` with one double field replaced: a good command spoiled in one input.
inline plc::Command with(plc::Command c, double plc::Command::*field, double value) {
  c.*field = value;
  return c;
}

// Posts `bad` to the probe only; checks the refusal and that the images stay the same for
// `cycles_after` cycles after it.
inline void expect_refused_without_effect(TwinKernels& t, const Bad& bad, int cycles_after = 50) {
  INFO(bad.what);
  const uint16_t n = t.probe.post(bad.command);
  t.cycles(1);
  const plc::CommandAnswer answer = t.probe.answer(n);
  CHECK(answer.state == plc::CommandState::kError);
  CHECK(answer.error_code == id(bad.expected));
  for (int i = 0; i < cycles_after; ++i) {
    REQUIRE(t.same());
    t.cycles(1);
  }
  REQUIRE(t.same());
}

}  // namespace kt
