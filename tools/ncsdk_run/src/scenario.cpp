// Reading and checking a scenario: the axes document, the timeline, the checks and the plots.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "nc_core/config.hpp"
#include "scenario_impl.hpp"

namespace scenario {

using nlohmann::json;

InputError::InputError(std::string file, std::string pointer, std::string rule)
    : std::runtime_error(file + ":" + (pointer.empty() ? std::string("(document)") : pointer) +
                         ": " + rule),
      file_(std::move(file)),
      pointer_(std::move(pointer)),
      rule_(std::move(rule)) {}

json read_json_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  try {
    return json::parse(text.str());
  } catch (const json::parse_error& e) {
    throw InputError(path.string(), "", std::string("malformed JSON: ") + e.what());
  }
}

namespace {

constexpr std::size_t kMaxSamples = 5'000'000;  // NC cycles of one run (the trace's memory)

// "a, b, c": the names an error message offers.
void append_name(std::string& list, std::string_view name) {
  if (!list.empty()) list += ", ";
  list += name;
}

// The reader of the timeline document: every rule it enforces names the JSON pointer.
class Reader {
 public:
  Reader(Scenario::Impl& s, const std::string& file) : s_(s), file_(file) {}

  [[noreturn]] void bad(const std::string& pointer, const std::string& rule) const {
    throw InputError(file_, pointer, rule);
  }

  void keys(const json& object, const std::string& pointer,
            std::initializer_list<std::string_view> known) const {
    if (!object.is_object()) bad(pointer, "must be an object");
    for (const auto& item : object.items()) {
      if (std::find(known.begin(), known.end(), item.key()) == known.end()) {
        std::string list;
        for (const std::string_view k : known)
          append_name(list, k);
        bad(pointer + "/" + item.key(), "unknown key (known here: " + list + ")");
      }
    }
  }

  double real(const json& value, const std::string& pointer) const {
    if (!value.is_number()) bad(pointer, "must be a number, got " + value.dump());
    const double v = value.get<double>();
    if (!std::isfinite(v)) bad(pointer, "must be finite");
    return v;
  }
  double time(const json& value, const std::string& pointer) const {
    const double t = real(value, pointer);
    if (t < 0.0) bad(pointer, "a time must be >= 0 s, got " + value.dump());
    return t;
  }
  // object[key], which must be a non-empty array.
  const json& items(const json& object, const char* key, const std::string& pointer) const {
    if (!object.contains(key) || !object[key].is_array() || object[key].empty()) {
      bad(pointer, "required: a non-empty array");
    }
    return object[key];
  }
  std::string text(const json& value, const std::string& pointer) const {
    if (!value.is_string()) bad(pointer, "must be a string, got " + value.dump());
    return value.get<std::string>();
  }

  std::size_t axis(const json& value, const std::string& pointer) const {
    const std::string name = text(value, pointer);
    for (std::size_t i = 0; i < s_.axes.size(); ++i) {
      if (s_.axes[i].name == name) return i;
    }
    std::string list;
    for (const AxisSlot& a : s_.axes)
      append_name(list, a.name);
    bad(pointer, "no axis '" + name + "' in " + s_.axes_file + " (axes: " + list + ")");
  }

  std::size_t block(const json& value, const std::string& pointer) const {
    const std::string name = text(value, pointer);
    for (std::size_t i = 0; i < s_.blocks.size(); ++i) {
      if (s_.blocks[i].name == name) return i;
    }
    bad(pointer, "no block '" + name +
                     "' declared before (the first action naming a block gives its \"type\")");
  }

