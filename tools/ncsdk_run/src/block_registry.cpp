#include "ncsdk_run/block_registry.hpp"

#include <algorithm>
#include <array>
#include <type_traits>

#include "fb/fb.hpp"

namespace scenario {
namespace {

template <class T>
struct MemberOf;
template <class C, class T>
struct MemberOf<T C::*> {
  using Class = C;
  using Type = T;
};

template <class T>
constexpr ValueType value_type() {
  if constexpr (std::is_same_v<T, bool>) return ValueType::kBool;
  if constexpr (std::is_same_v<T, double>) return ValueType::kReal;
  if constexpr (std::is_same_v<T, fb::MC_Direction>) return ValueType::kDirection;
  if constexpr (std::is_same_v<T, fb::MC_BufferMode>) return ValueType::kBufferMode;
  if constexpr (std::is_same_v<T, fb::E_PositionType>) return ValueType::kPositionType;
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) return ValueType::kInteger;
}

template <class T>
T from_double(double value) noexcept {
  if constexpr (std::is_same_v<T, bool>) {
    return value != 0.0;
  } else if constexpr (std::is_enum_v<T>) {
    return static_cast<T>(static_cast<int32_t>(value));
  } else {
    return static_cast<T>(value);
  }
}

// A port over the public member M of a block.
template <auto M>
constexpr Port port(std::string_view name, PortKind kind) {
  using C = typename MemberOf<decltype(M)>::Class;
  using T = typename MemberOf<decltype(M)>::Type;
  return Port{name, kind, value_type<T>(),
              [](const void* block) noexcept {
                return static_cast<double>(static_cast<const C*>(block)->*M);
              },
              [](void* block, double value) noexcept {
                static_cast<C*>(block)->*M = from_double<T>(value);
              }};
}

// The IEC name is the member's name.
#define NCSDK_IN(B, member) port<&B::member>(#member, PortKind::kInput)
#define NCSDK_OUT(B, member) port<&B::member>(#member, PortKind::kOutput)

template <std::size_t... N>
constexpr std::array<Port, (N + ...)> join(const std::array<Port, N>&... parts) {
  std::array<Port, (N + ...)> all{};
  std::size_t i = 0;
  ((std::copy(parts.begin(), parts.end(), all.begin() + static_cast<std::ptrdiff_t>(i)), i += N),
   ...);
  return all;
}

// The groups of ports many blocks share (the same names in Tc2_MC2).
template <class B>
constexpr std::array<Port, 4> status_outputs() {  // Done … ErrorID of the simple Execute blocks
  return {NCSDK_OUT(B, Done), NCSDK_OUT(B, Busy), NCSDK_OUT(B, Error), NCSDK_OUT(B, ErrorID)};
}
template <class B>
constexpr std::array<Port, 6> motion_outputs() {  // a motion command's outputs
  return {NCSDK_OUT(B, Done),           NCSDK_OUT(B, Busy),  NCSDK_OUT(B, Active),
          NCSDK_OUT(B, CommandAborted), NCSDK_OUT(B, Error), NCSDK_OUT(B, ErrorID)};
}
template <class B>
constexpr std::array<Port, 4> dynamics_inputs() {  // Velocity, Acceleration, Deceleration, Jerk
  return {NCSDK_IN(B, Velocity), NCSDK_IN(B, Acceleration), NCSDK_IN(B, Deceleration),
          NCSDK_IN(B, Jerk)};
}
template <class B>
constexpr std::array<Port, 3> read_outputs() {  // Valid, Busy, Error, ErrorID of the read blocks
  return {NCSDK_OUT(B, Valid), NCSDK_OUT(B, Busy), NCSDK_OUT(B, Error)};
}

// MC_ExtSetPointGenFeed is a function in fb; as a block it is called every PLC cycle with its
// inputs and shows the function's result as ErrorID.
struct ExtSetPointGenFeed {
  double Position = 0.0;
  double Velocity = 0.0;
  double Acceleration = 0.0;
  int32_t Direction = 0;
  uint32_t ErrorID = 0;
  void operator()(plc::AXIS_REF& axis) noexcept {
    ErrorID = fb::MC_ExtSetPointGenFeed(Position, Velocity, Acceleration, Direction, axis);
  }
};

using fb::MC_AbortSuperposition;
using fb::MC_ExtSetPointGenDisable;
using fb::MC_ExtSetPointGenEnable;
using fb::MC_GearIn;
using fb::MC_GearInDyn;
using fb::MC_GearOut;
using fb::MC_Halt;
using fb::MC_MoveAbsolute;
using fb::MC_MoveModulo;
using fb::MC_MoveRelative;
using fb::MC_MoveSuperImposed;
using fb::MC_MoveVelocity;
using fb::MC_NewPos;
using fb::MC_NewPosAndVelo;
using fb::MC_Power;
using fb::MC_ReadActualPosition;
using fb::MC_ReadAxisError;
using fb::MC_ReadStatus;
using fb::MC_Reset;
using fb::MC_SetOverride;
using fb::MC_Stop;

constexpr auto kPower =
    std::array<Port, 9>{NCSDK_IN(MC_Power, Enable),          NCSDK_IN(MC_Power, Enable_Positive),
                        NCSDK_IN(MC_Power, Enable_Negative), NCSDK_IN(MC_Power, Override),
                        NCSDK_OUT(MC_Power, Status),         NCSDK_OUT(MC_Power, Busy),
                        NCSDK_OUT(MC_Power, Active),         NCSDK_OUT(MC_Power, Error),
                        NCSDK_OUT(MC_Power, ErrorID)};
constexpr auto kReset =
    join(std::array<Port, 1>{NCSDK_IN(MC_Reset, Execute)}, status_outputs<MC_Reset>());
constexpr auto kMoveAbsolute = join(
    std::array<Port, 2>{NCSDK_IN(MC_MoveAbsolute, Execute), NCSDK_IN(MC_MoveAbsolute, Position)},
    dynamics_inputs<MC_MoveAbsolute>(), std::array<Port, 1>{NCSDK_IN(MC_MoveAbsolute, BufferMode)},
    motion_outputs<MC_MoveAbsolute>());
constexpr auto kMoveRelative = join(
    std::array<Port, 2>{NCSDK_IN(MC_MoveRelative, Execute), NCSDK_IN(MC_MoveRelative, Distance)},
    dynamics_inputs<MC_MoveRelative>(), std::array<Port, 1>{NCSDK_IN(MC_MoveRelative, BufferMode)},
    motion_outputs<MC_MoveRelative>());
constexpr auto kMoveModulo = join(
    std::array<Port, 2>{NCSDK_IN(MC_MoveModulo, Execute), NCSDK_IN(MC_MoveModulo, Position)},
    dynamics_inputs<MC_MoveModulo>(),
    std::array<Port, 2>{NCSDK_IN(MC_MoveModulo, Direction), NCSDK_IN(MC_MoveModulo, BufferMode)},
    motion_outputs<MC_MoveModulo>());
constexpr auto kMoveVelocity = join(
    std::array<Port, 1>{NCSDK_IN(MC_MoveVelocity, Execute)}, dynamics_inputs<MC_MoveVelocity>(),
    std::array<Port, 2>{NCSDK_IN(MC_MoveVelocity, Direction),
                        NCSDK_IN(MC_MoveVelocity, BufferMode)},
    std::array<Port, 6>{NCSDK_OUT(MC_MoveVelocity, InVelocity), NCSDK_OUT(MC_MoveVelocity, Busy),
                        NCSDK_OUT(MC_MoveVelocity, Active),
                        NCSDK_OUT(MC_MoveVelocity, CommandAborted),
                        NCSDK_OUT(MC_MoveVelocity, Error), NCSDK_OUT(MC_MoveVelocity, ErrorID)});
constexpr auto kHalt =
    join(std::array<Port, 4>{NCSDK_IN(MC_Halt, Execute), NCSDK_IN(MC_Halt, Deceleration),
                             NCSDK_IN(MC_Halt, Jerk), NCSDK_IN(MC_Halt, BufferMode)},
         motion_outputs<MC_Halt>());
constexpr auto kStop =
    join(std::array<Port, 3>{NCSDK_IN(MC_Stop, Execute), NCSDK_IN(MC_Stop, Deceleration),
                             NCSDK_IN(MC_Stop, Jerk)},
         motion_outputs<MC_Stop>());
constexpr auto kSetOverride =
    std::array<Port, 6>{NCSDK_IN(MC_SetOverride, Enable),   NCSDK_IN(MC_SetOverride, VelFactor),
                        NCSDK_OUT(MC_SetOverride, Enabled), NCSDK_OUT(MC_SetOverride, Busy),
                        NCSDK_OUT(MC_SetOverride, Error),   NCSDK_OUT(MC_SetOverride, ErrorID)};
constexpr auto kNewPos = std::array<Port, 7>{
    NCSDK_IN(MC_NewPos, Execute), NCSDK_IN(MC_NewPos, NewPos),          NCSDK_OUT(MC_NewPos, Done),
    NCSDK_OUT(MC_NewPos, Busy),   NCSDK_OUT(MC_NewPos, CommandAborted), NCSDK_OUT(MC_NewPos, Error),
    NCSDK_OUT(MC_NewPos, ErrorID)};
constexpr auto kNewPosAndVelo = std::array<Port, 9>{
    NCSDK_IN(MC_NewPosAndVelo, Execute),         NCSDK_IN(MC_NewPosAndVelo, NewPos),
    NCSDK_IN(MC_NewPosAndVelo, NewVelo),         NCSDK_IN(MC_NewPosAndVelo, ActivationPos),
    NCSDK_OUT(MC_NewPosAndVelo, Done),           NCSDK_OUT(MC_NewPosAndVelo, Busy),
    NCSDK_OUT(MC_NewPosAndVelo, CommandAborted), NCSDK_OUT(MC_NewPosAndVelo, Error),
    NCSDK_OUT(MC_NewPosAndVelo, ErrorID)};
constexpr auto kMoveSuperImposed = join(
    std::array<Port, 7>{
        NCSDK_IN(MC_MoveSuperImposed, Execute), NCSDK_IN(MC_MoveSuperImposed, Distance),
        NCSDK_IN(MC_MoveSuperImposed, VelocityDiff), NCSDK_IN(MC_MoveSuperImposed, Acceleration),
        NCSDK_IN(MC_MoveSuperImposed, Deceleration), NCSDK_IN(MC_MoveSuperImposed, VelocityProcess),
        NCSDK_IN(MC_MoveSuperImposed, Length)},
    motion_outputs<MC_MoveSuperImposed>(),
    std::array<Port, 5>{NCSDK_OUT(MC_MoveSuperImposed, Warning),
                        NCSDK_OUT(MC_MoveSuperImposed, WarningID),
                        NCSDK_OUT(MC_MoveSuperImposed, ActualDistance),
                        NCSDK_OUT(MC_MoveSuperImposed, ActualLength),
                        NCSDK_OUT(MC_MoveSuperImposed, ActualVelocityDiff)});
constexpr auto kAbortSuperposition =
    join(std::array<Port, 1>{NCSDK_IN(MC_AbortSuperposition, Execute)},
         status_outputs<MC_AbortSuperposition>());
constexpr auto kExtSetPointGenEnable =
    join(std::array<Port, 3>{NCSDK_IN(MC_ExtSetPointGenEnable, Execute),
                             NCSDK_IN(MC_ExtSetPointGenEnable, Position),
                             NCSDK_IN(MC_ExtSetPointGenEnable, PositionType)},
         status_outputs<MC_ExtSetPointGenEnable>(),
         std::array<Port, 1>{NCSDK_OUT(MC_ExtSetPointGenEnable, Enabled)});
constexpr auto kExtSetPointGenDisable =
    join(std::array<Port, 1>{NCSDK_IN(MC_ExtSetPointGenDisable, Execute)},
         status_outputs<MC_ExtSetPointGenDisable>(),
         std::array<Port, 1>{NCSDK_OUT(MC_ExtSetPointGenDisable, Enabled)});
constexpr auto kGearIn = std::array<Port, 13>{NCSDK_IN(MC_GearIn, Execute),
                                              NCSDK_IN(MC_GearIn, RatioNumerator),
                                              NCSDK_IN(MC_GearIn, RatioDenominator),
                                              NCSDK_IN(MC_GearIn, Acceleration),
                                              NCSDK_IN(MC_GearIn, Deceleration),
                                              NCSDK_IN(MC_GearIn, Jerk),
                                              NCSDK_IN(MC_GearIn, BufferMode),
                                              NCSDK_OUT(MC_GearIn, InGear),
                                              NCSDK_OUT(MC_GearIn, Busy),
                                              NCSDK_OUT(MC_GearIn, Active),
                                              NCSDK_OUT(MC_GearIn, CommandAborted),
                                              NCSDK_OUT(MC_GearIn, Error),
                                              NCSDK_OUT(MC_GearIn, ErrorID)};
constexpr auto kGearInDyn = std::array<Port, 12>{
    NCSDK_IN(MC_GearInDyn, Enable),       NCSDK_IN(MC_GearInDyn, GearRatio),
    NCSDK_IN(MC_GearInDyn, Acceleration), NCSDK_IN(MC_GearInDyn, Deceleration),
    NCSDK_IN(MC_GearInDyn, Jerk),         NCSDK_IN(MC_GearInDyn, BufferMode),
    NCSDK_OUT(MC_GearInDyn, InGear),      NCSDK_OUT(MC_GearInDyn, Busy),
    NCSDK_OUT(MC_GearInDyn, Active),      NCSDK_OUT(MC_GearInDyn, CommandAborted),
    NCSDK_OUT(MC_GearInDyn, Error),       NCSDK_OUT(MC_GearInDyn, ErrorID)};
constexpr auto kGearOut =
    join(std::array<Port, 1>{NCSDK_IN(MC_GearOut, Execute)}, status_outputs<MC_GearOut>());
constexpr auto kExtSetPointGenFeed = std::array<Port, 5>{
    NCSDK_IN(ExtSetPointGenFeed, Position), NCSDK_IN(ExtSetPointGenFeed, Velocity),
    NCSDK_IN(ExtSetPointGenFeed, Acceleration), NCSDK_IN(ExtSetPointGenFeed, Direction),
    NCSDK_OUT(ExtSetPointGenFeed, ErrorID)};
constexpr auto kReadStatus = join(
    std::array<Port, 1>{NCSDK_IN(MC_ReadStatus, Enable)}, read_outputs<MC_ReadStatus>(),
    std::array<Port, 12>{
        NCSDK_OUT(MC_ReadStatus, ErrorID), NCSDK_OUT(MC_ReadStatus, ErrorStop),
        NCSDK_OUT(MC_ReadStatus, Disabled), NCSDK_OUT(MC_ReadStatus, Stopping),
        NCSDK_OUT(MC_ReadStatus, StandStill), NCSDK_OUT(MC_ReadStatus, DiscreteMotion),
        NCSDK_OUT(MC_ReadStatus, ContinuousMotion), NCSDK_OUT(MC_ReadStatus, SynchronizedMotion),
        NCSDK_OUT(MC_ReadStatus, Homing), NCSDK_OUT(MC_ReadStatus, ConstantVelocity),
        NCSDK_OUT(MC_ReadStatus, Accelerating), NCSDK_OUT(MC_ReadStatus, Decelerating)});
constexpr auto kReadActualPosition =
    join(std::array<Port, 1>{NCSDK_IN(MC_ReadActualPosition, Enable)},
         read_outputs<MC_ReadActualPosition>(),
         std::array<Port, 2>{NCSDK_OUT(MC_ReadActualPosition, ErrorID),
                             NCSDK_OUT(MC_ReadActualPosition, Position)});
constexpr auto kReadAxisError =
    join(std::array<Port, 1>{NCSDK_IN(MC_ReadAxisError, Enable)}, read_outputs<MC_ReadAxisError>(),
         std::array<Port, 2>{NCSDK_OUT(MC_ReadAxisError, ErrorID),
                             NCSDK_OUT(MC_ReadAxisError, AxisErrorID)});

#undef NCSDK_IN
#undef NCSDK_OUT

template <class B>
class Holder final : public Block {
 public:
  void call(plc::AXIS_REF& first, plc::AXIS_REF& second) noexcept override {
    if constexpr (std::is_invocable_v<B&, plc::AXIS_REF&, plc::AXIS_REF&>) {
      block_(first, second);
    } else {
      (void)second;
      block_(first);
    }
  }
  void* data() noexcept override { return &block_; }
  const void* data() const noexcept override { return &block_; }

