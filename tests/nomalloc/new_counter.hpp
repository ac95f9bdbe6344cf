#pragma once
// The process-wide count of operator new calls, incremented by counting_new.hpp.
#include <atomic>

namespace adcs::test {
inline std::atomic<long> g_new_calls{0};
}  // namespace adcs::test
