// How a fuzz target reports a broken invariant: a message on stderr, then abort(), which
// libFuzzer (and the CTest replay) counts as a crash and keeps the input of.
#pragma once

#include <cstdio>
#include <cstdlib>

// On the harness's own checks (not the code under test): no coverage instrumentation and not
// inlined into instrumented callers, so the fuzzer neither pays for nor steers by the checker's
// comparisons, which run for every block call and every axis in every cycle (fuzz_blocks).
#if defined(__clang__)
#define FUZZ_CHECKER __attribute__((noinline, no_sanitize("coverage")))
#else
#define FUZZ_CHECKER
#endif

namespace fuzz {

[[noreturn]] inline void fail(const char* what) noexcept {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::fflush(stderr);
  std::abort();
}

}  // namespace fuzz
