// MC_AbortSuperposition (seed 000 §2.5 "Compensation stop"): posts kAbortSuperposition, is Done
// once the NC takes it — the running MC_MoveSuperImposed then ends with CommandAborted — and shows
// the NC's Error 0x4246 when no compensation runs. It never touches the basic motion.
#include <catch2/catch.hpp>

#include "fb/mc_abort_superposition.hpp"
#include "fb/mc_move_absolute.hpp"
#include "fb/mc_move_superimposed.hpp"
#include "plc_interface/axis_ref.hpp"
#include "scripted_nc.hpp"

TEST_CASE("MC_AbortSuperposition posts kAbortSuperposition and no parameters",
          "[fb][superimposed]") {
  plc::AXIS_REF axis{};
  fbtest::ScriptedNc nc(axis);
  fb::MC_AbortSuperposition abort;
  abort.Execute = true;
  abort(axis);
  REQUIRE(abort.Busy);
  nc.cycle();
  REQUIRE(nc.taken().size() == 1);
  const plc::Command c = nc.taken().front();
  REQUIRE(c.type == plc::CommandType::kAbortSuperposition);
  REQUIRE(c.position == 0.0);
  REQUIRE(c.velocity == 0.0);
}

TEST_CASE(
    "MC_AbortSuperposition is Done and the compensation shows CommandAborted; the basic move "
    "stays Active",
    "[fb][superimposed]") {
  plc::AXIS_REF axis{};
  fbtest::ScriptedNc nc(axis);
  fb::MC_MoveAbsolute move;
  fb::MC_MoveSuperImposed comp;
  fb::MC_AbortSuperposition abort;
  move.Position = 10000.0;
  move.Velocity = 2000.0;
  move.Execute = true;
  comp.Distance = 250.0;
  comp.Execute = true;
  move(axis);
  comp(axis);
  nc.cycle();
  comp(axis);
  REQUIRE(comp.Active);

  abort.Execute = true;
  abort(axis);
  REQUIRE(abort.Busy);
  REQUIRE_FALSE(abort.Done);
  nc.cycle();
  abort(axis);
  comp(axis);
  move(axis);
  REQUIRE(abort.Done);
  REQUIRE_FALSE(abort.Busy);
  REQUIRE_FALSE(abort.Error);
  REQUIRE(comp.CommandAborted);
  REQUIRE(move.Active);
  REQUIRE_FALSE(plc::test_bit(axis.NcToPlc.StateDWord, plc::kStateCompensating));

  abort.Execute = false;
  abort(axis);
  REQUIRE_FALSE(abort.Done);
}

TEST_CASE("MC_AbortSuperposition without a running compensation shows the NC's Error 0x4246",
          "[fb][superimposed]") {
  plc::AXIS_REF axis{};
  fbtest::ScriptedNc nc(axis);
  fb::MC_AbortSuperposition abort;
  abort.Execute = true;
  abort(axis);
  nc.cycle();
  abort(axis);
  REQUIRE(abort.Error);
  REQUIRE(abort.ErrorID == 0x4246);
  REQUIRE_FALSE(abort.Busy);
  REQUIRE_FALSE(abort.Done);
}
