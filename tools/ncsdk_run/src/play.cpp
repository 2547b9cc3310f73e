// Playing a scenario: the PLC task, the trace task and the checks on the recorded trace.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "nc_core/cycle_driver.hpp"
#include "plc_interface/error_code.hpp"
#include "scenario_impl.hpp"

namespace scenario {

std::string error_text(uint32_t code) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%X", static_cast<unsigned>(code));
  return std::string(hex) + " (" + std::string(plc::error_text(code)) + ")";
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

namespace {

constexpr uint32_t kEnableBit = 1U << 0;
constexpr uint32_t kFeedPlusBit = 1U << 1;
constexpr uint32_t kFeedMinusBit = 1U << 2;

void set_bit(uint32_t& word, uint32_t bit, double on) noexcept {
  word = on != 0.0 ? (word | bit) : (word & ~bit);
}

void write_field(plc::PLCTONC_AXIS_REF& out, PlcField field, double v) noexcept {
  switch (field) {
    case PlcField::kOverride:
      out.Override = static_cast<uint32_t>(v);
      break;
    case PlcField::kControlDWord:
      out.ControlDWord = static_cast<uint32_t>(v);
      break;
    case PlcField::kEnable:
      set_bit(out.ControlDWord, kEnableBit, v);
      break;
    case PlcField::kFeedEnablePlus:
      set_bit(out.ControlDWord, kFeedPlusBit, v);
      break;
    case PlcField::kFeedEnableMinus:
      set_bit(out.ControlDWord, kFeedMinusBit, v);
      break;
    case PlcField::kGearRatio1:
      out.GearRatio1 = v;
      break;
    case PlcField::kExtSetPos:
      out.ExtSetPos = v;
      break;
    case PlcField::kExtSetVelo:
      out.ExtSetVelo = v;
      break;
    case PlcField::kExtSetAcc:
      out.ExtSetAcc = v;
      break;
    case PlcField::kExtSetDirection:
      out.ExtSetDirection = static_cast<int32_t>(v);
      break;
  }
}

// Remembers a code the first time it shows (bounded: a run shows a handful of errors).
void note(std::vector<std::pair<uint32_t, double>>& seen, uint32_t code, double t) {
  if (code == 0 || seen.size() >= kMaxErrorsNoted) return;
  if (!seen.empty() && seen.back().first == code) return;
  for (const auto& s : seen) {
    if (s.first == code) return;
  }
  seen.emplace_back(code, t);
}

}  // namespace

void Scenario::Impl::plc_cycle() noexcept {
  const double now = kernel.time();
  while (next_action < actions.size()) {
    const Action& a = actions[next_action];
    if (a.t && now < *a.t - eps()) break;
    if (now < armed_at + a.after - eps()) break;
    if (a.when && !holds(*a.when)) break;
    if (a.block != kNone) {
      BlockSlot& b = blocks[a.block];
      for (const auto& [port, value] : a.sets)
        port->set(b.block->data(), value);
      if (a.declares) b.active = true;
    } else if (a.axis != kNone) {
      for (const auto& [field, value] : a.writes)
        write_field(axes[a.axis].ref->PlcToNc, field, value);
    }
    armed_at = now;
    ++next_action;
  }
  for (BlockSlot& b : blocks) {
    if (b.active) b.block->call(*b.first, *b.second);
  }
}

void Scenario::Impl::trace_cycle() noexcept {
  const double now = kernel.time();
  for (BlockSlot& b : blocks) {
    const void* data = b.block->data();
    for (std::size_t k = 0; k < b.outputs.size(); ++k)
      outputs[b.trace_begin + k] = b.outputs[k]->get(data);
    if (b.error != nullptr && b.error->get(data) != 0.0) {
      const double id = b.error_id != nullptr ? b.error_id->get(data) : 0.0;
      note(b.errors, id != 0.0 ? static_cast<uint32_t>(id) : 1U, now);
    }
  }
  for (AxisSlot& a : axes)
    note(a.errors, a.ref->NcToPlc.ErrorCode, now);
  scope.record(now);
}

void Scenario::play() {
  Impl& s = *impl_;
  if (s.played) throw std::logic_error("a scenario plays once");
  nc::CycleDriver driver(s.kernel);
  driver.add_task("PlcTask", s.plc_period, [&s] { s.plc_cycle(); });
  driver.add_task("Trace", s.cycle_time(), [&s] { s.trace_cycle(); });
  // The run covers t = 0 … duration (duration / T + 1 ticks), or ends `after` seconds after the
  // stop condition first holds.
  const double timeout = s.duration + s.cycle_time();
  if (s.stop_when || s.stop_when_actions_done) {
    double stop_at = -1.0;
    s.stop_reached = driver.run_until(
        [&s, &stop_at] {
          const bool holds =
              s.stop_when ? s.holds(*s.stop_when) : s.next_action == s.actions.size();
          if (stop_at < 0.0 && holds) stop_at = s.kernel.time() + s.stop_after;
          return stop_at >= 0.0 && s.kernel.time() >= stop_at - s.eps();
        },
        timeout);
  } else {
    driver.run_for(timeout);
  }
  s.played = true;
  s.evaluate();
}

namespace {

// The index of the sample nearest to t (t = +inf: the last), or kNone past the recording.
std::size_t row_at(std::span<const double> time, double t, double eps) {
  if (time.empty()) return kNone;
  if (std::isinf(t)) return time.size() - 1;
  if (t > time.back() + eps) return kNone;
  const auto it = std::lower_bound(time.begin(), time.end(), t - eps);
  return static_cast<std::size_t>(it - time.begin());
}

}  // namespace

void Scenario::Impl::evaluate() {
  results.clear();
  const std::span<const double> time = scope.time();
  const double end = time.empty() ? 0.0 : time.back();
  if (stop_when || stop_when_actions_done) {
    CheckResult r{stop_pointer,
                  "the stop condition holds within the duration (" + number(duration) + " s)",
                  stop_reached, stop_reached ? "reached" : "not reached by " + number(end) + " s"};
    results.push_back(r);
  }
  for (const Check& c : checks) {
    CheckResult r{c.pointer, c.description, false, {}};
    if (c.kind == CheckKind::kNoErrors) {
      r.passed = true;
      auto in_window = [&](double t) { return t >= c.from - eps() && t <= c.to + eps(); };
      for (const AxisSlot& a : axes) {
        for (const auto& [code, t] : a.errors) {
          if (!in_window(t) || !r.passed) continue;
          r.passed = false;
          r.detail = a.name + ": ErrorCode " + error_text(code) + " at " + number(t) + " s";
        }
      }
      for (const BlockSlot& b : blocks) {
        for (const auto& [code, t] : b.errors) {
          if (!in_window(t) || !r.passed) continue;
          r.passed = false;
          r.detail = b.name + " (" + std::string(b.type->name) + "): Error, ErrorID " +
                     error_text(code) + " at " + number(t) + " s";
        }
      }
      if (r.passed) r.detail = "none";
      results.push_back(r);
      continue;
    }
    const std::span<const double> values = scope.values(c.column);
    switch (c.kind) {
      case CheckKind::kAt: {
        const std::size_t i = row_at(time, c.t, eps());
        if (i == kNone) {
          r.detail = "the run ended at " + number(end) + " s";
          break;
        }
        r.passed = std::fabs(values[i] - c.value) <= c.tolerance;
        r.detail = "was " + number(values[i]) + " at " + number(time[i]) + " s";
        break;
      }
      case CheckKind::kChange: {
        const std::size_t i = row_at(time, c.from, eps());
        const std::size_t j = row_at(time, c.to, eps());
        if (i == kNone || j == kNone) {
          r.detail = "the run ended at " + number(end) + " s";
          break;
        }
        const double change = values[j] - values[i];
        r.passed = std::fabs(change - c.value) <= c.tolerance;
        r.detail = "changed by " + number(change) + " (" + number(values[i]) + " at " +
                   number(time[i]) + " s, " + number(values[j]) + " at " + number(time[j]) + " s)";
        break;
      }
      case CheckKind::kAll:
      case CheckKind::kEver: {
        const bool ever = c.kind == CheckKind::kEver;
        std::size_t samples = 0;
        std::size_t first_bad = kNone;
        std::size_t first_good = kNone;
        double lo = INFINITY, hi = -INFINITY;
        for (std::size_t i = 0; i < time.size(); ++i) {
          if (time[i] < c.from - eps() || time[i] > c.to + eps()) continue;
          ++samples;
          const double v = c.absolute ? std::fabs(values[i]) : values[i];
          lo = std::min(lo, v);
          hi = std::max(hi, v);
          const bool inside = v >= c.min && v <= c.max;
          if (!inside && first_bad == kNone) first_bad = i;
          if (inside && first_good == kNone) first_good = i;
        }
        if (samples == 0) {
          r.detail = "no sample in the window (the run ended at " + number(end) + " s)";
          break;
        }
        r.passed = ever ? first_good != kNone : first_bad == kNone;
        r.detail = "ranged " + number(lo) + " … " + number(hi) + " over " +
                   std::to_string(samples) + " samples";
        if (!ever && first_bad != kNone) {
          r.detail +=
              "; first outside at " + number(time[first_bad]) + " s: " + number(values[first_bad]);
        }
        if (ever && first_good != kNone)
          r.detail += "; first at " + number(time[first_good]) + " s";
        break;
      }
      case CheckKind::kNoErrors:
        break;
    }
    results.push_back(r);
  }
}

}  // namespace scenario
