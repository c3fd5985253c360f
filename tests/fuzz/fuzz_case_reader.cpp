// libFuzzer entry point: see fuzz_entries.hpp (case_reader).
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/fuzz_entries.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  magfem::fuzz::case_reader({reinterpret_cast<const char*>(data), size});
  return 0;
}
