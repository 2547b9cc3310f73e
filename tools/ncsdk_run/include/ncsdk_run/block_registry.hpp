// The registry of function blocks a scenario can call by type name (SPEC H, API.md "Scenarios").
//
// Every block of fb is listed once with its IEC inputs and outputs: a port is a name, a value
// type and a getter/setter over the block's public member, so a timeline can set
// `"Execute": true` on an "MC_MoveAbsolute" and read its `Done`. A block type says which axes
// it is called with: one ("axis") or, for the coupling blocks, two ("master", "slave"); MC_GearOut
// names its one axis "slave". MC_ExtSetPointGenFeed, a function in fb, is wrapped as a block
// whose output ErrorID is the function's result.
// Set-up code (find_block_type, make) allocates; Block::call is a cycle function.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>

#include "plc_interface/axis_ref.hpp"

namespace scenario {

enum class PortKind : uint8_t { kInput, kOutput };

// How a port's value reads in JSON: BOOL true/false, REAL any finite number, an integer, or one of
// fb's enums (by its name or its number).
enum class ValueType : uint8_t { kBool, kReal, kInteger, kDirection, kBufferMode, kPositionType };

struct Port {
  std::string_view name;  // IEC name, e.g. "Execute"
  PortKind kind = PortKind::kInput;
  ValueType type = ValueType::kReal;
  double (*get)(const void* block) noexcept = nullptr;
  void (*set)(void* block, double value) noexcept = nullptr;
};

// One block instance of a scenario.
class Block {
 public:
  virtual ~Block() = default;
  // Cycle: runs the block once; `second` is the slave of a two-axis block (else unused).
  virtual void call(plc::AXIS_REF& first, plc::AXIS_REF& second) noexcept = 0;
  virtual void* data() noexcept = 0;
  virtual const void* data() const noexcept = 0;
};

struct BlockType {
  std::string_view name;                   // "MC_MoveAbsolute"
  std::span<const Port> ports;             // inputs and outputs
  std::span<const std::string_view> axes;  // {"axis"} or {"master", "slave"} or {"slave"}
  std::unique_ptr<Block> (*make)() = nullptr;

  const Port* find(std::string_view port) const noexcept;
};

// Every registered type, in a fixed order.
std::span<const BlockType> block_types();
// The type with this name, nullptr when there is none.
const BlockType* find_block_type(std::string_view name) noexcept;

// fb's enums by name: the name of a value ("" when it has none) and the value of a name (-1 when
// there is none).
std::string_view enum_value_name(ValueType type, int value) noexcept;
int enum_value(ValueType type, std::string_view name) noexcept;

}  // namespace scenario
