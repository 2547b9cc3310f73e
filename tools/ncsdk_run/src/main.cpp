// ncsdk_run: plays a JSON timeline of PLC block calls against a JSON axis configuration (see
// cli.hpp and docs/scenarios/README.md).
#include <iostream>
#include <string>
#include <vector>

#include "ncsdk_run/cli.hpp"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  return scenario::run_command(args, std::cout, std::cerr);
}
