// The parts of a Scenario shared by its reading (scenario.cpp), its run (play.cpp) and its
// outputs (output.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "nc_core/kernel.hpp"
#include "nc_core/scope.hpp"
#include "ncsdk_run/block_registry.hpp"
#include "ncsdk_run/scenario.hpp"
#include "plc_interface/axis_ref.hpp"

namespace scenario {

inline constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
// Distinct error codes noted per axis or block (storage reserved at set-up).
inline constexpr std::size_t kMaxErrorsNoted = 32;

struct AxisSlot {
  std::string name;
  plc::AXIS_REF* ref = nullptr;
  std::vector<std::pair<uint32_t, double>> errors;  // code, first time (distinct, in order)
};

struct BlockSlot {
  std::string name;
  const BlockType* type = nullptr;
  std::unique_ptr<Block> block;
  plc::AXIS_REF* first = nullptr;
  plc::AXIS_REF* second = nullptr;
  bool active = false;                              // declared by an action that has fired
  std::vector<const Port*> outputs;                 // traced, in port order
  std::size_t trace_begin = 0;                      // index of the first output in Impl::outputs
  const Port* error = nullptr;                      // the Error output, if any
  const Port* error_id = nullptr;                   // the ErrorID output, if any
  std::vector<std::pair<uint32_t, double>> errors;  // ErrorID, first time
};

// A block output compared with a value (a "when" or "stop_when" condition).
struct Condition {
  std::size_t block = kNone;
  const Port* port = nullptr;
  double value = 1.0;
};

// PlcToNc fields a timeline may write.
enum class PlcField : uint8_t {
  kOverride,
  kControlDWord,
  kEnable,
  kFeedEnablePlus,
  kFeedEnableMinus,
  kGearRatio1,
  kExtSetPos,
  kExtSetVelo,
  kExtSetAcc,
  kExtSetDirection,
};

struct Action {
  std::optional<double> t;  // s, not before
  double after = 0.0;       // s after the previous action fired
  std::optional<Condition> when;
  std::size_t block = kNone;
  bool declares = false;
  std::vector<std::pair<const Port*, double>> sets;
  std::size_t axis = kNone;
  std::vector<std::pair<PlcField, double>> writes;
};

enum class CheckKind : uint8_t { kAt, kAll, kEver, kChange, kNoErrors };

struct Check {
  std::string pointer;
  std::string description;
  CheckKind kind = CheckKind::kAt;
  std::size_t column = kNone;  // scope channel
  double t = 0.0;              // kAt; +inf = the end
  double from = 0.0;           // window (kAll, kEver, kNoErrors, kChange)
  double to = std::numeric_limits<double>::infinity();
  double value = 0.0;  // kAt, kChange
  double tolerance = 0.0;
  double min = -std::numeric_limits<double>::infinity();  // kAll, kEver
  double max = std::numeric_limits<double>::infinity();
  bool absolute = false;  // compare |value|
};

struct PlotSeriesSpec {
  std::size_t column = kNone;
  std::string label;
  std::string colour;
  double scale = 1.0;
  double width = 2.0;
};
struct PlotPanelSpec {
  std::string title;
  std::string unit;
  std::vector<PlotSeriesSpec> series;
};
struct PlotSpec {
  std::string name;
  std::string title;
  std::vector<PlotPanelSpec> panels;
};

struct Scenario::Impl {
  Impl(const nc::KernelConfig& config, std::size_t samples) : kernel(config), scope(samples) {}

  std::string axes_file;
  std::string timeline_file;
  nc::Kernel kernel;
  nc::Scope scope;
  std::string title;
  double plc_period = 0.0;
  double duration = 0.0;
  std::optional<Condition> stop_when;
  bool stop_when_actions_done = false;  // stop once every action has fired
  double stop_after = 0.0;
  std::string stop_pointer;
  std::vector<AxisSlot> axes;
  std::vector<BlockSlot> blocks;
  std::vector<double> outputs;  // traced block outputs; sized once, the scope reads them
  std::vector<Action> actions;
  std::vector<Check> checks;
  std::vector<std::string> extra_panels;  // axis fields drawn under the seed's four panels
  std::vector<PlotSpec> plots;
  std::string figure;

  // Run state.
  std::size_t next_action = 0;
  double armed_at = 0.0;  // s, when the previous action fired
  bool played = false;
  bool stop_reached = false;
  std::vector<CheckResult> results;

  double cycle_time() const noexcept { return kernel.cycle_time(); }
  double eps() const noexcept { return 1e-6 * kernel.cycle_time(); }
  bool holds(const Condition& c) const noexcept {
    const BlockSlot& b = blocks[c.block];
    return c.port->get(b.block->data()) == c.value;
  }
  void plc_cycle() noexcept;
  void trace_cycle() noexcept;
  void evaluate();
};

// "0x4550 (Following error too large)".
std::string error_text(uint32_t code);
// A number the way a summary shows it: up to 10 significant digits.
std::string number(double value);

}  // namespace scenario
