#pragma once
// Counts heap allocations made through operator new (every C++ allocation, Eigen's included,
// since Eigen's aligned_malloc calls std::malloc — guarded separately by
// Eigen::internal::set_is_malloc_allowed). Replacing operator new is the portable way; we do
// not interpose malloc itself.
#include <Eigen/Core>
#include <cstddef>

#include "new_counter.hpp"

namespace adcs::test {

//! Counts allocations inside its scope and forbids Eigen's heap with the runtime check.
class NoAllocScope {
 public:
  NoAllocScope() : start_(g_new_calls.load()) { Eigen::internal::set_is_malloc_allowed(false); }
  ~NoAllocScope() { Eigen::internal::set_is_malloc_allowed(true); }
  long allocations() const { return g_new_calls.load() - start_; }

 private:
  long start_;
};
}  // namespace adcs::test