 private:
  B block_;
};

template <class B>
std::unique_ptr<Block> make() {
  return std::make_unique<Holder<B>>();
}

// The axes a block is called with: the coupling blocks with kMasterSlave (MC_GearIn,
// MC_GearInDyn) and kSlave (MC_GearOut); Holder calls a two-axis block with (master, slave).
constexpr std::string_view kOneAxis[] = {"axis"};
constexpr std::string_view kMasterSlave[] = {"master", "slave"};
constexpr std::string_view kSlave[] = {"slave"};

const BlockType kTypes[] = {
    {"MC_Power", kPower, kOneAxis, &make<MC_Power>},
    {"MC_Reset", kReset, kOneAxis, &make<MC_Reset>},
    {"MC_MoveAbsolute", kMoveAbsolute, kOneAxis, &make<MC_MoveAbsolute>},
    {"MC_MoveRelative", kMoveRelative, kOneAxis, &make<MC_MoveRelative>},
    {"MC_MoveModulo", kMoveModulo, kOneAxis, &make<MC_MoveModulo>},
    {"MC_MoveVelocity", kMoveVelocity, kOneAxis, &make<MC_MoveVelocity>},
    {"MC_Halt", kHalt, kOneAxis, &make<MC_Halt>},
    {"MC_Stop", kStop, kOneAxis, &make<MC_Stop>},
    {"MC_SetOverride", kSetOverride, kOneAxis, &make<MC_SetOverride>},
    {"MC_NewPos", kNewPos, kOneAxis, &make<MC_NewPos>},
    {"MC_NewPosAndVelo", kNewPosAndVelo, kOneAxis, &make<MC_NewPosAndVelo>},
    {"MC_MoveSuperImposed", kMoveSuperImposed, kOneAxis, &make<MC_MoveSuperImposed>},
    {"MC_AbortSuperposition", kAbortSuperposition, kOneAxis, &make<MC_AbortSuperposition>},
    {"MC_ExtSetPointGenEnable", kExtSetPointGenEnable, kOneAxis, &make<MC_ExtSetPointGenEnable>},
    {"MC_ExtSetPointGenDisable", kExtSetPointGenDisable, kOneAxis, &make<MC_ExtSetPointGenDisable>},
    {"MC_ExtSetPointGenFeed", kExtSetPointGenFeed, kOneAxis, &make<ExtSetPointGenFeed>},
    {"MC_GearIn", kGearIn, kMasterSlave, &make<MC_GearIn>},
    {"MC_GearInDyn", kGearInDyn, kMasterSlave, &make<MC_GearInDyn>},
    {"MC_GearOut", kGearOut, kSlave, &make<MC_GearOut>},
    {"MC_ReadStatus", kReadStatus, kOneAxis, &make<MC_ReadStatus>},
    {"MC_ReadActualPosition", kReadActualPosition, kOneAxis, &make<MC_ReadActualPosition>},
    {"MC_ReadAxisError", kReadAxisError, kOneAxis, &make<MC_ReadAxisError>},
};

struct EnumValue {
  ValueType type;
  int value;
  std::string_view name;
};
constexpr EnumValue kEnumValues[] = {
    {ValueType::kDirection, fb::MC_Positive_Direction, "MC_Positive_Direction"},
    {ValueType::kDirection, fb::MC_Shortest_Way, "MC_Shortest_Way"},
    {ValueType::kDirection, fb::MC_Negative_Direction, "MC_Negative_Direction"},
    {ValueType::kDirection, fb::MC_Current_Direction, "MC_Current_Direction"},
    {ValueType::kDirection, fb::MC_Undefined_Direction, "MC_Undefined_Direction"},
    {ValueType::kBufferMode, fb::MC_Aborting, "MC_Aborting"},
    {ValueType::kBufferMode, fb::MC_Buffered, "MC_Buffered"},
    {ValueType::kBufferMode, fb::MC_BlendingLow, "MC_BlendingLow"},
    {ValueType::kBufferMode, fb::MC_BlendingPrevious, "MC_BlendingPrevious"},
    {ValueType::kBufferMode, fb::MC_BlendingNext, "MC_BlendingNext"},
    {ValueType::kBufferMode, fb::MC_BlendingHigh, "MC_BlendingHigh"},
    {ValueType::kPositionType, fb::POSITIONTYPE_ABSOLUTE, "POSITIONTYPE_ABSOLUTE"},
    {ValueType::kPositionType, fb::POSITIONTYPE_RELATIVE, "POSITIONTYPE_RELATIVE"},
};

}  // namespace

const Port* BlockType::find(std::string_view port) const noexcept {
  for (const Port& p : ports) {
    if (p.name == port) return &p;
  }
  return nullptr;
}

std::span<const BlockType> block_types() {
  return kTypes;
}

const BlockType* find_block_type(std::string_view name) noexcept {
  for (const BlockType& type : kTypes) {
    if (type.name == name) return &type;
  }
  return nullptr;
}

std::string_view enum_value_name(ValueType type, int value) noexcept {
  for (const EnumValue& e : kEnumValues) {
    if (e.type == type && e.value == value) return e.name;
  }
  return {};
}

int enum_value(ValueType type, std::string_view name) noexcept {
  for (const EnumValue& e : kEnumValues) {
    if (e.type == type && e.name == name) return e.value;
  }
  return -1;
}

}  // namespace scenario
