#include "allocation_guard.h"

#include <mrpt/core/aligned_allocator.h>
#include <cstdlib>

#include <new>

namespace pmap::input {
namespace {
thread_local std::size_t t_limit = 0;  // 0 = no limit
thread_local std::size_t t_total_limit = 0;
thread_local std::size_t t_total = 0;  // bytes allocated in the scope so far
thread_local bool t_refused = false;
}  // namespace

ScopedAllocationLimit::ScopedAllocationLimit(std::size_t max_bytes, std::size_t max_total_bytes) {
  t_limit = max_bytes;
  t_total_limit = max_total_bytes;
  t_total = 0;
  t_refused = false;
}

ScopedAllocationLimit::~ScopedAllocationLimit() {
  t_limit = 0;
  t_total_limit = 0;
}

bool ScopedAllocationLimit::refused() const {
  return t_refused;
}

/// Throws std::bad_alloc (and records it) when `size` is above the limits of
/// the current scope.
void checkAllocationLimit(std::size_t size) {
  if (t_limit == 0) {
    return;
  }
  t_total += size;
  if (size > t_limit || t_total > t_total_limit) {
    t_refused = true;
    throw std::bad_alloc();
  }
}

}  // namespace pmap::input

// Replacement of the global allocation functions ([replacement.functions]):
// std::vector and std::string (a string's length field, most containers).
// The whole family is replaced, all on malloc / aligned_alloc / free, so that
// every pair matches (AddressSanitizer checks new/delete against
// malloc/free: replacing only some would mix the runtime's and ours).
namespace {

void* allocate(std::size_t size) {
  pmap::input::checkAllocationLimit(size);
  if (void* p = std::malloc(size == 0 ? 1 : size)) {
    return p;
  }
  throw std::bad_alloc();
}

void* allocateAligned(std::size_t size, std::align_val_t align) {
  pmap::input::checkAllocationLimit(size);
  const auto a = static_cast<std::size_t>(align);
  const std::size_t rounded = size == 0 ? a : (size + a - 1) / a * a;
  if (void* p = std::aligned_alloc(a, rounded)) {
    return p;
  }
  throw std::bad_alloc();
}

template <class F>
void* orNull(F&& f) noexcept {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}

}  // namespace

void* operator new(std::size_t size) {
  return allocate(size);
}
void* operator new[](std::size_t size) {
  return allocate(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  return orNull([size] { return allocate(size); });
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  return orNull([size] { return allocate(size); });
}
void* operator new(std::size_t size, std::align_val_t align) {
  return allocateAligned(size, align);
}
void* operator new[](std::size_t size, std::align_val_t align) {
  return allocateAligned(size, align);
}
void* operator new(std::size_t size, std::align_val_t align, const std::nothrow_t&) noexcept {
  return orNull([size, align] { return allocateAligned(size, align); });
}
void* operator new[](std::size_t size, std::align_val_t align, const std::nothrow_t&) noexcept {
  return orNull([size, align] { return allocateAligned(size, align); });
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
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
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
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
  std::free(p);
}

// Interposes libmrpt-core's mrpt::aligned_malloc, which MRPT's
// aligned_std_vector uses (the ranges and validity flags of a 2D scan):
// without this, one corrupted scan length makes CObservation2DRangeScan
// allocate and zero up to 16 GiB. Same rounding and the same allocator as
// MRPT 2.5's own (aligned_alloc, released by mrpt::aligned_free = free),
// plus the limit. Outside a ScopedAllocationLimit it is MRPT's function.
namespace mrpt {
void* aligned_malloc(std::size_t size, std::size_t alignment) {
  pmap::input::checkAllocationLimit(size);
  if (size % alignment != 0) {
    size = (size / alignment + 1) * alignment;
  }
  return std::aligned_alloc(alignment, size);
}
}  // namespace mrpt
