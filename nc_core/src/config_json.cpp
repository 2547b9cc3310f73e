// Reading and writing the configuration as JSON, driven by visit_fields() (config_fields.hpp).
// Readers are strict: a key the visitor does not list, a value of the wrong JSON type, and a
// number with a fraction where an integer is needed are errors, never silently converted.
#include <algorithm>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "config_text.hpp"
#include "nc_core/cnc_parameters.hpp"
#include "nc_core/config.hpp"

namespace nc {

namespace {

using config_text::child;
using config_text::shown;
using nlohmann::json;

// Keys the visitor lists for a struct, to recognise unknown keys.
template <class Config>
std::vector<std::string_view> field_keys() {
  std::vector<std::string_view> keys;
  const Config probe{};
  visit_fields(probe, [&](const FieldInfo& f, const auto&, const auto&) { keys.push_back(f.key); });
  return keys;
}

// Levenshtein distance, to suggest the intended key for a misspelt one.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

[[noreturn]] void throw_unknown_key(std::string_view pointer, const std::string& key,
                                    const std::vector<std::string_view>& known) {
  std::string rule = "unknown key";
  std::string_view best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (const auto k : known) {
    const std::size_t d = edit_distance(key, k);
    if (d < best_distance) {
      best_distance = d;
      best = k;
    }
  }
  // Up to a third of the letters wrong still reads as a typo rather than another word.
  if (!best.empty() && best_distance * 3 <= std::max<std::size_t>(best.size(), 3)) {
    rule += " (did you mean \"" + std::string(best) + "\"?)";
  }
  throw ConfigError(child(pointer, key), rule);
}

void require_object(const json& value, std::string_view pointer) {
  if (!value.is_object())
    throw ConfigError(std::string(pointer), "must be an object", shown(value));
}

void reject_unknown_keys(const json& object, std::string_view pointer,
                         const std::vector<std::string_view>& known) {
  for (const auto& item : object.items()) {
    if (std::find(known.begin(), known.end(), item.key()) == known.end()) {
      throw_unknown_key(pointer, item.key(), known);
    }
  }
}

// Copies each present key into the struct, checking only the JSON type; the value rules are
// checked afterwards by validate() so that code and JSON share one set of rules.
struct ReadVisitor {
  const json& object;
  std::string_view pointer;

  const json* find(const FieldInfo& f) const {
    const auto it = object.find(f.key);
    return it == object.end() ? nullptr : &*it;
  }

  void operator()(const FieldInfo& f, double& value, const RealRule&) const {
    const json* j = find(f);
    if (j == nullptr) return;
    if (!j->is_number()) throw ConfigError(child(pointer, f.key), "must be a number", shown(*j));
    value = j->get<double>();
  }
  void operator()(const FieldInfo& f, int& value, const IntRule& rule) const {
    const json* j = find(f);
    if (j == nullptr) return;
    if (!j->is_number_integer()) {
      throw ConfigError(child(pointer, f.key), "must be an integer", shown(*j));
    }
    // Out of int's range cannot be stored; it is outside every IntRule anyway, and the message
    // states both bounds so that "must be >= 0" is not said of a huge positive number.
    const bool fits = j->is_number_unsigned()
                          ? j->get<std::uint64_t>() <= static_cast<std::uint64_t>(INT_MAX)
                          : j->get<std::int64_t>() >= INT_MIN && j->get<std::int64_t>() <= INT_MAX;
    if (!fits) {
      throw ConfigError(child(pointer, f.key),
                        std::string("must be in [") + std::to_string(rule.min) + ", " +
                            std::to_string(rule.max) + "]",
                        shown(*j));
    }
    value = static_cast<int>(j->get<std::int64_t>());
  }
  void operator()(const FieldInfo& f, bool& value, const FlagRule&) const {
    const json* j = find(f);
    if (j == nullptr) return;
    if (!j->is_boolean()) {
      throw ConfigError(child(pointer, f.key), "must be true or false", shown(*j));
    }
    value = j->get<bool>();
  }
  void operator()(const FieldInfo& f, std::string& value, const TextRule&) const {
    const json* j = find(f);
    if (j == nullptr) return;
    if (!j->is_string()) throw ConfigError(child(pointer, f.key), "must be a string", shown(*j));
    value = j->get<std::string>();
  }
  template <class E>
  void operator()(const FieldInfo& f, E& value, const EnumRule<E>& rule) const {
    const json* j = find(f);
    if (j == nullptr) return;
    if (j->is_string()) {
      const auto& text = j->get_ref<const std::string&>();
      for (const auto& n : rule.names) {
        if (n.name == text) {
          value = n.value;
          return;
        }
      }
    }
    throw ConfigError(child(pointer, f.key), config_text::must(rule), shown(*j));
  }
};

struct WriteVisitor {
  json& out;

