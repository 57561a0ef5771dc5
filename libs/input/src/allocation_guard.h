// A per-thread cap on the size of single heap allocations, active only inside
// a ScopedAllocationLimit. Used while MRPT decodes one rawlog record: a
// corrupted length field then fails with std::bad_alloc instead of reserving
// gigabytes (doc/robustness.md). Implemented by replacing the global
// operator new and interposing MRPT's aligned_malloc (allocation_guard.cpp);
// outside a scope both behave exactly like the default ones. Active in the
// sanitizer and fuzzing builds too (the sanitizers' allocators sit below).
#pragma once

#include <cstddef>

namespace pmap::input {

/// Within its scope (one thread), refuses a single allocation above
/// `max_bytes` and any allocation once `max_total_bytes` have been allocated
/// in all (a corrupted count of small objects, e.g. MRPT's particles).
/// Scopes do not nest.
class ScopedAllocationLimit {
 public:
  ScopedAllocationLimit(std::size_t max_bytes, std::size_t max_total_bytes);
  ~ScopedAllocationLimit();
  ScopedAllocationLimit(const ScopedAllocationLimit&) = delete;
  ScopedAllocationLimit& operator=(const ScopedAllocationLimit&) = delete;

  /// True if an allocation was refused in this scope.
  bool refused() const;
};

/// Throws std::bad_alloc when `size` bytes exceed the current scope's limit.
void checkAllocationLimit(std::size_t size);

}  // namespace pmap::input
