// How a fuzz target reports a broken invariant: a message on stderr, then abort(), which
// libFuzzer (and the CTest replay) counts as a crash and keeps the input of.
#pragma once

#include <cstdio>
#include <cstdlib>

namespace fuzz {

[[noreturn]] inline void fail(const char* what) noexcept {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::fflush(stderr);
  std::abort();
}

}  // namespace fuzz
