// The ncsdk_run command (API.md "Scenarios"):
//   ncsdk_run AXES.json TIMELINE.json --out DIR [--html]
//   ncsdk_run TIMELINE.json --out DIR [--html]      (the axes file named by the timeline's "axes")
// Plays the timeline, writes DIR/trace.csv, trace.json, summary.json, one SVG per axis (and per
// plot of the timeline), with --html DIR/scope.html, and prints the summary. Exit status 0 when
// every check passed, 1 when a check failed (each failed check is named by its JSON pointer), 2 on
// a bad input or command line (the file, the JSON pointer and the rule), with nothing written.
#pragma once

#include <iosfwd>
#include <span>
#include <string>

namespace scenario {

int run_command(std::span<const std::string> args, std::ostream& out, std::ostream& err);

}  // namespace scenario