  // A port value from JSON by the port's type.
  double port_value(const Port& port, const json& value, const std::string& pointer) const {
    switch (port.type) {
      case ValueType::kBool:
        if (!value.is_boolean()) {
          bad(pointer, std::string(port.name) + " is a BOOL: true or false, got " + value.dump());
        }
        return value.get<bool>() ? 1.0 : 0.0;
      case ValueType::kReal:
        if (!value.is_number()) {
          bad(pointer, std::string(port.name) + " is a REAL: a number, got " + value.dump());
        }
        return real(value, pointer);
      case ValueType::kInteger: {
        if (!value.is_number_integer()) {
          bad(pointer, std::string(port.name) + " is an integer, got " + value.dump());
        }
        const double v = value.get<double>();
        if (v < -2147483648.0 || v > 4294967295.0) bad(pointer, "out of range");
        return v;
      }
      case ValueType::kDirection:
      case ValueType::kBufferMode:
      case ValueType::kPositionType: {
        if (value.is_number_integer()) {
          const auto v = value.get<int64_t>();
          if (v < -2147483648LL || v > 2147483647LL) bad(pointer, "out of range");
          return static_cast<double>(v);  // the block itself refuses an undefined value
        }
        if (value.is_string()) {
          const int v = enum_value(port.type, value.get<std::string>());
          if (v >= 0) return v;
        }
        std::string list;
        for (int v = 0; v < 256; ++v) {
          const std::string_view n = enum_value_name(port.type, v);
          if (!n.empty()) append_name(list, n);
        }
        bad(pointer, std::string(port.name) + " takes one of " + list + " (or its number), got " +
                         value.dump());
      }
    }
    bad(pointer, "unsupported type");
  }

  // {"block": …, "output": …, "value": …}
  Condition condition(const json& c, const std::string& pointer,
                      std::initializer_list<std::string_view> known) const {
    keys(c, pointer, known);
    if (!c.contains("block")) bad(pointer + "/block", "required");
    if (!c.contains("output")) bad(pointer + "/output", "required");
    Condition out;
    out.block = block(c["block"], pointer + "/block");
    out.port = output_port(out.block, c["output"], pointer + "/output");
    out.value = c.contains("value") ? port_value(*out.port, c["value"], pointer + "/value") : 1.0;
    return out;
  }

  const Port* output_port(std::size_t b, const json& name_json, const std::string& pointer) const {
    const std::string name = text(name_json, pointer);
    const BlockType& type = *s_.blocks[b].type;
    const Port* p = type.find(name);
    if (p == nullptr || p->kind != PortKind::kOutput) {
      bad(pointer, "'" + name + "' is not an output of " + std::string(type.name) +
                       " (outputs: " + ports(type, PortKind::kOutput) + ")");
    }
    return p;
  }

  static std::string ports(const BlockType& type, PortKind kind) {
    std::string list;
    for (const Port& p : type.ports) {
      if (p.kind == kind) append_name(list, p.name);
    }
    return list;
  }

  // A scope column: {"axis", "field"} or {"block", "output"}.
  std::size_t column(const json& c, const std::string& pointer, std::string& name) const {
    if (c.contains("axis")) {
      const std::size_t a = axis(c["axis"], pointer + "/axis");
      if (!c.contains("field")) bad(pointer + "/field", "required with \"axis\"");
      const std::string field = text(c["field"], pointer + "/field");
      name = s_.axes[a].name + "." + field;
      const std::size_t index = s_.scope.find(name);
      if (index == s_.scope.channel_count()) {
        std::string list;
        for (std::size_t i = 0; i < s_.scope.channel_count(); ++i) {
          const nc::ScopeChannelInfo& info = s_.scope.channel(i);
          if (info.axis_name == s_.axes[a].name || info.name.rfind(s_.axes[a].name + ".", 0) == 0) {
            append_name(list, info.name.substr(s_.axes[a].name.size() + 1));
          }
        }
        bad(pointer + "/field", "unknown axis field '" + field + "' (fields: " + list + ")");
      }
      return index;
    }
    if (c.contains("block")) {
      const std::size_t b = block(c["block"], pointer + "/block");
      if (!c.contains("output")) bad(pointer + "/output", "required with \"block\"");
      const Port* p = output_port(b, c["output"], pointer + "/output");
      name = s_.blocks[b].name + "." + std::string(p->name);
      return s_.scope.find(name);
    }
    bad(pointer, "needs \"axis\" and \"field\", or \"block\" and \"output\"");
  }

