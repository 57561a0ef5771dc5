// A per-thread cap on the size of single heap allocations, active only inside
// a ScopedAllocationLimit. Used while MRPT decodes one rawlog record: a
// corrupted length field then fails with std::bad_alloc instead of reserving
// gigabytes (doc/robustness.md). Implemented by replacing the global
// operator new (allocation_guard.cpp); outside a scope it behaves exactly
// like the default one.
#pragma once

#include <cstddef>

namespace pmap::input {

class ScopedAllocationLimit {
 public:
  explicit ScopedAllocationLimit(std::size_t max_bytes);
  ~ScopedAllocationLimit();
  ScopedAllocationLimit(const ScopedAllocationLimit&) = delete;
  ScopedAllocationLimit& operator=(const ScopedAllocationLimit&) = delete;

  /// True if an allocation above the limit was refused in this scope.
  bool refused() const;

 private:
  std::size_t previous_;
};

}  // namespace pmap::input
