#pragma once
// Replaces the global operator new/delete with malloc/free plus a counter (g_new_calls). Include in exactly one translation unit of an executable: adcs_nomalloc_tests
// and adcs-bench (its allocs_per_step counter). Needs -Wno-mismatched-new-delete: the pair is
// malloc/free on purpose.
#include <cstdlib>
#include <new>

#include "new_counter.hpp"

void* operator new(std::size_t n) {
  ++adcs::test::g_new_calls;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  ++adcs::test::g_new_calls;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
