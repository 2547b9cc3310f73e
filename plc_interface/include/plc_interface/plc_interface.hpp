// Umbrella header of the PLC↔NC contract: the cyclic axis interface, the command mailbox
// and the HLI axis-coupling control unit.
#pragma once

#include "plc_interface/axis_ref.hpp"
#include "plc_interface/command.hpp"
#include "plc_interface/error_code.hpp"
#include "plc_interface/hli.hpp"