 private:
  Scenario::Impl& s_;
  const std::string& file_;
};

bool valid_name(const std::string& name) {
  return !name.empty() && name.find_first_of(".,\"\r\n") == std::string::npos;
}

struct FieldName {
  std::string_view name;
  PlcField field;
  bool boolean;
};
constexpr FieldName kPlcFields[] = {
    {"Override", PlcField::kOverride, false},
    {"ControlDWord", PlcField::kControlDWord, false},
    {"Enable", PlcField::kEnable, true},
    {"FeedEnablePlus", PlcField::kFeedEnablePlus, true},
    {"FeedEnableMinus", PlcField::kFeedEnableMinus, true},
    {"GearRatio1", PlcField::kGearRatio1, false},
    {"ExtSetPos", PlcField::kExtSetPos, false},
    {"ExtSetVelo", PlcField::kExtSetVelo, false},
    {"ExtSetAcc", PlcField::kExtSetAcc, false},
    {"ExtSetDirection", PlcField::kExtSetDirection, false},
};

void read_action(Reader& r, Scenario::Impl& s, const json& a, const std::string& p,
                 std::optional<double>& last_t) {
  r.keys(a, p, {"t", "after", "when", "block", "type", "axis", "master", "slave", "set", "write"});
  Action action;
  if (a.contains("t")) {
    action.t = r.time(a["t"], p + "/t");
    if (last_t && *action.t < *last_t) {
      r.bad(p + "/t", "time going backwards: " + number(*action.t) +
                          " s is before the previous action's " + number(*last_t) + " s");
    }
    last_t = action.t;
  }
  if (a.contains("after")) action.after = r.time(a["after"], p + "/after");
  if (a.contains("when")) {
    action.when = r.condition(a["when"], p + "/when", {"block", "output", "value"});
  }
  if (a.contains("block")) {
    const std::string name = r.text(a["block"], p + "/block");
    auto it = std::find_if(s.blocks.begin(), s.blocks.end(),
                           [&](const BlockSlot& b) { return b.name == name; });
    if (a.contains("type")) {
      const std::string type_name = r.text(a["type"], p + "/type");
      const BlockType* type = find_block_type(type_name);
      if (type == nullptr) {
        std::string list;
        for (const BlockType& t : block_types())
          append_name(list, t.name);
        r.bad(p + "/type", "unknown block type '" + type_name + "' (types: " + list + ")");
      }
      if (it != s.blocks.end()) r.bad(p + "/type", "block '" + name + "' was declared before");
      if (!valid_name(name)) {
        r.bad(p + "/block", "a block name is not empty and has no . , \" or line break");
      }
      BlockSlot slot;
      slot.errors.reserve(kMaxErrorsNoted);
      slot.name = name;
      slot.type = type;
      slot.block = type->make();
      std::vector<plc::AXIS_REF*> refs;
      for (const std::string_view key : type->axes) {
        const std::string k(key);
        std::string pointer = p + "/";
        pointer += k;
        if (!a.contains(k)) r.bad(pointer, std::string(type->name) + " needs \"" + k + "\"");
        refs.push_back(s.axes[r.axis(a[k], pointer)].ref);
      }
      for (const char* key : {"axis", "master", "slave"}) {
        if (a.contains(key) &&
            std::find(type->axes.begin(), type->axes.end(), key) == type->axes.end()) {
          r.bad(p + "/" + key, std::string(type->name) + " takes no \"" + key + "\"");
        }
      }
      slot.first = refs[0];
      slot.second = refs.size() > 1 ? refs[1] : refs[0];
      for (const Port& port : type->ports) {
        if (port.kind != PortKind::kOutput) continue;
        slot.outputs.push_back(&port);
        if (port.name == "Error") slot.error = &port;
        if (port.name == "ErrorID") slot.error_id = &port;
      }
      s.blocks.push_back(std::move(slot));
      it = std::prev(s.blocks.end());
      action.declares = true;
    } else {
      if (it == s.blocks.end()) {
        r.bad(p + "/block", "no block '" + name +
                                "' declared before (the first action naming a block gives its "
                                "\"type\")");
      }
      for (const char* key : {"axis", "master", "slave"}) {
        if (a.contains(key))
          r.bad(p + "/" + key, "the axes of a block are given where it is declared");
      }
    }
    action.block = static_cast<std::size_t>(it - s.blocks.begin());
    if (a.contains("set")) {
      const json& set = a["set"];
      if (!set.is_object()) r.bad(p + "/set", "must be an object of inputs");
      const BlockType& type = *it->type;
      for (const auto& item : set.items()) {
        const std::string ip = p + "/set/" + item.key();
        const Port* port = type.find(item.key());
        if (port == nullptr || port->kind != PortKind::kInput) {
          r.bad(ip, "unknown input '" + item.key() + "' of " + std::string(type.name) +
                        " (inputs: " + Reader::ports(type, PortKind::kInput) + ")");
        }
        action.sets.emplace_back(port, r.port_value(*port, item.value(), ip));
      }
    }
    if (a.contains("write"))
      r.bad(p + "/write", "an action sets a block or writes an axis, not both");
  } else {
    if (a.contains("type")) r.bad(p + "/block", "required with \"type\"");
    if (a.contains("set")) r.bad(p + "/block", "required with \"set\"");
    if (a.contains("write")) {
      if (!a.contains("axis")) r.bad(p + "/axis", "required with \"write\"");
      action.axis = r.axis(a["axis"], p + "/axis");
      const json& write = a["write"];
      if (!write.is_object()) r.bad(p + "/write", "must be an object of PlcToNc fields");
      for (const auto& item : write.items()) {
        const std::string wp = p + "/write/" + item.key();
        const auto* f = std::find_if(std::begin(kPlcFields), std::end(kPlcFields),
                                     [&](const FieldName& n) { return n.name == item.key(); });
        if (f == std::end(kPlcFields)) {
          std::string list;
          for (const FieldName& n : kPlcFields)
            append_name(list, n.name);
          r.bad(wp, "unknown PlcToNc field '" + item.key() + "' (fields: " + list + ")");
        }
        double v = 0.0;
        if (f->boolean) {
          if (!item.value().is_boolean())
            r.bad(wp, "a BOOL: true or false, got " + item.value().dump());
          v = item.value().get<bool>() ? 1.0 : 0.0;
        } else {
          v = r.real(item.value(), wp);
        }
        if (f->field == PlcField::kOverride && (v < 0.0 || v > 1'000'000.0 || v != std::floor(v))) {
          r.bad(wp, "Override is an integer 0 … 1000000 (= 0 … 100 %)");
        }
        if (f->field == PlcField::kControlDWord &&
            (v < 0.0 || v > 4294967295.0 || v != std::floor(v))) {
          r.bad(wp, "ControlDWord is an unsigned 32-bit integer");
        }
        if (f->field == PlcField::kExtSetDirection && v != -1.0 && v != 0.0 && v != 1.0) {
          r.bad(wp, "ExtSetDirection is -1, 0 or 1");
        }
        action.writes.emplace_back(f->field, v);
      }
    } else {
      if (a.contains("axis")) r.bad(p + "/write", "required with \"axis\" (or give a \"block\")");
      if (!action.t && !action.when && !a.contains("after")) {
        r.bad(p, "an action needs \"block\" or \"axis\" with \"write\"");
      }
    }
  }
  s.actions.push_back(std::move(action));
}

std::string describe_time(double t) {
  return std::isinf(t) ? std::string("the end") : number(t) + " s";
}

void read_check(Reader& r, Scenario::Impl& s, const json& c, const std::string& p) {
  r.keys(c, p,
         {"name", "t", "from", "to", "axis", "field", "block", "output", "value", "tol", "min",
          "max", "abs", "ever", "change", "no_errors"});
  Check check;
  check.pointer = p;
  auto read_t = [&](const char* key, double fallback) {
    if (!c.contains(key)) return fallback;
    if (c[key].is_string() && c[key].get<std::string>() == "end") {
      return std::numeric_limits<double>::infinity();
    }
    return r.time(c[key], p + "/" + key);
  };
  check.from = read_t("from", 0.0);
  check.to = read_t("to", std::numeric_limits<double>::infinity());
  if (check.to < check.from) r.bad(p + "/to", "the window ends before it starts");
  if (c.contains("tol")) {
    check.tolerance = r.real(c["tol"], p + "/tol");
    if (check.tolerance < 0.0) r.bad(p + "/tol", "must be >= 0");
  }
  std::string subject;
  if (c.contains("no_errors")) {
    if (c["no_errors"] != true) r.bad(p + "/no_errors", "must be true");
    check.kind = CheckKind::kNoErrors;
    check.description = "no block or axis error";
    if (check.from > 0.0 || !std::isinf(check.to)) {
      check.description += " from " + describe_time(check.from) + " to " + describe_time(check.to);
    }
  } else {
    check.column = r.column(c, p, subject);
    const Port* port = nullptr;
    if (c.contains("block")) {
      port = s.blocks[r.block(c["block"], p + "/block")].type->find(c["output"].get<std::string>());
    }
    auto value_of = [&](const char* key) {
      return port != nullptr ? r.port_value(*port, c[key], p + "/" + key)
                             : r.real(c[key], p + "/" + key);
    };
    const std::string tol = check.tolerance > 0.0 ? " \u00b1 " + number(check.tolerance) : "";
    if (c.contains("change")) {
      if (!c.contains("from") || !c.contains("to"))
        r.bad(p, "\"change\" needs \"from\" and \"to\"");
      check.kind = CheckKind::kChange;
      check.value = r.real(c["change"], p + "/change");
      check.description = subject + " changes by " + number(check.value) + tol + " from " +
                          describe_time(check.from) + " to " + describe_time(check.to);
    } else if (c.contains("min") || c.contains("max") || c.contains("ever")) {
      const bool ever = c.contains("ever") && c["ever"] == true;
      if (c.contains("ever") && !c["ever"].is_boolean())
        r.bad(p + "/ever", "must be true or false");
      check.kind = ever ? CheckKind::kEver : CheckKind::kAll;
      check.absolute = c.contains("abs") && c["abs"] == true;
      if (c.contains("value")) {
        check.min = check.max = value_of("value");
      }
      if (c.contains("min")) check.min = r.real(c["min"], p + "/min");
      if (c.contains("max")) check.max = r.real(c["max"], p + "/max");
      if (!c.contains("min") && !c.contains("max") && !c.contains("value")) {
        r.bad(p, "needs \"min\", \"max\" or \"value\"");
      }
      check.min -= check.tolerance;
      check.max += check.tolerance;
      const std::string what = check.absolute ? "|" + subject + "|" : subject;
      std::string range;
      if (c.contains("value") && !c.contains("min") && !c.contains("max")) {
        range = "= " + number(check.min + check.tolerance) + tol;
      } else {
        if (!std::isinf(check.min)) range += ">= " + number(check.min);
        if (!std::isinf(check.max))
          range += std::string(range.empty() ? "" : " and ") + "<= " + number(check.max);
      }
      check.description = what + (ever ? " is at some time " : " stays ") + range;
      if (check.from > 0.0 || !std::isinf(check.to)) {
        check.description +=
            " from " + describe_time(check.from) + " to " + describe_time(check.to);
      }
    } else {
      if (!c.contains("t"))
        r.bad(p + "/t", "required (a time in s or \"end\"), or give min/max/ever/change");
      if (!c.contains("value")) r.bad(p + "/value", "required with \"t\"");
      check.kind = CheckKind::kAt;
      check.t = read_t("t", 0.0);
      check.value = value_of("value");
      check.description = subject + " at " + describe_time(check.t) + " = " +
                          (port != nullptr && port->type == ValueType::kBool
                               ? std::string(check.value != 0.0 ? "TRUE" : "FALSE")
                               : number(check.value)) +
                          tol;
    }
  }
  if (c.contains("name"))
    check.description = r.text(c["name"], p + "/name") + ": " + check.description;
  s.checks.push_back(std::move(check));
}

void read_plots(Reader& r, Scenario::Impl& s, const json& plots) {
  if (!plots.is_array()) r.bad("/plots", "must be an array");
  for (std::size_t i = 0; i < plots.size(); ++i) {
    const std::string p = "/plots/" + std::to_string(i);
    r.keys(plots[i], p, {"name", "title", "panels"});
    PlotSpec plot;
    if (!plots[i].contains("name")) r.bad(p + "/name", "required");
    plot.name = r.text(plots[i]["name"], p + "/name");
    if (!valid_name(plot.name) || plot.name.find_first_of("/\\") != std::string::npos) {
      r.bad(p + "/name", "a plot name is a file stem (no . , \" / \\ or line break)");
    }
    for (const AxisSlot& a : s.axes) {
      if (a.name == plot.name)
        r.bad(p + "/name", "is the name of an axis (its plot is made anyway)");
    }
    for (const PlotSpec& other : s.plots) {
      if (other.name == plot.name) r.bad(p + "/name", "duplicate plot name");
    }
    if (plots[i].contains("title")) plot.title = r.text(plots[i]["title"], p + "/title");
    const json& panels = r.items(plots[i], "panels", p + "/panels");
    for (std::size_t k = 0; k < panels.size(); ++k) {
      const std::string pp = p + "/panels/" + std::to_string(k);
      r.keys(panels[k], pp, {"title", "unit", "series"});
      PlotPanelSpec panel;
      if (panels[k].contains("title")) panel.title = r.text(panels[k]["title"], pp + "/title");
      if (panels[k].contains("unit")) panel.unit = r.text(panels[k]["unit"], pp + "/unit");
      const json& series = r.items(panels[k], "series", pp + "/series");
      for (std::size_t j = 0; j < series.size(); ++j) {
        const std::string sp = pp + "/series/" + std::to_string(j);
        r.keys(series[j], sp,
               {"axis", "field", "block", "output", "label", "colour", "scale", "width"});
        PlotSeriesSpec line;
        std::string name;
        line.column = r.column(series[j], sp, name);
        line.label = series[j].contains("label") ? r.text(series[j]["label"], sp + "/label") : name;
        line.colour =
            series[j].contains("colour") ? r.text(series[j]["colour"], sp + "/colour") : "#404040";
        if (series[j].contains("scale")) line.scale = r.real(series[j]["scale"], sp + "/scale");
        if (series[j].contains("width")) {
          line.width = r.real(series[j]["width"], sp + "/width");
          if (line.width <= 0.0) r.bad(sp + "/width", "must be > 0");
        }
        panel.series.push_back(std::move(line));
      }
      plot.panels.push_back(std::move(panel));
    }
    s.plots.push_back(std::move(plot));
  }
}

}  // namespace

