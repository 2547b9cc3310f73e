// Catch2's implementation (CATCH_CONFIG_RUNNER: everything but main), compiled once per build and
// linked into every test executable: with catch_main.cpp's main into the Catch tests, alone into a
// test that has a main of its own (tools/test_scope_page_in_chromium.cpp), which before compiled
// all of Catch again (42 s of CPU at -O3, 89 s under the sanitizers at -O1). Catch declares its
// Session only where its implementation is compiled, so a main elsewhere runs the tests through
// ncsdk_test::run_catch.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

namespace ncsdk_test {

// Catch's own default main: runs the tests the command line selects, returns the failure count.
int run_catch(int argc, char* argv[]) {
  return Catch::Session().run(argc, argv);
}

}  // namespace ncsdk_test
