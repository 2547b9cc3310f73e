// Umbrella header of the PLC side: the PLCopen / Tc2_MC2 motion function blocks.
//
// Each block is a class whose inputs and outputs are public members with the Tc2_MC2 names;
// calling it with its axis runs it once (a cycle function: no allocation, no exceptions).
// docs/blocks.md lists every block's inputs, outputs and errors.
#pragma once

#include "fb/hli_axis_coupling.hpp"
#include "fb/mc_abort_superposition.hpp"
#include "fb/mc_ext_set_point_gen_disable.hpp"
#include "fb/mc_ext_set_point_gen_enable.hpp"
#include "fb/mc_ext_set_point_gen_feed.hpp"
#include "fb/mc_gear_in.hpp"
#include "fb/mc_gear_in_dyn.hpp"
#include "fb/mc_gear_out.hpp"
#include "fb/mc_halt.hpp"
#include "fb/mc_home.hpp"
#include "fb/mc_move_absolute.hpp"
#include "fb/mc_move_modulo.hpp"
#include "fb/mc_move_relative.hpp"
#include "fb/mc_move_superimposed.hpp"
#include "fb/mc_move_velocity.hpp"
#include "fb/mc_new_pos.hpp"
#include "fb/mc_new_pos_and_velo.hpp"
#include "fb/mc_power.hpp"
#include "fb/mc_read_actual_position.hpp"
#include "fb/mc_read_axis_error.hpp"
#include "fb/mc_read_status.hpp"
#include "fb/mc_reset.hpp"
#include "fb/mc_set_override.hpp"
#include "fb/mc_stop.hpp"
#include "fb/types.hpp"
