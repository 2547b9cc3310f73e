// A counting global operator new for the no-allocation tests (brief: no allocation in the cycle
// path): while `ca::g_counting` is set, every allocation through any form of operator new adds
// one to `ca::g_allocations`; delete frees as usual.
//
// ONE-DEFINITION RULE: this header DEFINES the replacement operator new / operator delete
// functions, non-inline as [replacement.functions] requires, so it may be included by exactly one
// translation unit per executable. Every test executable is one test file plus the shared Catch
// main object (tests/CMakeLists.txt), so include it only from the test file itself — never from
// another header. The sanitizers own the allocator, so `*no_allocation*` tests are built only
// in the plain build.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>

namespace ca {

inline bool g_counting = false;  // count only inside the region under test
inline long g_allocations = 0;

inline void* counted_alloc(std::size_t size) {
  if (g_counting) ++g_allocations;
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

inline void* counted_alloc_aligned(std::size_t size, std::align_val_t align) {
  if (g_counting) ++g_allocations;
  const auto a = static_cast<std::size_t>(align);
  void* p = std::aligned_alloc(a, ((size == 0 ? 1 : size) + a - 1) / a * a);
  if (p == nullptr) throw std::bad_alloc();
  return p;
}

}  // namespace ca

// NOLINTBEGIN(misc-definitions-in-headers): see the one-definition note above.
void* operator new(std::size_t size) {
  return ca::counted_alloc(size);
}
void* operator new[](std::size_t size) {
  return ca::counted_alloc(size);
}
void* operator new(std::size_t size, std::align_val_t a) {
  return ca::counted_alloc_aligned(size, a);
}
void* operator new[](std::size_t size, std::align_val_t a) {
  return ca::counted_alloc_aligned(size, a);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
// NOLINTEND(misc-definitions-in-headers)