Scenario::Scenario(const json& axes, const json& timeline, std::string axes_file,
                   std::string timeline_file) {
  // The axes: nc's reader names the pointer and the rule of a bad configuration.
  nc::KernelSetup setup;
  try {
    setup = nc::parse_kernel_setup(axes);
  } catch (const nc::ConfigError& e) {
    throw InputError(axes_file, e.pointer(),
                     e.rule() + (e.value().empty() ? "" : " (got " + e.value() + ")"));
  }
  if (setup.axes.empty())
    throw InputError(axes_file, "/axes", "a scenario needs at least one axis");
  const double cycle = setup.kernel.cycle_time;

  // The run's length decides the trace's size, so it is read first.
  if (!timeline.is_object()) throw InputError(timeline_file, "", "must be a JSON object");
  auto bad = [&](const std::string& pointer, const std::string& rule) {
    throw InputError(timeline_file, pointer, rule);
  };
  if (!timeline.contains("duration")) bad("/duration", "required: the longest the run may take, s");
  if (!timeline["duration"].is_number()) bad("/duration", "must be a number");
  const double duration = timeline["duration"].get<double>();
  if (!std::isfinite(duration) || duration <= 0.0) bad("/duration", "must be > 0 s and finite");
  const double samples = std::ceil(duration / cycle) + 3.0;
  if (samples > static_cast<double>(kMaxSamples)) {
    bad("/duration", "too long: more than " + std::to_string(kMaxSamples) + " NC cycles");
  }
  impl_ = std::make_unique<Impl>(setup.kernel, static_cast<std::size_t>(samples));
  Impl& s = *impl_;
  s.axes_file = std::move(axes_file);
  s.timeline_file = std::move(timeline_file);
  s.duration = duration;
  Reader r(s, s.timeline_file);
  r.keys(timeline, "",
         {"title", "axes", "plc_period", "duration", "stop_when", "timeline", "expect",
          "extra_panels", "plots", "figure", "comment"});

  for (const nc::AxisConfig& config : setup.axes) {
    if (config.name.find_first_of(".,\"\r\n") != std::string::npos) {
      throw InputError(s.axes_file, "/axes/" + std::to_string(s.axes.size()) + "/name",
                       "a scenario's axis name has no . , \" or line break");
    }
    AxisSlot slot;
    slot.errors.reserve(kMaxErrorsNoted);  // the cycle only copies numbers
    slot.name = config.name;
    slot.ref = &s.kernel.add_axis(config);
    s.scope.add_signal(*slot.ref, slot.name, nc::Signal::kSetPos);
    for (int k = 1; k <= static_cast<int>(nc::Signal::kControlDWord); ++k) {
      s.scope.add_signal(*slot.ref, slot.name, static_cast<nc::Signal>(k));
    }
    s.scope.add_variable(&slot.ref->PlcToNc.GearRatio1, slot.name + ".GearRatio1", "");
    s.scope.add_variable(&slot.ref->NcToPlc.GearRatio, slot.name + ".GearRatio", "");
    s.axes.push_back(std::move(slot));
  }

  if (timeline.contains("title")) s.title = r.text(timeline["title"], "/title");
  if (timeline.contains("axes")) (void)r.text(timeline["axes"], "/axes");
  s.plc_period = cycle;
  if (timeline.contains("plc_period")) {
    s.plc_period = r.real(timeline["plc_period"], "/plc_period");
    const double ratio = s.plc_period / cycle;
    if (s.plc_period <= 0.0 || std::round(ratio) < 1.0 ||
        std::fabs(ratio - std::round(ratio)) > 1e-9 * ratio) {
      r.bad("/plc_period",
            "must be a positive whole multiple of the NC cycle (" + number(cycle) + " s)");
    }
  }

  if (!timeline.contains("timeline") || !timeline["timeline"].is_array()) {
    r.bad("/timeline", "required: an array of actions");
  }
  std::optional<double> last_t;
  const json& actions = timeline["timeline"];
  for (std::size_t i = 0; i < actions.size(); ++i) {
    read_action(r, s, actions[i], "/timeline/" + std::to_string(i), last_t);
  }
  // The traced outputs: sized once, then the scope reads them in place.
  std::size_t count = 0;
  for (BlockSlot& b : s.blocks) {
    b.trace_begin = count;
    count += b.outputs.size();
  }
  s.outputs.assign(count, 0.0);
  for (BlockSlot& b : s.blocks) {
    for (std::size_t k = 0; k < b.outputs.size(); ++k) {
      s.scope.add_variable(&s.outputs[b.trace_begin + k],
                           b.name + "." + std::string(b.outputs[k]->name), "");
    }
  }

  if (timeline.contains("stop_when")) {
    s.stop_pointer = "/stop_when";
    const json& stop = timeline["stop_when"];
    if (stop.is_object() && stop.contains("actions_done")) {
      r.keys(stop, "/stop_when", {"actions_done", "after"});
      if (stop["actions_done"] != true) r.bad("/stop_when/actions_done", "must be true");
      s.stop_when_actions_done = true;
    } else {
      s.stop_when = r.condition(stop, "/stop_when", {"block", "output", "value", "after"});
    }
    if (timeline["stop_when"].contains("after")) {
      s.stop_after = r.time(timeline["stop_when"]["after"], "/stop_when/after");
    }
  }
  if (timeline.contains("expect")) {
    const json& expect = timeline["expect"];
    if (!expect.is_array()) r.bad("/expect", "must be an array of checks");
    for (std::size_t i = 0; i < expect.size(); ++i) {
      read_check(r, s, expect[i], "/expect/" + std::to_string(i));
    }
  }
  if (timeline.contains("extra_panels")) {
    const json& extra = timeline["extra_panels"];
    if (!extra.is_array()) r.bad("/extra_panels", "must be an array of axis field names");
    for (std::size_t i = 0; i < extra.size(); ++i) {
      const std::string p = "/extra_panels/" + std::to_string(i);
      const std::string field = r.text(extra[i], p);
      if (s.scope.find(s.axes[0].name + "." + field) == s.scope.channel_count()) {
        r.bad(p, "unknown axis field '" + field + "'");
      }
      s.extra_panels.push_back(field);
    }
  }
  if (timeline.contains("plots")) read_plots(r, s, timeline["plots"]);
  s.figure = s.axes.size() == 1 || s.plots.empty() ? s.axes[0].name : s.plots[0].name;
  if (timeline.contains("figure")) {
    s.figure = r.text(timeline["figure"], "/figure");
    const std::vector<std::string> names = figure_names();
    if (std::find(names.begin(), names.end(), s.figure) == names.end()) {
      r.bad("/figure", "names no axis and no plot");
    }
  }
}

Scenario::~Scenario() = default;

std::vector<std::string> Scenario::figure_names() const {
  std::vector<std::string> names;
  for (const AxisSlot& a : impl_->axes)
    names.push_back(a.name);
  for (const PlotSpec& p : impl_->plots)
    names.push_back(p.name);
  return names;
}

std::string Scenario::figure() const {
  return impl_->figure;
}
const std::string& Scenario::title() const {
  return impl_->title;
}
const nc::Scope& Scenario::trace() const {
  return impl_->scope;
}
const std::vector<CheckResult>& Scenario::checks() const {
  return impl_->results;
}
bool Scenario::passed() const {
  return impl_->played && std::all_of(impl_->results.begin(), impl_->results.end(),
                                      [](const CheckResult& c) { return c.passed; });
}

}  // namespace scenario
