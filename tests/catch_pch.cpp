// The source of ncsdk_catch_pch (tests/CMakeLists.txt), the target that builds the precompiled
// catch.hpp every test executable reuses: CMake builds a precompiled header only for a target
// with a source that includes it, and catch_runner.cpp cannot (it must define CATCH_CONFIG_RUNNER
// before the header). Nothing of this object is linked.
