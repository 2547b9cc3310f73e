// Umbrella header of the PLC↔NC contract: the cyclic axis interface and the command mailbox.
#pragma once

#include "plc_interface/axis_ref.hpp"
#include "plc_interface/command.hpp"
#include "plc_interface/error_code.hpp"