  void operator()(const FieldInfo& f, double value, const RealRule&) const {
    out[std::string(f.key)] = value;
  }
  void operator()(const FieldInfo& f, int value, const IntRule&) const {
    out[std::string(f.key)] = value;
  }
  void operator()(const FieldInfo& f, bool value, const FlagRule&) const {
    out[std::string(f.key)] = value;
  }
  void operator()(const FieldInfo& f, const std::string& value, const TextRule&) const {
    out[std::string(f.key)] = value;
  }
  template <class E>
  void operator()(const FieldInfo& f, E value, const EnumRule<E>& rule) const {
    const std::string_view* name = rule.find_name(value);
    if (name == nullptr) {
      throw ConfigError(child("", f.key), config_text::must(rule),
                        std::to_string(static_cast<std::underlying_type_t<E>>(value)));
    }
    out[std::string(f.key)] = std::string(*name);
  }
};

template <class Config>
Config parse_struct(const json& object, std::string_view pointer) {
  require_object(object, pointer);
  static const std::vector<std::string_view> known = field_keys<Config>();
  reject_unknown_keys(object, pointer, known);
  Config config{};
  visit_fields(config, ReadVisitor{object, pointer});
  try {
    validate(config);
  } catch (const ConfigError& e) {
    throw e.prefixed(pointer);
  }
  return config;
}

// Tracks where the parser is, to name a key that occurs twice in one object: the JSON library
// keeps only one of them, which would silently drop a setting.
class DuplicateKeyFinder {
 public:
  bool on_event(json::parse_event_t event, const json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
        frames_.push_back(Frame{false, 0, {}, {}});
        break;
      case json::parse_event_t::array_start:
        frames_.push_back(Frame{true, 0, {}, {}});
        break;
      case json::parse_event_t::key: {
        Frame& frame = frames_.back();
        frame.key = parsed.get<std::string>();
        if (!frame.keys.insert(frame.key).second && !error_) {
          error_ = ConfigError(current_pointer(), "key occurs twice in the same object");
        }
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        frames_.pop_back();
        element_done();
        break;
      case json::parse_event_t::value:
        element_done();
        break;
    }
    return true;
  }

  const std::optional<ConfigError>& error() const { return error_; }

  // Where the parser is: the key or array element being read.
  std::string current_pointer() const {
    std::string out;
    for (const Frame& f : frames_) {
      out += f.is_array ? std::string("/") + std::to_string(f.index) : child("", f.key);
    }
    return out;
  }

 private:
  struct Frame {
    bool is_array;
    std::size_t index;  // array: elements completed so far = index of the one being read
    std::string key;    // object: the key being read
    std::set<std::string> keys;
  };

  void element_done() {
    if (!frames_.empty() && frames_.back().is_array) ++frames_.back().index;
  }

