// Umbrella header of the NC side: kernel and cycle driver, configuration, planner, scope.
#pragma once

#include "nc_core/axis_config.hpp"
#include "nc_core/cnc_parameters.hpp"
#include "nc_core/config.hpp"
#include "nc_core/cycle_driver.hpp"
#include "nc_core/kernel.hpp"
#include "nc_core/profile.hpp"
#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"
#include "nc_core/trapezoid.hpp"
