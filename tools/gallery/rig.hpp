// The gallery's test rig: one simulated axis, its PLC program and a scope, for one figure.
//
// A Rig owns a kernel (1 ms NC cycle) with one axis, a cycle driver with a scope task and a PLC
// task (both every NC cycle, so events happen on the millisecond the scenario names), and an
// MC_Power that enables the axis at 100 % override before the scenario's program runs. The
// scenario's program is ordinary PLC code over fb blocks; the Rig records SetPos/ActPos,
// SetVelo/ActVelo, SetAcc/ActAcc, PosDiff, Override and ModuloSetPos every cycle, checks
// what every figure must show (no block or axis error, the limits kept at every cycle) and
// writes the SVG with the seed's colours (seed 000 §2.1 "Notes on the figures").
// Set-up and after-run code: it allocates and may throw.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "fb/mc_power.hpp"
#include "nc_core/axis_config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "nc_core/scope.hpp"
#include "plc_interface/axis_ref.hpp"

namespace gallery {

// One figure of the gallery and what went wrong while it was made (empty: it shows what its
// title says).
struct Figure {
  std::string name;  // file stem: <out>/<name>.svg
  std::string title;
  std::filesystem::path file;
  std::vector<std::string> problems;
  bool ok() const { return problems.empty(); }
};

// Extra panels under the seed's four.
enum class Extra : uint8_t {
  kNone = 0,
  kOverride = 1,      // PlcToNc.Override in %
  kModuloSetPos = 2,  // NcToPlc.ModuloSetPos
};

// The limits every cycle must keep (path-relative, seed 000 §2.1): |v| ≤ velocity, |a| ≤
// max(acceleration, deceleration), |da/dt| ≤ jerk. 0 leaves a limit unchecked.
struct CheckedLimits {
  double velocity = 0.0;
  double acceleration = 0.0;
  double deceleration = 0.0;
  double jerk = 0.0;
};

// The axis of the seed's figures: A+ = A- = 5000 mm/s², J = 50000 mm/s³, Vmax 2200 mm/s, on a
// drive that lags a little (first order 1 ms, dead time 1 ms; Kv 5 /s) so that the actual values
// and the following error look like a real axis's.
nc::AxisConfig seed_axis();

// A number as a title shows it: the shortest of up to 6 significant digits ("5000", "0.75").
std::string num(double value);

class Rig {
 public:
  using Program = std::function<void(Rig&)>;

  // Set-up: `seconds` is the longest the figure may run (the scope's storage).
  Rig(const nc::AxisConfig& config, double seconds);
  Rig(const Rig&) = delete;
  Rig& operator=(const Rig&) = delete;

  plc::AXIS_REF& axis() noexcept { return axis_; }
  const plc::AXIS_REF& axis() const noexcept { return axis_; }
  // s, time of the tick being run (the NcToPlc the program reads was published then).
  double time() const noexcept { return kernel_.time(); }
  fb::MC_Power& power() noexcept { return power_; }
  // The set values rest (set velocity and acceleration 0).
  bool at_rest() const noexcept {
    return axis_.NcToPlc.SetVelo == 0.0 && axis_.NcToPlc.SetAcc == 0.0;
  }

  // Runs `program` every PLC cycle until `done()` holds (then `settle` seconds longer) or until
  // the rig's time is up; a timeout is a problem of the figure.
  void run(const Program& program, const std::function<bool()>& done, double settle = 0.3);
  // Runs `program` for exactly `seconds`.
  void run_for(const Program& program, double seconds);

  // A block's Error during the run is a problem of the figure (noted once per block).
  template <class Block>
  void watch(const Block& block, const std::string& name) {
    if (block.Error) note_block_error(name, block.ErrorID);
  }
  void expect(bool ok, const std::string& what);
  void expect_near(double value, double wanted, double tolerance, const std::string& what);
  void check_limits(const CheckedLimits& limits) { limits_ = limits; }

  // After-run: checks the limits over the recording, then writes <out>/<name>.svg.
  Figure write(const std::filesystem::path& out, const std::string& name, const std::string& title,
               Extra extra = Extra::kNone);

 private:
  void note_block_error(const std::string& name, uint32_t id);
  void sample() noexcept;
  void check_recording();

  nc::Kernel kernel_;
  plc::AXIS_REF& axis_;
  nc::CycleDriver driver_;
  nc::Scope scope_;
  double seconds_;
  fb::MC_Power power_;
  Program program_;
  CheckedLimits limits_;
  std::vector<std::string> problems_;
  std::vector<std::string> blocks_in_error_;
  uint32_t axis_error_ = 0;
};

}  // namespace gallery
