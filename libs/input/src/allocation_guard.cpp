#include "allocation_guard.h"

#include <cstdlib>
#include <new>

namespace pmap::input {
namespace {
thread_local std::size_t t_limit = 0;  // 0 = no limit
thread_local bool t_refused = false;
}  // namespace

ScopedAllocationLimit::ScopedAllocationLimit(std::size_t max_bytes) : previous_(t_limit) {
  t_limit = max_bytes;
  t_refused = false;
}

ScopedAllocationLimit::~ScopedAllocationLimit() {
  t_limit = previous_;
}

bool ScopedAllocationLimit::refused() const {
  return t_refused;
}

}  // namespace pmap::input

#ifndef PMAP_NO_ALLOCATION_GUARD
// Replacement of the global allocation functions ([replacement.functions]).
// Sanitizer builds define PMAP_NO_ALLOCATION_GUARD and rely on the
// sanitizer's own allocator limits instead.
void* operator new(std::size_t size) {
  if (pmap::input::t_limit != 0 && size > pmap::input::t_limit) {
    pmap::input::t_refused = true;
    throw std::bad_alloc();
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) {
    return p;
  }
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  return ::operator new(size);
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
#endif
