// Umbrella header of the PLC↔NC contract: the cyclic axis interface, the command mailbox, the
// HLI axis-coupling control unit and the two-speed drive image.
#pragma once

#include "plc_interface/axis_ref.hpp"
#include "plc_interface/command.hpp"
#include "plc_interface/error_code.hpp"
#include "plc_interface/hli.hpp"
#include "plc_interface/two_speed.hpp"