  std::vector<Frame> frames_;
  std::optional<ConfigError> error_;
};

// The library's message without its "[json.exception.parse_error.101] " tag.
std::string without_tag(const char* what) {
  std::string message = what;
  const auto tag_end = message.find("] ");
  if (message.rfind("[json.exception.", 0) == 0 && tag_end != std::string::npos) {
    message.erase(0, tag_end + 2);
  }
  return message;
}

json parse_text(std::string_view text) {
  DuplicateKeyFinder finder;
  json document;
  try {
    document = json::parse(text, [&finder](int, json::parse_event_t event, json& parsed) {
      return finder.on_event(event, parsed);
    });
  } catch (const json::parse_error& e) {
    throw ConfigError("", std::string("invalid JSON: ") + without_tag(e.what()));
  } catch (const json::out_of_range& e) {
    // A number beyond double (1e999): the parser stops at it, so the key being read is known.
    std::string message = without_tag(e.what());
    const auto open = message.find('\'');
    const auto close = message.rfind('\'');
    std::string token = open != std::string::npos && close > open
                            ? message.substr(open + 1, close - open - 1)
                            : message;
    throw ConfigError(finder.current_pointer(), "must be finite", std::move(token));
  }
  if (finder.error()) throw *finder.error();
  return document;
}

}  // namespace

KernelConfig parse_kernel_config(const json& object, std::string_view pointer) {
  return parse_struct<KernelConfig>(object, pointer);
}

AxisConfig parse_axis_config(const json& object, std::string_view pointer) {
  require_object(object, pointer);
  // From code an empty name is refused by validate(); in a file the key must be there at all.
  if (!object.contains("name")) throw ConfigError(child(pointer, "name"), "required");
  // CNC parameters in native units (seed 002 §4) map onto fields once those are read.
  const auto cnc = object.find("cnc");
  if (cnc == object.end()) return parse_struct<AxisConfig>(object, pointer);
  json fields = object;
  fields.erase("cnc");
  AxisConfig config = parse_struct<AxisConfig>(fields, pointer);
  cnc::apply_cnc_parameters(*cnc, object, pointer, config);
  return config;
}

KernelSetup parse_kernel_setup(const json& document) {
  require_object(document, "");
  static const std::vector<std::string_view> kTopKeys = {"kernel", "axes"};
  reject_unknown_keys(document, "", kTopKeys);

  KernelSetup setup;
  if (const auto it = document.find("kernel"); it != document.end()) {
    setup.kernel = parse_kernel_config(*it, "/kernel");
  }

  const auto axes = document.find("axes");
  if (axes == document.end()) throw ConfigError("/axes", "required");
  if (!axes->is_array()) throw ConfigError("/axes", "must be an array", shown(*axes));

  std::map<std::string, std::size_t> index_of_name;
  std::map<int, std::size_t> index_of_id;
  setup.axes.reserve(axes->size());
  for (std::size_t i = 0; i < axes->size(); ++i) {
    const std::string pointer = std::string("/axes/") + std::to_string(i);
    AxisConfig axis = parse_axis_config((*axes)[i], pointer);
    if (const auto [it, fresh] = index_of_name.emplace(axis.name, i); !fresh) {
      throw ConfigError(
          pointer + "/name",
          std::string("must be unique; axis ") + std::to_string(it->second) + " has it too",
          shown(json(axis.name)));
    }
    // id 0 asks the kernel to assign one, so only explicit ids must differ.
    if (axis.id != 0) {
      if (const auto [it, fresh] = index_of_id.emplace(axis.id, i); !fresh) {
        throw ConfigError(
            pointer + "/id",
            std::string("must be unique; axis ") + std::to_string(it->second) + " has it too",
            std::to_string(axis.id));
      }
    }
    setup.axes.push_back(std::move(axis));
  }
  return setup;
}

KernelSetup parse_kernel_setup_text(std::string_view text) {
  return parse_kernel_setup(parse_text(text));
}

KernelSetup parse_kernel_setup_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError("", std::string("cannot open file ") + path.string());
  std::ostringstream contents;
  contents << in.rdbuf();
  if (in.bad()) throw ConfigError("", std::string("cannot read file ") + path.string());
  return parse_kernel_setup_text(contents.str());
}

json to_json(const KernelConfig& config) {
  json out = json::object();
  visit_fields(config, WriteVisitor{out});
  return out;
}

json to_json(const AxisConfig& config) {
  json out = json::object();
  visit_fields(config, WriteVisitor{out});
  return out;
}

json to_json(const KernelSetup& setup) {
  json axes = json::array();
  for (const AxisConfig& axis : setup.axes)
    axes.push_back(to_json(axis));
  return json{{"kernel", to_json(setup.kernel)}, {"axes", std::move(axes)}};
}

}  // namespace nc
