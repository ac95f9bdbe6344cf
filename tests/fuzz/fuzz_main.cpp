// The libFuzzer entry point of one fuzzer: ADCS_FUZZ_HARNESS (set per executable by
// tests/fuzz/CMakeLists.txt) names the harness, one of the five compiled together in
// adcs_fuzz_harnesses (fuzz_seed00*.cpp, fuzz_components.cpp; ADCS_FUZZ_ENTRY in fuzz_common.hpp).
#include <cstddef>
#include <cstdint>

extern "C" int ADCS_FUZZ_HARNESS(const std::uint8_t* data, std::size_t size);

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ADCS_FUZZ_HARNESS(data, size);
}
