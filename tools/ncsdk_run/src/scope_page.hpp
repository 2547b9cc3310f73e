// The interactive scope page (scope_page.html with the trace embedded): one self-contained HTML
// file, no network, no external script. After-run code.
#pragma once

#include <string>

#include "nc_core/scope.hpp"

namespace scenario {

// The page for the motion signals (kMotionSignals) of every axis the scope recorded.
std::string scope_page(const nc::Scope& scope, const std::string& title);

}  // namespace scenario
