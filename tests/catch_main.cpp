// The one main of the Catch2 test executables (what CATCH_CONFIG_MAIN writes); Catch's
// implementation is catch_runner.cpp.
namespace ncsdk_test {
int run_catch(int argc, char* argv[]);  // tests/catch_runner.cpp
}

int main(int argc, char* argv[]) {
  return ncsdk_test::run_catch(argc, argv);
}
