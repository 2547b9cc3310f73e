// Counts heap allocations inside a region (brief: no allocation in the cycle), for the fuzz
// targets and the soak. Under AddressSanitizer (libFuzzer builds, the sanitizer test build) the
// sanitizer's allocator hook counts; otherwise the tests' counting operator new does.
//
// Only the thread that opened the region counts. The sanitizer hook sees every thread's malloc,
// and libFuzzer starts its RSS watcher thread just before it runs the first inputs: on a loaded
// machine that thread's start-up allocations (glibc, ASan) fell inside the first regions and
// looked like an allocation in the NC cycle (finding A1, docs/reliability.md).
//
// ONE-DEFINITION RULE: without a sanitizer this header includes counting_allocator.hpp, which
// defines the replacement operator new — include it from exactly one translation unit per
// executable (the target's own .cpp).
#pragma once

#include <cstddef>

#if defined(__SANITIZE_ADDRESS__)
#define NCSDK_FUZZ_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define NCSDK_FUZZ_ASAN 1
#endif
#endif

#ifdef NCSDK_FUZZ_ASAN
extern "C" int __sanitizer_install_malloc_and_free_hooks(void (*malloc_hook)(const volatile void*,
                                                                             std::size_t),
                                                         void (*free_hook)(const volatile void*));

namespace fuzz::alloc {
// A thread_local of the executable with a constant initialiser: reading it never allocates.
inline thread_local bool g_counting = false;
inline long g_allocations = 0;
inline void on_malloc(const volatile void*, std::size_t) {
  if (g_counting) ++g_allocations;
}
inline void on_free(const volatile void*) {}
// Installs the hook once per process (the first Region does it).
inline void install() {
  static const bool installed =
      (__sanitizer_install_malloc_and_free_hooks(on_malloc, on_free), true);
  (void)installed;
}
}  // namespace fuzz::alloc
#else
#include "counting_allocator.hpp"

namespace fuzz::alloc {
inline bool& g_counting = ca::g_counting;
inline long& g_allocations = ca::g_allocations;
inline void install() {}
}  // namespace fuzz::alloc
#endif

namespace fuzz {

// Allocations made between construction and allocations().
class AllocationRegion {
 public:
  AllocationRegion() noexcept {
    alloc::install();
    start_ = alloc::g_allocations;
    alloc::g_counting = true;
  }
  ~AllocationRegion() { alloc::g_counting = false; }
  AllocationRegion(const AllocationRegion&) = delete;
  AllocationRegion& operator=(const AllocationRegion&) = delete;
  long allocations() const noexcept { return alloc::g_allocations - start_; }

 private:
  long start_ = 0;
};

}  // namespace fuzz
