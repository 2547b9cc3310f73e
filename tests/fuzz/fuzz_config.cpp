// fuzz_config (issue 16): the input bytes are JSON text for the kernel configuration (SPEC A5).
// Invariants: the text gives a kernel or an nc::ConfigError whose pointer is a JSON pointer into
// the document, never another exception, a crash or a hang; a configuration that was accepted
// survives to_json → parse unchanged, and its kernel runs 20 cycles with every axis enabled and
// moving with every published double finite.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "fail.hpp"
#include "fb/fb.hpp"
#include "nc_core/config.hpp"
#include "nc_core/kernel.hpp"

namespace {

void check_pointer(const nc::ConfigError& e) {
  const std::string& p = e.pointer();
  if (!p.empty() && p.front() != '/') fuzz::fail("ConfigError pointer is not a JSON pointer");
  if (std::string_view(e.what()).empty()) fuzz::fail("ConfigError without a message");
}

bool finite_image(const plc::NCTOPLC_AXIS_REF& n) {
  for (const double d :
       {n.ActPos, n.ModuloActPos, n.ActVelo, n.ActAcc, n.PosDiff, n.SetPos, n.ModuloSetPos,
        n.SetVelo, n.SetAcc, n.SetJerk, n.TargetPos, n.TargetVelo, n.CompensationDistance,
        n.CompensationLength, n.CompensationVelocityDiff}) {
    if (!std::isfinite(d)) return false;
  }
  return true;
}

// An accepted configuration runs: enable every axis and move it half its max velocity to 10 mm.
void run_kernel(nc::Kernel& kernel, const nc::KernelSetup& setup) {
  constexpr std::size_t kMaxAxes = 16;  // enough for the dictionary's documents; keeps it fast
  const std::size_t n = std::min(kernel.axis_count(), kMaxAxes);
  fb::MC_Power power[kMaxAxes];
  fb::MC_MoveAbsolute move[kMaxAxes];
  for (int cycle = 0; cycle < 20; ++cycle) {
    for (std::size_t i = 0; i < n; ++i) {
      plc::AXIS_REF& axis = kernel.axis(i);
      power[i].Enable = power[i].Enable_Positive = power[i].Enable_Negative = true;
      power[i](axis);
      move[i].Position = 10.0;
      move[i].Velocity = 0.5 * std::min(setup.axes[i].max_velocity, setup.axes[i].ref_velocity);
      move[i].Execute = cycle >= 2;
      move[i](axis);
    }
    kernel.cycle();
    for (std::size_t i = 0; i < n; ++i) {
      if (!finite_image(kernel.axis(i).NcToPlc)) fuzz::fail("accepted config: image not finite");
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);

  // The text reader: a setup or a ConfigError (syntax errors included).
  nc::KernelSetup setup;
  bool text_ok = false;
  try {
    setup = nc::parse_kernel_setup_text(text);
    text_ok = true;
  } catch (const nc::ConfigError& e) {
    check_pointer(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "parse_kernel_setup_text threw: %s\n", e.what());
    fuzz::fail("parse_kernel_setup_text threw something other than ConfigError");
  }
  if (text_ok) {
    try {
      if (!(nc::parse_kernel_setup(nc::to_json(setup)) == setup)) {
        fuzz::fail("to_json → parse_kernel_setup does not give the same setup");
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "round trip threw: %s\n", e.what());
      fuzz::fail("an accepted setup does not read back from its own JSON");
    }
  }

  // Kernel::from_json on the parsed document: a kernel or a ConfigError.
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  if (document.is_discarded()) return 0;
  try {
    nc::Kernel kernel = nc::Kernel::from_json(document);
    const nc::KernelSetup parsed = nc::parse_kernel_setup(document);
    if (parsed.axes.size() != kernel.axis_count()) fuzz::fail("kernel axis count differs");
    run_kernel(kernel, parsed);
  } catch (const nc::ConfigError& e) {
    check_pointer(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "Kernel::from_json threw: %s\n", e.what());
    fuzz::fail("Kernel::from_json threw something other than ConfigError");
  }
  return 0;
}
