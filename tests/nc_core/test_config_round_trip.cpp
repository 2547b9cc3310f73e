// to_json and the reader are inverse for every field: reading what was written gives the same
// configuration, bit for bit. Also checks that the visitor lists every member of the structs, so
// that a newly added field cannot be silently skipped by JSON, validation and docs.
#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>

#include <nlohmann/json.hpp>

#include "nc_core/config.hpp"

using nlohmann::json;

namespace {

// Changes every field to a valid value different from the default, using the visitor itself.
struct Mutate {
  int index = 0;

  void operator()(const nc::FieldInfo&, double& v, const nc::RealRule& rule) {
    // Thirds need all 17 digits to read back exactly; increasing with the field index keeps
    // sw_limit_min below sw_limit_max.
    const double third = (index++ + 1) / 3.0;
    v = rule.allows(third) && third != v ? third : 0.0015;
  }
  void operator()(const nc::FieldInfo&, int& v, const nc::IntRule& rule) {
    ++index;
    v = rule.allows(static_cast<long long>(v) + 1) ? v + 1 : v - 1;
  }
  void operator()(const nc::FieldInfo&, bool& v, const nc::FlagRule&) {
    ++index;
    v = !v;
  }
  void operator()(const nc::FieldInfo&, std::string& v, const nc::TextRule&) {
    ++index;
    v = "Axis/1~\xC3\xA4 \"q\"";  // slash, tilde, UTF-8 and quotes survive
  }
  template <class E>
  void operator()(const nc::FieldInfo&, E& v, const nc::EnumRule<E>& rule) {
    ++index;
    for (const auto& n : rule.names) {
      if (n.value != v) {
        v = n.value;
        return;
      }
    }
  }
};

template <class Config>
Config everything_changed() {
  Config c{};
  nc::visit_fields(c, Mutate{});
  return c;
}

template <class Config>
std::size_t visited_field_count() {
  std::size_t n = 0;
  const Config c{};
  nc::visit_fields(c, [&](const nc::FieldInfo&, const auto&, const auto&) { ++n; });
  return n;
}

// Counts the members of an aggregate: the largest number of initialisers it accepts.
struct AnyValue {
  template <class T>
  operator T() const;  // never called: only used in unevaluated contexts
};

template <class T, std::size_t... I>
constexpr bool brace_constructible(std::index_sequence<I...>) {
  return requires {
    T{((void)I, AnyValue{})...};
  };
}

template <class T, std::size_t N = 0>
constexpr std::size_t member_count() {
  if constexpr (brace_constructible<T>(std::make_index_sequence<N + 1>{})) {
    return member_count<T, N + 1>();
  } else {
    return N;
  }
}

}  // namespace

TEST_CASE("the visitor lists every member of KernelConfig and AxisConfig", "[config]") {
  static_assert(std::is_aggregate_v<nc::AxisConfig> && std::is_aggregate_v<nc::KernelConfig>);
  CHECK(visited_field_count<nc::KernelConfig>() == member_count<nc::KernelConfig>());
  CHECK(visited_field_count<nc::AxisConfig>() == member_count<nc::AxisConfig>());
  CHECK(visited_field_count<nc::AxisConfig>() >= 32);
}

TEST_CASE("every field written by to_json is read back unchanged", "[config]") {
  const nc::AxisConfig axis = everything_changed<nc::AxisConfig>();
  const nc::KernelConfig kernel = everything_changed<nc::KernelConfig>();
  REQUIRE_NOTHROW(nc::validate(axis));
  REQUIRE_NOTHROW(nc::validate(kernel));

  // Every key really differs from its default, so the round trip below tests each field.
  const json changed = nc::to_json(axis);
  const json defaults = nc::to_json(nc::AxisConfig{});
  REQUIRE(changed.size() == visited_field_count<nc::AxisConfig>());
  for (const auto& item : changed.items()) {
    INFO(item.key());
    CHECK(item.value() != defaults.at(item.key()));
  }
  CHECK(nc::to_json(kernel) != nc::to_json(nc::KernelConfig{}));

  CHECK(nc::parse_axis_config(changed) == axis);
  CHECK(nc::parse_kernel_config(nc::to_json(kernel)) == kernel);

  nc::KernelSetup setup{kernel, {axis, nc::AxisConfig{}}};
  setup.axes[1].name = "second";
  CHECK(nc::parse_kernel_setup(nc::to_json(setup)) == setup);
  // Through text as well: doubles are printed with enough digits to read back exactly.
  CHECK(nc::parse_kernel_setup_text(nc::to_json(setup).dump(2)) == setup);
}

TEST_CASE("enums are written by name", "[config]") {
  nc::AxisConfig axis;
  axis.name = "E";
  axis.kind = nc::AxisKind::kEncoder;
  axis.drive_model = nc::DriveModel::kFirstOrderLag;
  const json j = nc::to_json(axis);
  CHECK(j.at("kind") == "encoder");
  CHECK(j.at("drive_model") == "first_order_lag");
  CHECK(nc::to_string(nc::AxisKind::kContinuous) == "continuous");
  CHECK(nc::to_string(nc::DriveModel::kIdeal) == "ideal");
}
